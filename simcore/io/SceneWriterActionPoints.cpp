// Writes the scene's action points (`action_points`).
#include "simcore/io/detail/YamlWriter.h"
#include "simcore/scene/Scene.h"

namespace throng::sim::detail {

void writeSceneActionPoints(YamlWriter& w, const Scene& s)
{
    if (s.actionPoints.empty())
        return;
    YAML::Emitter& o = w.out;
    const ActionPoint defaults;
    w.key("action_points");
    o << YAML::BeginSeq;
    for (const ActionPoint& p : s.actionPoints) {
        o << YAML::Flow << YAML::BeginMap;
        w.kv("name", p.name);
        w.key("position");
        w.vec2(p.position);
        w.kvf("radius", p.radiusM);
        w.kv("action", p.action);
        w.kvf("duration", p.durationS);
        if (p.faces)
            w.kvf("facing", p.facingDeg);
        if (p.chance != defaults.chance)
            w.kvf("chance", p.chance);
        if (!p.types.empty()) {
            w.key("types");
            o << YAML::Flow << YAML::BeginSeq;
            for (const std::string& t : p.types)
                o << t;
            o << YAML::EndSeq;
        }
        o << YAML::EndMap;
    }
    o << YAML::EndSeq;
}

}  // namespace throng::sim::detail
