#pragma once
// What the step's phases read of the World besides their own state: the agents' columns,
// the types, the set, the clock, the neighbour grid, the traffic and the navigation, and
// the threads to
// share the work with. A phase takes it as const and names the columns it writes in its
// own signature.

#include "simcore/base/ThreadTeam.h"
#include "simcore/world/AgentColumns.h"
#include "simcore/world/AgentTypes.h"
#include "simcore/world/NeighbourGrid.h"
#include "simcore/world/StaticSet.h"
#include "simcore/world/StepClock.h"
#include "simcore/world/TieOrder.h"
#include "simcore/world/WorldNav.h"
#include "simcore/world/WorldTraffic.h"

#include <cstdint>

namespace throng::sim {

class Formations;

struct StepView {
    const AgentColumns& agents;
    const AgentTypes& types;
    const StaticSet& set;
    const StepClock& clock;
    const NeighbourGrid& grid;  // indexes agents.pos
    const WorldTraffic& traffic;
    const WorldNav& nav;  // the navigation phase's targets for this step
    const ThreadTeam& team;
    bool hasFliers;   // the grid also sorts by height, for 3D queries
    bool allFliers;   // no obstacles, crosswalks or leaders to count for anyone
    float maxRadius;  // the largest body radius, m
    std::uint64_t seed;  // the World's: random draws are keyed by it (Rng.h)
    // The kernels' neighbour searches start from last step's k nearest (lastNearestBound,
    // Sense.h) instead of the perception radius: the same result, fewer cells (WorldOptions).
    bool warmSearch;
    const Formations& formations;  // who walks on a slot round whom (Formations.h)
    const TieOrder& ties;          // neighbours at equal distances go by id (TieOrder.h)

    const TypeParams& type(std::size_t i) const { return types.params[agents.info[i].typeIndex]; }
    const TypeCollision& collision(std::size_t i) const { return types.collision[agents.info[i].typeIndex]; }
    // Agent i's goal (it has one) is an exit walked through, not stopped at: no navigation
    // target leads there (arrival, TargetBehaviours.h; the walker kernel).
    bool walksThroughGoal(std::size_t i) const
    {
        return set.goals[std::size_t(agents.goal[i])].exit && !(nav.active && nav.hasTarget[i]);
    }
    // A traffic light's state now: 0 green, 1 yellow, 2 red.
    int lightState(std::size_t light) const;
};

}  // namespace throng::sim
