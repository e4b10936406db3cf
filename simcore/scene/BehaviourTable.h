#pragma once
// The steering behaviours an agent type can use, in one list: each enumerator with the
// behaviour's descriptor (its name in the scene file, parameters, keys and request; in the
// behaviour's own header). The order is the one prioritised allocation serves them in
// (Reynolds 1987: the most urgent first) and the order of the blend's sum. The compiler
// checks that the list pairs every enumerator once, in the enum's order, so a behaviour
// added to one and not the other does not build. Everything else (TypeSteering, steer, the
// scene reader's keys) iterates this list.

#include "simcore/steering/Containment.h"
#include "simcore/steering/FlockingBehaviours.h"
#include "simcore/steering/FlowFollowing.h"
#include "simcore/steering/LeaderFollowing.h"
#include "simcore/steering/ObstacleAvoidance.h"
#include "simcore/steering/PathFollowing.h"
#include "simcore/steering/PursuitBehaviours.h"
#include "simcore/steering/ReciprocalAvoidance.h"
#include "simcore/steering/TargetBehaviours.h"
#include "simcore/steering/UnalignedCollisionAvoidance.h"
#include "simcore/steering/WallAvoidance.h"
#include "simcore/steering/Wander.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>
#include <tuple>

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

// One row of the list: an enumerator and its behaviour's descriptor, a struct with
//   kName     the behaviour's name in the scene file (agent_types.*.behaviours, brains'
//             weight outputs);
//   Slot      a struct with one member, the behaviour's parameters under the name the
//             World's code reads (TypeSteering derives from every Slot); kParams points to it;
//   kKeys     a std::array of ParamKey (BehaviourKey.h): the parameters the scene file sets;
//   request   template <class Step, class Emit> static void request(const Step&, const Params&,
//             Emit&& emit): calls emit(force) for each force it asks for, none when what it
//             needs is missing (no leader, no goal, no wall near). Step is the step's view of
//             one agent (world/detail/BehaviourStep.h). Called only when the type runs it;
//   leadsSomewhere  optional, template <class Step> static bool leadsSomewhere(const Step&):
//             true where the behaviour moves an agent that has no goal, path or leader, which
//             would otherwise come to rest (wander, flow field following).
template <Behaviour B, class Descriptor>
struct BehaviourRow {
    static constexpr Behaviour kBehaviour = B;
    using Type = Descriptor;
};

template <class... Rows>
struct BehaviourRows {
    static constexpr std::size_t kSize = sizeof...(Rows);
};

using BehaviourList = BehaviourRows<
    BehaviourRow<Behaviour::Containment, ContainmentBehaviour>,
    BehaviourRow<Behaviour::WallFollowing, WallFollowingBehaviour>,
    BehaviourRow<Behaviour::ObstacleAvoidance, ObstacleAvoidanceBehaviour>,
    BehaviourRow<Behaviour::Separation, SeparationBehaviour>,
    BehaviourRow<Behaviour::UnalignedCollisionAvoidance, UnalignedCollisionAvoidanceBehaviour>,
    BehaviourRow<Behaviour::Evasion, EvasionBehaviour>,
    BehaviourRow<Behaviour::Flee, FleeBehaviour>,
    BehaviourRow<Behaviour::LeaderFollowing, LeaderFollowingBehaviour>,
    BehaviourRow<Behaviour::OffsetPursuit, OffsetPursuitBehaviour>,
    BehaviourRow<Behaviour::Pursuit, PursuitBehaviour>,
    BehaviourRow<Behaviour::PathFollowing, PathFollowingBehaviour>,
    BehaviourRow<Behaviour::FlowFieldFollowing, FlowFieldFollowingBehaviour>,
    BehaviourRow<Behaviour::Arrival, ArrivalBehaviour>,
    BehaviourRow<Behaviour::Seek, SeekBehaviour>,
    BehaviourRow<Behaviour::Alignment, AlignmentBehaviour>,
    BehaviourRow<Behaviour::Cohesion, CohesionBehaviour>,
    BehaviourRow<Behaviour::Wander, WanderBehaviour>,
    BehaviourRow<Behaviour::ReciprocalAvoidance, ReciprocalAvoidanceBehaviour>>;

// Every behaviour's parameters, one named member per behaviour (SeekParams seek, ...).
template <class List>
struct BehaviourParamsOf;
template <class... Rows>
struct BehaviourParamsOf<BehaviourRows<Rows...>> : Rows::Type::Slot... {};

// The row of behaviour b.
template <class List, Behaviour B>
struct BehaviourRowOf;
template <class... Rows, Behaviour B>
struct BehaviourRowOf<BehaviourRows<Rows...>, B> {
    using Type = std::tuple_element_t<std::size_t(B), std::tuple<Rows...>>;
};

struct BehaviourEntry {
    Behaviour behaviour;
    std::string_view name;  // in the scene file (agent_types.*.behaviours, brains' weight outputs)
};

template <class... Rows>
constexpr std::array<BehaviourEntry, sizeof...(Rows)> behaviourEntries(BehaviourRows<Rows...>)
{
    return {BehaviourEntry{Rows::kBehaviour, Rows::Type::kName}...};
}

inline constexpr std::array kBehaviourTable = behaviourEntries(BehaviourList{});

inline constexpr std::size_t kBehaviourCount = std::size_t(Behaviour::Count);

constexpr bool behaviourTableInEnumOrder()
{
    for (std::size_t i = 0; i < kBehaviourTable.size(); ++i)
        if (std::size_t(kBehaviourTable[i].behaviour) != i || kBehaviourTable[i].name.empty())
            return false;
    for (std::size_t i = 0; i < kBehaviourTable.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (kBehaviourTable[i].name == kBehaviourTable[j].name)
                return false;
    return true;
}
static_assert(kBehaviourTable.size() == kBehaviourCount, "BehaviourList needs a row for every Behaviour");
static_assert(behaviourTableInEnumOrder(),
              "BehaviourList lists the behaviours in the enum's order, each with a name of its own");

// The scene file's name of b (null-terminated: the descriptors' names are literals).
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
