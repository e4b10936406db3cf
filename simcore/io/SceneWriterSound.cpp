// Writes the scene's sound sources (an agent type's `emits` is written with the type).
#include "simcore/io/detail/YamlWriter.h"
#include "simcore/scene/Scene.h"

namespace throng::sim::detail {

void writeSceneSound(YamlWriter& w, const Scene& s)
{
    if (s.soundSources.empty())
        return;
    YAML::Emitter& o = w.out;
    w.key("sound_sources");
    o << YAML::BeginSeq;
    for (const SoundSource& src : s.soundSources) {
        o << YAML::Flow << YAML::BeginMap;
        w.kv("name", src.name);
        w.kv("channel", src.channel);
        w.key("position");
        w.vec2(src.position);
        w.kvf("strength", src.strength);
        w.kvf("radius", src.radiusM);
        o << YAML::EndMap;
    }
    o << YAML::EndSeq;
}

void writeEmission(YamlWriter& w, const SoundEmission& e)
{
    if (e.channel.empty())
        return;
    YAML::Emitter& o = w.out;
    w.key("emits");
    o << YAML::Flow << YAML::BeginMap;
    w.kv("channel", e.channel);
    w.kvf("strength", e.strength);
    w.kvf("radius", e.radiusM);
    o << YAML::EndMap;
}

}  // namespace throng::sim::detail
