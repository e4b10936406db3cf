#pragma once
// A checkpoint of a World: everything the next steps read that the scene does not give
// (per-agent motion, arrival, navigation, signal and brain state, traffic, counters, the
// step). World::saveState fills it, World::restoreState / adoptState (WorldState.cpp)
// put it back. Plain data; never steps and never refers back to the World.
//
// The resume rule (issue 6, "editing the scene invalidates frames from the edit on"):
// frames before the edit frame stay as they were; from the edit frame on, the *edited*
// scene runs from the state at that frame. adoptState decides what of the state carries
// over into a World built from the edited scene:
//  - agents are matched by key, never by dense index (matchAgents): placed agents,
//    vehicles and heroes by id, group members by (group, member) while their group is
//    unchanged. An agent of the edited scene with no match (a crowd-brush stroke, a
//    changed group) starts from its scene state as the edited World builds it; an agent
//    with no match in the edited scene (the erase brush) is gone from the edit frame on.
//    A source's agents match by (source, arrival) while the source is unchanged; those of
//    an edited source start from their scene state (off stage until due: arrivals whose
//    time has passed come in at once, one a step where each fits);
//    A kept agent keeps its id (the key of its random draws) and, with an unchanged
//    type, its max speed, stride and waypoint radius: adding placed agents moves the ids
//    a World gives group members. The FrameCache keeps both sets (changeAgents);
//  - a traffic light's phases or timing may change: the vehicles keep their state and
//    the signal its clock (the step), with the edited timing;
//  - lanes, crosswalks, vehicles, vehicle types, where a light stands and what it
//    controls may change too (TrafficSystem::adoptFrom): the traffic system is the one
//    of the edited scene, on the old clock (the signals keep their phase), with the old
//    counters and, per stop line still there (light and lane or crosswalk), its
//    throughput. Vehicles are matched by id, like agents: an added vehicle starts from its
//    scene state (atM, speed) at the edit frame; a removed one is gone from the edit frame
//    on; a kept one on a lane of the same name keeps its motion and car-following state
//    (speed, start-up timer, stops, off-stage wait, respawns, its yellow decision while
//    that stop line stays), and its s along the lane -- exactly when the lane's centre
//    line is unchanged, else the nearest point of the edited lane to where it stood. A
//    vehicle whose lane was deleted is gone with it (the traffic system takes no vehicle
//    on a lane it does not have), and one that the edit put on another lane starts there
//    from its scene state. Walkers keep their crosswalk answer while the crosswalks stay;
//  - it refuses (returns false; the caller restarts from frame 0) when the edit changes
//    the settings (fps, duration, seed, bounds, navigation cell): the frames before would
//    be of another run, and that is the right answer for them;
//  - otherwise every kept agent keeps its motion (position, velocity, frame, wander, gait
//    phase), arrival, signal and exit state, and its brain memory when its type keeps the
//    same brain; its body and type parameters (type, radius, max speed, stride, leader,
//    navigation mode) come from the edited scene;
//  - an agent whose declared goal or path changed takes the edited one and starts that
//    leg afresh (not arrived, no plan); others keep the goal their brain may have chosen;
//  - an agent playing at an action point plays out the time it had left there while a
//    point of that name stays (with the edited point's action and facing); one whose
//    point the edit removed, or whose leg changed, goes on at once;
//  - when the navigation grid changed (walls, obstacles, a walker's radius), every A*
//    walker plans again from where it stands; walls, obstacles, lights, paths and fields
//    always come from the edited scene.
//
// saveState / restoreDynamicState copy the World's members through the lists in
// detail/WorldStateColumns.h: a new piece of state is named there once.

#include "simcore/nav/NavFollow.h"
#include "simcore/nav/PlanCache.h"
#include "simcore/scene/Scene.h"
#include "simcore/steering/Wander.h"
#include "simcore/traffic/TrafficSystem.h"
#include "simcore/world/FrameCache.h"
#include "simcore/world/NeighbourGrid.h"
#include "simcore/world/StepCounters.h"
#include "simcore/world/WorldNav.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace throng::sim {

struct WorldState {
    std::uint64_t step = 0;
    std::uint64_t seed = 0;
    std::vector<AgentInfo> agents;  // dense order: ids and type indices
    StepCounters counters;
    // The neighbour grid as the last step left it (built before that step's last moves).
    NeighbourGrid grid;
    bool gridCurrent = false;

    // Per agent, dense order (the World's arrays of the same names).
    std::vector<glm::vec3> pos, vel, fwd, side, up, nextPos, nextVel, nextFwd, nextSide, nextUp, resolvedPos;
    std::vector<WanderState> wander, nextWander;
    std::vector<float> radius, maxSpeed, phase, stride, arrivalTime;
    std::vector<std::int32_t> goal, path, leader;
    std::vector<glm::vec2> goalSpot;
    std::vector<float> pathAlong;
    std::vector<std::uint8_t> escaping;
    std::vector<glm::vec2> escapeTo;
    std::vector<std::uint8_t> arrived, stopped, stoppedBefore, onCrosswalk, nearCount, out;
    std::vector<std::uint8_t> offstage;  // a source's agent not yet let in (Sources.h)
    std::vector<std::uint8_t> unstarted;  // a walker still standing out its reaction time (StartPhase.h)
    std::vector<std::uint32_t> nearIndex;  // World::kMaxNeighbours per agent
    std::vector<glm::vec3> heldForce;
    std::vector<std::int32_t> pointAt, pointLast;
    std::vector<float> pointLeftS;

    // Traffic.
    std::optional<TrafficSystem> trafficSystem;
    std::vector<PedestrianSignal> signal;
    std::vector<PedestrianView> pedestriansBefore, pedestriansAfter;

    // Navigation.
    NavCounters navCounters;
    NavGrid navGrid;  // the plans' grid: its generation keeps them and the cache valid
    PlanCache planCache;
    std::vector<Navigation> navMode;
    std::vector<std::shared_ptr<const NavPlan>> plan;
    std::vector<std::int32_t> planGoal;
    std::vector<std::uint32_t> waypoint;
    std::vector<float> waypointRadiusM, sideStepS;
    std::vector<StallWatch> stall;
    std::vector<std::uint8_t> replan, hasTarget, waiting, waitingNext, lostSteps, noWay;
    std::vector<glm::vec2> sideDir, target;

    // Brains (empty when no type has one).
    bool hasBrains = false;
    std::vector<std::vector<std::vector<float>>> brainState; // per brain batch, per state column, per batch-local agent
    std::vector<std::int32_t> brainBatch;                     // per agent: its batch (type, or type and own brain)
    std::vector<std::int32_t> brainLocal;                     // per agent: index among its batch's agents, -1 = none
    std::vector<std::int16_t> brainAction;                    // per agent
    std::vector<std::string> tags;
    std::vector<std::vector<float>> tagValues;                // per tag, per agent
    std::vector<float> vehicleSpeed;                          // per vehicle

    // Bytes this checkpoint holds (its arrays; shared plans and the traffic system's
    // lane network counted roughly).
    std::size_t memoryBytes() const;
};

// Per agent of `after` (a World of afterScene, dense order), the index of the same agent
// in `before` (a World of beforeScene), or -1 for an agent that is new. Placed agents,
// vehicles and heroes match by id, group members by (group, member) while the group is
// unchanged; members of a group that changed never match (the group spawns again); a
// source's agents by (source, arrival) while the source is unchanged (the arrivals as
// `seed` gives them: sourceCounts), and never when it changed (its stream starts again).
std::vector<std::int32_t> matchAgents(const std::vector<AgentInfo>& before, const Scene& beforeScene,
                                      const std::vector<AgentInfo>& after, const Scene& afterScene,
                                      std::uint64_t seed);
// `old` laid out for a World whose agents come from `previous` (matchAgents): kept agents
// take their state from `old`, new ones from `fresh` (the new World as built); the global
// state (step, counters, traffic, navigation, brain memory) is old's.
WorldState remapState(const WorldState& old, const WorldState& fresh, const std::vector<std::int32_t>& previous);

// True when a World of `b` runs the same traffic system as a World of `a` (same settings,
// lanes, crosswalks, vehicles, vehicle types, and lights at the same place controlling
// the same lines; their timing may differ): adoptState then keeps the system as it was.
bool sameTrafficSet(const Scene& a, const Scene& b);

}  // namespace throng::sim
