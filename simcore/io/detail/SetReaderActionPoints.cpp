// Action points (`action_points`): places where walkers stop, turn and play an action
// for a time (Scene.h, ActionPoint).
#include "simcore/io/detail/SetReader.h"

#include "simcore/scene/Clip.h"

namespace throng::sim::detail {

namespace {

// "wait, look_around, ..., get_up": the names an action point may play.
std::string actionNames()
{
    std::string names;
    for (int c = int(Clip::Wait); c < kClipCount; ++c)
        names += (names.empty() ? "" : ", ") + std::string(toString(Clip(c)));
    return names;
}

}  // namespace

void SetReader::readActionPoints(const YAML::Node& node, Scene& scene)
{
    if (!m_f.expectSequence(node, "action_points"))
        return;
    for (std::size_t i = 0; i < node.size(); ++i) {
        const std::string key = indexKey("action_points", i);
        const YAML::Node item = node[i];
        if (!m_f.expectMap(item, key))
            continue;
        m_f.checkKeys(item, key, {"name", "position", "radius", "action", "duration", "facing", "chance", "types"});
        ActionPoint p;
        if (m_f.readName(item, "name", key, p.name, true))
            m_names.claim(item, key, p.name, "action point");
        m_f.readVec2(item, "position", key, p.position, true);
        m_f.readFloat(item, "radius", key, p.radiusM, false, Range::Positive);
        if (m_f.readName(item, "action", key, p.action, true)) {
            const std::optional<Clip> clip = clipFromName(p.action);
            if (!clip || !isAction(*clip))
                m_f.error(item["action"].Mark(), key + ".action",
                          "'" + p.action + "' is not an action; use one of " + actionNames());
        }
        m_f.readFloat(item, "duration", key, p.durationS, false, Range::Positive);
        if (item["facing"].IsDefined() && m_f.readFloat(item, "facing", key, p.facingDeg, false))
            p.faces = true;
        m_f.readFloat(item, "chance", key, p.chance, false, Range::Unit);
        if (m_f.readStringList(item, "types", key, p.types, false))
            for (std::size_t t = 0; t < p.types.size(); ++t)
                if (!m_names.known("agent type", p.types[t]))
                    m_f.error(item["types"][t].Mark(), indexKey(key + ".types", t),
                              "no agent type named '" + p.types[t] + "'");
        scene.actionPoints.push_back(std::move(p));
    }
}

}  // namespace throng::sim::detail
