#pragma once
// Agents that keep together. A group's formation (line, column, wedge; walkers or fliers)
// holds each member on a slot in its anchor's frame: the group's leader, else the member at
// its front. A group's companions (families, friends) walk in small groups, each round one
// of them: abreast where there is room, one behind the other where a wall leaves none.
// Members steer to their slots (offset pursuit, Reynolds 1999); each anchor walks a little
// slower than its slowest member and waits while one lags. Owns who follows whom and where,
// built once per World from the scene; each step's pace comes from the previous state only.

#include "simcore/scene/Scene.h"
#include "simcore/steering/PursuitBehaviours.h"
#include "simcore/world/AgentColumns.h"
#include "simcore/world/StaticSet.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace throng::sim {

class Formations {
public:
    // The anchors and slots of the scene's groups with a formation or companions. `scene`
    // is the one the World was built from; its groups' members are the agents after its
    // placed agents, group after group.
    void build(const Scene& scene, const AgentColumns& agents, std::uint64_t seed);
    bool active() const { return !m_anchor.empty(); }

    // Member i's anchor while it holds its slot, else -1: not a member, or its anchor has
    // arrived, left or not come in (its members then walk to the goal on their own).
    std::int32_t anchorOf(std::size_t i, const AgentColumns& agents) const;
    // Member i's anchor as built, whatever the anchor is doing; -1 for non-members.
    std::int32_t anchorIndex(std::size_t i) const { return active() ? m_anchor[i] : -1; }
    // A member or an anchor: steps through the general path, not the walker kernel.
    bool inFormation(std::size_t i) const { return active() && (m_anchor[i] >= 0 || m_isAnchor[i] != 0); }
    // Where member i walks this step: its anchor and its slot in the anchor's frame (x
    // right, z forward; a companion's abreast slot falls back behind the anchor where a wall
    // takes its room). No anchor (-1) when it does not hold a slot now: not a member, its
    // anchor has arrived or left, or a wall stands between it and its slot.
    struct SlotTarget {
        std::int32_t anchor = -1;
        glm::vec3 offsetM{0.0f};
    };
    SlotTarget target(std::size_t i, const AgentColumns& agents, const StaticSet& set) const;
    // Offset pursuit of the slot (Reynolds 1999), as members steer, and its weight in the
    // blend: twice a behaviour's usual 1, so separation from the crowd around bends a
    // member's way to its slot without pulling it off (companions in a crowd of 60 walked
    // level with their anchors 87 % of the time, against 78 % at 1).
    static OffsetPursuitParams slotParams(const SlotTarget& target);
    static constexpr float kSlotWeight = 2.0f;
    // Pace: each anchor's share of its top speed this step, from how far its members are
    // from their slots (the previous state). Call before the move phase.
    void pace(const AgentColumns& agents, const StaticSet& set);
    float paceOf(std::size_t i) const { return active() && m_isAnchor[i] ? m_pace[i] : 1.0f; }

    // The slot offsets (x right, z forward) of `count` members round an anchor, front first.
    static std::vector<glm::vec2> layout(const GroupFormation& formation, std::size_t count);

private:
    void buildFormation(const SpawnGroup& group, std::int32_t anchor, std::size_t first, const AgentColumns& agents);
    void buildCompanions(const SpawnGroup& group, std::size_t groupIndex, glm::vec2 target, bool hasTarget,
                         std::size_t first, const AgentColumns& agents, std::uint64_t seed);
    void setPaceRange(std::size_t anchor, float waitFromM, float waitToM, float slowestMember,
                      const AgentColumns& agents);

    std::vector<std::int32_t> m_anchor;     // per agent: its anchor's index, -1 none (empty: no formations)
    std::vector<glm::vec2> m_slot;          // per member: (x right, z forward) in the anchor's frame
    std::vector<glm::vec2> m_behind;        // per companion: where it walks when its slot has no room
    std::vector<std::uint8_t> m_companion;  // per member: a companion (its slot may fall back)
    std::vector<std::uint8_t> m_flier;      // per member: flies (walls do not cut it off its slot)
    std::vector<std::uint8_t> m_isAnchor;
    std::vector<float> m_basePace, m_waitFromM, m_waitToM;  // per anchor
    std::vector<float> m_pace, m_lagM;                      // per anchor, this step
};

}  // namespace throng::sim
