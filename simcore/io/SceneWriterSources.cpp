// Writes the scene's sources (`sources`).
#include "simcore/io/detail/YamlWriter.h"
#include "simcore/scene/Scene.h"

namespace throng::sim::detail {

void writeSceneSources(YamlWriter& w, const Scene& s)
{
    if (s.sources.empty())
        return;
    YAML::Emitter& o = w.out;
    w.key("sources");
    o << YAML::BeginSeq;
    for (const Source& src : s.sources) {
        o << YAML::Flow << YAML::BeginMap;
        w.kv("name", src.name);
        if (src.types.size() == 1 && src.types[0].weight == 1.0f) {
            w.kv("type", src.types[0].type);
        } else {
            w.key("types");
            o << YAML::Flow << YAML::BeginMap;
            for (const SourceType& t : src.types)
                w.kvf(t.type.c_str(), t.weight);
            o << YAML::EndMap;
        }
        if (src.shape == SourceShape::Line) {
            w.key("line");
            w.polyline({src.from, src.to});
        } else {
            w.key("rect");
            o << YAML::Flow << YAML::BeginMap;
            w.key("min");
            w.vec2(src.min);
            w.key("max");
            w.vec2(src.max);
            o << YAML::EndMap;
        }
        w.kvf("rate", src.rate);
        if (src.arrivals != Arrivals::Steady)
            w.kv("arrivals", toString(src.arrivals));
        if (!src.windows.empty()) {
            w.key("windows");
            o << YAML::Flow << YAML::BeginSeq;
            for (const glm::vec2& window : src.windows)
                w.vec2(window);
            o << YAML::EndSeq;
        }
        w.kvOpt("goal", src.goal);
        w.kvOpt("path", src.path);
        if (!src.exits.empty()) {
            w.key("exits");
            o << YAML::Flow << src.exits;
        }
        if (src.cap != 0)
            o << YAML::Key << "cap" << YAML::Value << src.cap;
        if (src.headed)
            w.kvf("heading", src.headingDeg);
        o << YAML::EndMap;
    }
    o << YAML::EndSeq;
}

}  // namespace throng::sim::detail
