// Writes the scene's measurement lines and areas (`measurements`).
#include "simcore/io/detail/YamlWriter.h"
#include "simcore/scene/Scene.h"

namespace throng::sim::detail {

void writeSceneMeasurements(YamlWriter& w, const Scene& s)
{
    if (s.measurements.empty())
        return;
    YAML::Emitter& o = w.out;
    w.key("measurements");
    o << YAML::BeginSeq;
    for (const Measurement& m : s.measurements) {
        o << YAML::Flow << YAML::BeginMap;
        w.kv("name", m.name);
        w.key(toString(m.shape));
        w.polyline(m.points);
        o << YAML::EndMap;
    }
    o << YAML::EndSeq;
}

}  // namespace throng::sim::detail
