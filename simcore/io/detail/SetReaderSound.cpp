// Sound: the scene's fixed sound sources (`sound_sources`) and what an agent type emits
// (`emits`). Brains hear both through the sound_* sensors on the named channel.
#include "simcore/io/detail/SetReader.h"

namespace throng::sim::detail {

void SetReader::readSoundSources(const YAML::Node& node, Scene& scene)
{
    if (!m_f.expectSequence(node, "sound_sources"))
        return;
    for (std::size_t i = 0; i < node.size(); ++i) {
        const std::string key = indexKey("sound_sources", i);
        const YAML::Node item = node[i];
        if (!m_f.expectMap(item, key))
            continue;
        m_f.checkKeys(item, key, {"name", "channel", "position", "strength", "radius"});
        SoundSource s;
        if (m_f.readName(item, "name", key, s.name, true))
            m_names.claim(item, key, s.name, "sound source");
        m_f.readName(item, "channel", key, s.channel, true);
        m_f.readVec2(item, "position", key, s.position, true);
        m_f.readFloat(item, "strength", key, s.strength, false, Range::Positive);
        m_f.readFloat(item, "radius", key, s.radiusM, false, Range::Positive);
        scene.soundSources.push_back(std::move(s));
    }
}

void readEmission(YamlFields& f, const YAML::Node& node, const std::string& key, SoundEmission& e)
{
    if (!f.expectMap(node, key))
        return;
    f.checkKeys(node, key, {"channel", "strength", "radius"});
    f.readName(node, "channel", key, e.channel, true);
    f.readFloat(node, "strength", key, e.strength, false, Range::Positive);
    f.readFloat(node, "radius", key, e.radiusM, false, Range::Positive);
}

}  // namespace throng::sim::detail
