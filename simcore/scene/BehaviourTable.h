#pragma once
// The steering behaviours an agent type can use, in one table: each enumerator with its
// name in the scene file. The order is the one prioritised allocation serves them in
// (Reynolds 1987: the most urgent first). The compiler checks that the table lists every
// enumerator once, in the enum's order, so a behaviour added to one and not the other
// does not build.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace throng::sim {

enum class Behaviour : std::uint8_t {
    Containment,
    WallFollowing,
    ObstacleAvoidance,
    Separation,
    UnalignedCollisionAvoidance,
    Evasion,
    Flee,
    LeaderFollowing,
    OffsetPursuit,
    Pursuit,
    PathFollowing,
    FlowFieldFollowing,
    Arrival,
    Seek,
    Alignment,
    Cohesion,
    Wander,
    // Not a force in the list: it replaces the velocity the others ask for by the nearest
    // one that avoids the neighbours (ORCA). Last, because it filters their result.
    ReciprocalAvoidance,
    Count  // not a behaviour: how many there are
};

struct BehaviourEntry {
    Behaviour behaviour;
    std::string_view name;  // in the scene file (agent_types.*.behaviours, brains' weight outputs)
};

inline constexpr std::array kBehaviourTable{
    BehaviourEntry{Behaviour::Containment, "containment"},
    BehaviourEntry{Behaviour::WallFollowing, "wall_following"},
    BehaviourEntry{Behaviour::ObstacleAvoidance, "obstacle_avoidance"},
    BehaviourEntry{Behaviour::Separation, "separation"},
    BehaviourEntry{Behaviour::UnalignedCollisionAvoidance, "unaligned_collision_avoidance"},
    BehaviourEntry{Behaviour::Evasion, "evasion"},
    BehaviourEntry{Behaviour::Flee, "flee"},
    BehaviourEntry{Behaviour::LeaderFollowing, "leader_following"},
    BehaviourEntry{Behaviour::OffsetPursuit, "offset_pursuit"},
    BehaviourEntry{Behaviour::Pursuit, "pursuit"},
    BehaviourEntry{Behaviour::PathFollowing, "path_following"},
    BehaviourEntry{Behaviour::FlowFieldFollowing, "flow_field_following"},
    BehaviourEntry{Behaviour::Arrival, "arrival"},
    BehaviourEntry{Behaviour::Seek, "seek"},
    BehaviourEntry{Behaviour::Alignment, "alignment"},
    BehaviourEntry{Behaviour::Cohesion, "cohesion"},
    BehaviourEntry{Behaviour::Wander, "wander"},
    BehaviourEntry{Behaviour::ReciprocalAvoidance, "reciprocal_avoidance"},
};

inline constexpr std::size_t kBehaviourCount = std::size_t(Behaviour::Count);

constexpr bool behaviourTableInEnumOrder()
{
    for (std::size_t i = 0; i < kBehaviourTable.size(); ++i)
        if (std::size_t(kBehaviourTable[i].behaviour) != i || kBehaviourTable[i].name.empty())
            return false;
    return true;
}
static_assert(kBehaviourTable.size() == kBehaviourCount, "kBehaviourTable needs a row for every Behaviour");
static_assert(behaviourTableInEnumOrder(), "kBehaviourTable lists the behaviours in the enum's order");

// The scene file's name of b (null-terminated: the table's names are literals).
constexpr const char* behaviourName(Behaviour b) { return kBehaviourTable[std::size_t(b)].name.data(); }

// The behaviour a scene file names; none for a name it does not know.
constexpr std::optional<Behaviour> behaviourFromName(std::string_view name)
{
    for (const BehaviourEntry& e : kBehaviourTable)
        if (e.name == name)
            return e.behaviour;
    return std::nullopt;
}

}  // namespace throng::sim
