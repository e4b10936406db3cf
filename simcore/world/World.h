#pragma once
// The runtime of a scene: one array per agent attribute, advanced by fixed steps.
// Reads only the previous state within a step, so results do not depend on the thread
// count. Never reads a clock, never allocates inside step(), never draws.

#include "simcore/base/SegmentGrid.h"
#include "simcore/base/ThreadTeam.h"
#include "simcore/scene/Scene.h"
#include "simcore/steering/Steering.h"
#include "simcore/world/AgentColumns.h"
#include "simcore/world/AgentTypes.h"
#include "simcore/world/BrainPhase.h"
#include "simcore/world/Collide.h"
#include "simcore/world/CountPhase.h"
#include "simcore/world/FrameCache.h"
#include "simcore/world/MovePhase.h"
#include "simcore/world/NearestList.h"
#include "simcore/world/NeighbourGrid.h"
#include "simcore/world/PhaseTimes.h"
#include "simcore/world/ExitChoice.h"
#include "simcore/world/Formations.h"
#include "simcore/world/Sources.h"
#include "simcore/world/StartPhase.h"
#include "simcore/world/StaticSet.h"
#include "simcore/world/StepClock.h"
#include "simcore/world/TieOrder.h"
#include "simcore/world/StepCounters.h"
#include "simcore/world/TypeSteering.h"
#include "simcore/world/WorldNav.h"
#include "simcore/world/WorldPriority.h"
#include "simcore/world/WorldTraffic.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace throng::sim {

class BrainEvaluator;
class DebugSink;
struct WorldState;

struct WorldOptions {
    std::uint64_t seed = 0;     // used when overrideSeed; else the scene's seed
    bool overrideSeed = false;
    int threads = 0;            // 0 = one per core this process may run on
    bool boidKernel = true;     // false: boids take the general steering path too (tests compare the two)
    // false: the collide pass searches every boid's neighbours for overlaps, instead of
    // trusting what the boids kernel found (tests compare)
    bool collideShortcut = true;
    // false: the contact rounds work out every agent in every round, instead of passing by
    // those they would leave where they are (Collide.h; the result is the same; tests compare)
    bool contactShortcut = true;
    bool walkKernel = true;     // false: walkers take the general steering path too (tests compare the two)
    // false: agents step in index order and the kernels' neighbour searches start from the
    // perception radius, instead of in the grid's order (fliers) from last step's
    // neighbours (the result is the same; tests compare)
    bool neighbourSweep = true;
    // false: the boids kernel steers four boids at a time even where the CPU has AVX2,
    // instead of eight (the result is the same; tests compare)
    bool steerEight = true;
    // The neighbour grid's cells on the ground: by how spread out the crowd is, or always
    // the fine or the coarse ones (the result is the same; tests compare, benches time)
    GridCells gridCells = GridCells::ByCrowd;
};

class World {
public:
    // Most neighbours one agent perceives (AgentColumns.h).
    static constexpr std::size_t kMaxNeighbours = sim::kMaxNeighbours;

    // Builds the runtime from a validated scene: placed agents, spawned groups (seeded),
    // goals, paths and leaders resolved to indices, walls and obstacles into grids.
    World(const Scene& scene, const WorldOptions& options = {});

    // Advances exactly one frame of 1 / fps seconds: one step, or below 24 fps several
    // equal sub-steps (StepRate.h).
    void step();

    std::size_t agentCount() const { return m_agents.pos.size(); }
    // Frames stepped so far.
    std::uint64_t stepIndex() const { return m_clock.frame(); }
    // A frame's length, s (1 / fps).
    float dt() const { return m_clock.frameDt; }
    // Steps per frame (1 from 24 fps up).
    int subSteps() const { return m_clock.subSteps; }
    double timeS() const { return m_clock.timeS(); }
    std::uint64_t seed() const { return m_seed; }
    int threads() const { return m_team.size(); }
    // The threads that step this World (tests ask it which threads did work).
    const ThreadTeam& team() const { return m_team; }
    // The wall-clock time the steps so far spent in each phase (PhaseTimes.h).
    const PhaseTimes& phaseTimes() const { return m_phaseTimes; }
    // The contact rounds' work so far: the agents they went through, and those passed by.
    const ContactRounds& contactRounds() const { return m_contactRounds; }

    // How many neighbours each agent listed in its last step (at most kMaxNeighbours; 0 for
    // one that had stopped): what its steering and avoidance, and the collide phase, went
    // through.
    std::span<const std::uint8_t> neighbourCounts() const { return m_agents.nearCount; }
    // Positions are relative to origin(): add it (in double) for the scene's coordinates.
    std::span<const glm::vec3> positions() const { return m_agents.pos; }
    // Where this World's coordinates start in the scene's: (0, 0, 0) unless the scene lies
    // far from it (simulationOrigin, SceneOrigin.h); goals(), navigation() and the frames
    // of snapshot() are relative to it too.
    glm::dvec3 origin() const { return {m_origin.x, 0.0, m_origin.y}; }
    std::span<const glm::vec3> velocities() const { return m_agents.vel; }
    std::span<const glm::vec3> forwards() const { return m_agents.fwd; }
    std::span<const glm::vec3> ups() const { return m_agents.up; }
    std::span<const float> radii() const { return m_agents.radius; }
    AgentId id(std::size_t i) const { return m_agents.info[i].id; }
    const std::vector<AgentInfo>& agentInfo() const { return m_agents.info; }
    bool hasArrived(std::size_t i) const { return m_agents.arrived[i] != 0; }
    // Seconds from the start until agent i arrived; negative while it has not.
    float arrivalTimeS(std::size_t i) const { return m_agents.arrivalTime[i]; }
    // Agents in the scene or gone from it with a goal or an open path to finish (not those
    // still off stage).
    std::size_t agentsWithGoal() const;
    // The dense index of the agent that agent i pursues, evades or follows; -1 for none.
    std::int32_t leaderOf(std::size_t i) const { return m_agents.leader[i]; }
    AgentKind agentKind(std::size_t i) const { return m_types.params[m_agents.info[i].typeIndex].kind; }
    // Agents of this type step through the fused boids kernel (BoidKernel.h).
    bool usesBoidKernel(std::size_t typeIndex) const { return m_move.boids().runs(typeIndex); }
    // How many boids the kernel steers at once: 8 where the CPU has AVX2 (canSteerEight)
    // and WorldOptions::steerEight asks for it, else 4.
    int boidLanes() const { return m_move.boids().lanes(); }
    static bool canSteerEight() { return BoidKernel::canSteerEight(); }
    // Agents of this type without a path step through the fused walker kernel (WalkKernel.h).
    bool usesWalkKernel(std::size_t typeIndex) const { return m_move.walk().runs(typeIndex); }
    // Navigation (WorldNav.cpp): agent i left through an exit goal; it is no longer
    // simulated or perceived and stays where it left (arrivalTimeS says when).
    bool isOut(std::size_t i) const { return m_agents.out[i] != 0 && m_agents.offstage[i] == 0; }
    // Sources (Sources.h): agent i is a source's, not yet let in (not in the scene).
    bool isOffstage(std::size_t i) const { return m_agents.offstage[i] != 0; }
    // Agents the scene's sources let in over the run, and how many of them are still off stage.
    std::size_t sourceAgents() const { return m_sources.scheduled(); }
    std::size_t offstageAgents() const { return m_sources.offstage(m_agents); }
    // Reaction times (StartPhase.h): when walker i sets off, s from the start (0: at once;
    // looked up in the schedule, not a column), and whether it still stands waiting.
    double startTimeS(std::size_t i) const { return m_starts.startS(i); }
    bool isUnstarted(std::size_t i) const { return m_agents.unstarted[i] != 0; }
    // The agent walker i keeps its slot round (a formation's or its companions' anchor,
    // Formations.h) as built from the scene; -1 for walkers that keep to nobody.
    std::int32_t formationAnchor(std::size_t i) const { return m_formations.anchorIndex(i); }
    // Agent i's age, years, when its type sets an age range (WalkingAge.h); else 0.
    float ageYears(std::size_t i) const;
    // Agents in the scene now: neither off stage nor gone through an exit.
    std::size_t agentsInScene() const;
    // Agent i started inside a wall or obstacle and is still walking out of it (its way
    // out: escapeTarget in Constraints.h, in this World's coordinates).
    bool isEscaping(std::size_t i) const { return m_agents.escaping[i] != 0; }
    glm::vec2 escapeTo(std::size_t i) const { return m_agents.escapeTo[i]; }
    // Agent i's goal as an index into goals(), or -1.
    std::int32_t goalIndex(std::size_t i) const { return m_agents.goal[i]; }
    const std::vector<Goal>& goals() const { return m_set.goals; }
    // Agent i's path as an index into paths(), or -1; the paths as the World follows them.
    std::int32_t pathIndex(std::size_t i) const { return m_agents.path[i]; }
    const std::vector<Path>& paths() const { return m_set.paths; }
    const WorldNav& navigation() const { return m_nav; }

    // The current state as one frame for the cache.
    void snapshot(std::vector<AgentFrame>& out) const;
    // Starts `cache` for this world's agents and records the current state as frame 0.
    void startRecording(FrameCache& cache) const;
    // Running totals of the quality figures since construction.
    const StepCounters& counters() const { return m_count.counters(); }
    // Bytes held by the per-agent arrays and the neighbour grid.
    std::size_t memoryBytes() const;
    // The neighbour grid's cell edge now, m: on the ground it follows how spread out the
    // crowd is (WorldOptions::gridCells, NeighbourGrid.h).
    float neighbourCellM() const { return m_grid.cellM(); }

    // Light state of a traffic light at the current time: 0 green, 1 yellow, 2 red.
    int lightState(std::size_t light) const;

    // Vehicles and heroes are agents too (after every walker and flier, in the scene's
    // order): driven by traffic or keyframes, never steered or pushed. See WorldTraffic.cpp.
    const TrafficSystem* trafficSystem() const { return m_traffic.system ? &*m_traffic.system : nullptr; }
    const std::vector<HeroTrack>& heroTracks() const { return m_traffic.heroes; }
    const WorldTraffic& traffic() const { return m_traffic; }
    bool isDriven(std::size_t i) const { return m_traffic.isDriven(i); }
    // Brains (WorldBrain.cpp). The action agent i's brain chose at the last step, as an
    // index into its program's action names, or -1 (no brain, or no action output).
    int brainAction(std::size_t i) const;
    std::string brainActionName(std::size_t i) const;
    // Why a type's brain does not run (compile errors, sensors the World cannot fill);
    // such a type steers without its brain. Empty when every brain runs.
    const std::vector<std::string>& brainErrors() const;
    // The evaluator of a type's brain (for the live view), null when the type has none.
    const BrainEvaluator* brainEvaluator(std::size_t typeIndex) const;
    // The evaluator agent i runs in: its type's, or that of the (type, brain) batch of a
    // placed agent with a brain of its own; null when it runs no brain.
    const BrainEvaluator* agentBrainEvaluator(std::size_t i) const;
    // Keeps agent i's node values (its type's evaluator's pickedValues) after each step;
    // -1 picks nobody. Agent i's index among its batch's agents is what the evaluator sees.
    void pickBrainAgent(std::ptrdiff_t i);

    // Publishes to `sink` what agent i senses and decides in the current state: its view
    // cone, the neighbours it sensed at the last step, each behaviour's force and their
    // blend as the general steering path computes them, its feelers, its planned way, the
    // field it follows and where it steers (WorldDebug.cpp). For the few agents a user watches; never changes
    // the World and never runs inside step().
    void describeAgent(std::size_t i, DebugSink& sink) const;

    // Checkpoints (WorldState.cpp). saveState: everything the next steps read. restoreState:
    // puts a checkpoint of a World of the same scene back (throws std::invalid_argument
    // when its agents differ); the steps from there are bit-identical. adoptState: this
    // World, built from `thisScene`, an edit of `stateScene`, continues from a checkpoint of
    // a World of `stateScene` by the rule in WorldState.h; false (nothing changed) when it
    // cannot, and the caller runs the edited scene from its start instead. `previous`, when
    // given, receives per agent of this World its index in the checkpoint (-1 = new).
    WorldState saveState() const;
    void restoreState(const WorldState& state);
    bool adoptState(const WorldState& state, const Scene& stateScene, const Scene& thisScene,
                    std::vector<std::int32_t>* previous = nullptr);

private:
    // One step of m_clock.dt: the phases World::step runs once a frame, or per sub-step.
    void stepOnce();
    // adoptState once the checkpoint is in this World's order; previous(i) as above.
    bool adoptMatched(const WorldState& state, const Scene& stateScene, const Scene& thisScene,
                      const std::function<std::int32_t(std::size_t)>& previous);
    // adoptMatched's heroes: a new one, or one with new keyframes, to where its track puts it now.
    void placeEditedHeroes(const Scene& stateScene, const Scene& thisScene,
                           const std::function<std::int32_t(std::size_t)>& previous);
    // keepBrain: per agent, 0 = its brain memory starts afresh (empty: all keep theirs).
    void restoreDynamicState(const WorldState& state, const std::vector<std::uint8_t>& keepBrain);

    void build(const Scene& scene, const WorldOptions& options);  // the constructor, in this World's coordinates
    void buildStatics(const Scene& scene);
    void buildAgents(const Scene& scene);
    void spawnGroup(const Scene& scene, const SpawnGroup& group, std::size_t groupIndex, std::uint16_t type,
                    int goal, int path, AgentId& nextId);
    void spreadMembers(const SpawnGroup& group, std::uint16_t type, std::size_t groupIndex,
                       std::vector<glm::vec2>& places, const std::vector<std::uint8_t>& clearOfStatics) const;
    void addAgent(const Scene& scene, AgentId id, std::uint16_t type, glm::vec3 pos, float headingRad, int goal,
                  int path, AgentId leader);
    // Every source's arrivals as off-stage agents after the groups' (Sources.h); a source's
    // exits (ExitChoice.h) become a set its agents choose from.
    void addSourceAgents(const Scene& scene, AgentId& nextId, std::vector<std::int32_t>& choosesFrom,
                         std::vector<std::vector<std::int32_t>>& exitSets);
    // The walkers whose type sets a reaction time, and when each sets off (StartPhase.h);
    // `hold` stands them where they are, as at the start (not the driven agents or those
    // off stage). Drawn by id, so adoptState schedules again once kept agents have theirs.
    void scheduleReactions(const Scene& scene, bool hold);
    // Sends each walker of `choices` to its exit, aiming at its own spot there (ExitChoice.h).
    void takeExits(const std::vector<ExitChoice::Switch>& choices);

    // Agents inside a wall or obstacle at the start: where each walks out to (Constraints.h).
    void findEscapes();
    // What the phases read of this World besides their own state (StepView.h).
    StepView view() const
    {
        return {m_agents, m_types,  m_set,       m_clock,      m_grid,      m_traffic,
                m_nav,    m_team,   m_hasFliers, m_allFliers, m_maxRadius, m_seed, m_neighbourSweep,
                m_formations, m_ties};
    }
    const TypeCollision& collision(std::size_t i) const { return m_types.collision[m_agents.info[i].typeIndex]; }

    // The traffic's vehicles and heroes as agents, after the scene's own (World.cpp); the
    // traffic phase itself is m_traffic (WorldTraffic.h).
    void addTrafficAgents(const Scene& scene);

    AgentTypes m_types;  // per type: body, steering, collision layers
    MovePhase m_move;  // steer, avoid, integrate, constrain; owns the kernels (MovePhase.h)

    StaticSet m_set;  // walls, obstacles, goals, paths, lights, crosswalks, flow, terrain, bounds

    AgentColumns m_agents;  // the agents' state, a column per attribute

    NeighbourGrid m_grid;
    TieOrder m_ties;  // the order of neighbours at equal distances: by id (TieOrder.h)
    bool m_gridCurrent = false;  // the grid indexes the current positions
    bool m_hasFliers = false;    // then the grid also sorts by height for 3D queries
    bool m_allFliers = true;     // no obstacles or crosswalks to count for anyone
    bool m_neighbourSweep = true;  // WorldOptions::neighbourSweep
    float m_maxRadius = 0.0f;    // the largest body radius, m
    CountPhase m_count;  // the run's figures (StepCounters.h)
    std::uint64_t m_seed = 1;
    StepClock m_clock;
    PhaseTimes m_phaseTimes;  // wall-clock time per phase of the steps so far
    ContactRounds m_contactRounds;  // the contact rounds' shortcut, and its work so far (Collide.h)
    ThreadTeam m_team;
    WorldTraffic m_traffic;
    WorldNav m_nav;
    glm::dvec2 m_origin{0.0};         // the scene's (x, z) of this World's (0, 0)
    BrainPhase m_brains;
    SourcePhase m_sources;
    StartPhase m_starts;  // walkers standing out their reaction times
    ExitChoice m_exits;   // walkers choosing among exits
    Formations m_formations;  // walkers keeping together: formations and companions
};

}  // namespace throng::sim
