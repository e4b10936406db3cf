// The move phase (MovePhase.h): each agent's next state from the old one, by the general
// path or a kernel. Every agent reads the previous state and writes only its own next
// state, so the result is the same for any thread count and any order of agents.
#include "simcore/world/MovePhase.h"

#include "simcore/world/BrainPhase.h"
#include "simcore/world/Constraints.h"
#include "simcore/world/Sense.h"
#include "simcore/world/Steer.h"
#include "simcore/world/WorldTraffic.h"

#include "simcore/steering/Headway.h"
#include "simcore/steering/KeepRight.h"
#include "simcore/steering/UninitialisedArray.h"
#include "simcore/world/detail/StepGeometry.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace throng::sim {

using namespace detail;

// One step's run of the phase: the step's view and what the agents' steps write, under
// the names the World gives them.
class MovePhase::Pass {
public:
    Pass(MovePhase& phase, const StepView& v, const BrainPhase& brains, WorldTraffic& traffic, AgentColumns& agents)
        : m_view(v), m_types(v.types), m_set(v.set), m_clock(v.clock), m_grid(v.grid), m_agents(agents),
          m_brains(brains), m_traffic(traffic), m_walk(phase.m_walk), m_boids(phase.m_boids),
          m_neighbourSweep(v.warmSearch)
    {
    }
    void run(bool hasStatics);

private:
    // Agent i's sense, steer, avoid, integrate and constrain. sweep: the thread's cursor
    // when agents are stepped in the grid's order, else null.
    void stepAgent(std::size_t i, bool hasStatics, NeighbourGrid::Sweep* sweep);
    // Steps agents order[begin, end) (the grid's order), boids in batches.
    void stepInGridOrder(const std::uint32_t* order, std::size_t begin, std::size_t end, bool hasStatics,
                         NeighbourGrid::Sweep& sweep);
    // Agent i's neighbours: those the brain phase gathered this step, or from the grid.
    std::size_t neighboursThisStep(std::size_t i, Neighbour* out);

    const StepView& m_view;
    const AgentTypes& m_types;
    const StaticSet& m_set;
    const StepClock& m_clock;
    const NeighbourGrid& m_grid;
    AgentColumns& m_agents;
    const BrainPhase& m_brains;
    WorldTraffic& m_traffic;
    const WalkKernel& m_walk;
    BoidKernel& m_boids;
    bool m_neighbourSweep;
};

void MovePhase::build(const AgentTypes& types, const StaticSet& set, float dt, std::size_t agents,
                      const Plain& plain, const Kernels& kernels)
{
    m_boids.build(types, dt, agents, kernels.boids, plain.boids, kernels.collideShortcut, kernels.steerEight);
    m_walk.build(types, set, dt, kernels.walkers, plain.walkers);
}

void MovePhase::run(const StepView& v, const BrainPhase& brains, WorldTraffic& traffic, AgentColumns& agents,
                    bool hasStatics)
{
    Pass(*this, v, brains, traffic, agents).run(hasStatics);
}

void MovePhase::Pass::run(bool hasStatics)
{
    const std::size_t n = m_agents.pos.size();
    // Agent by agent: the general path (stepAgent, Steer.cpp), the walker kernel
    // (WalkKernel.cpp) or the boids kernel (BoidKernel*.cpp). With fliers, agents are
    // stepped in the grid's order (by cell, then by height) when it holds them all:
    // consecutive boids then query the same columns at rising heights
    // (NeighbourGrid::forEachNearestSweep) and read neighbours that are already in cache.
    // Each agent still reads only the old state and writes only its own next state, so the
    // order changes nothing in the result. The order is cut into runs of consecutive cells,
    // and each thread takes runs as it comes free: a run is a region of space, so the
    // threads write the next state in regions of their own (in short interleaved runs both
    // threads wrote the same cache lines: 2 threads gained 2 % over 1 thread's 19 %,
    // instead of 17 %), and a flock that gathers in one part of the order, or a thread that
    // the machine holds off its core, unbalances nothing.
    const std::span<const std::uint32_t> gridOrder = m_grid.order();
    if (m_neighbourSweep && m_grid.sortedByHeight() && gridOrder.size() == n) {
        const std::uint32_t* order = gridOrder.data();
        const std::size_t run = std::max<std::size_t>(1024, n / (std::size_t(m_view.team.size()) * 16));
        m_view.team.forChunks(n, run, [&](std::size_t first, std::size_t last, int) {
            NeighbourGrid::Sweep sweep;
            stepInGridOrder(order, first, last, hasStatics, sweep);
        });
    } else {
        m_view.team.forEach(n, 256, [&](std::size_t i) { stepAgent(i, hasStatics, nullptr); });
    }
}

// Boids in batches of kBoidBatch (BoidKernel.h, BoidSense): their senses, then their steering.
void MovePhase::Pass::stepInGridOrder(const std::uint32_t* order, std::size_t begin, std::size_t end,
                                      bool hasStatics, NeighbourGrid::Sweep& sweep)
{
    constexpr std::size_t kBoidBatch = 16;  // 8 to 32 measured alike, 1 about 5 % slower
    constexpr std::size_t kSenseLanes = 4;  // boids sensed together (senseFourBoids)
    constexpr std::size_t kPrefetchAhead = 32;
    BoidPass pass(m_boids, m_view, m_agents);
    BoidPass::BoidSense sensed[kBoidBatch]{};  // zeros: the lanes past a boid's count are read (steerLanes)
    std::uint32_t boid[kBoidBatch];
    static_assert(kBoidBatch % kSenseLanes == 0);
    // boid[held - unsensed, held) await their senses, all in cell unsensedCell.
    std::size_t held = 0, unsensed = 0;
    std::uint32_t unsensedCell = 0;
    auto senseHeld = [&] {
        pass.senseFourBoids(&boid[held - unsensed], int(unsensed), sweep, &sensed[held - unsensed]);
        unsensed = 0;
    };
    for (std::size_t k = begin; k < end; ++k) {
        const std::uint32_t i = order[k];
        // The grid's order is not the index order, so the agents' own states lie scattered
        // in memory. Asked for two batches ahead, they are in cache when their turn comes
        // (32 and 64 ahead measured alike; prefetching the neighbours' states gained nothing).
        if (k + kPrefetchAhead < end) {
            const std::uint32_t a = order[k + kPrefetchAhead];
            __builtin_prefetch(&m_agents.info[a]);
            __builtin_prefetch(&m_agents.pos[a]);
            __builtin_prefetch(&m_agents.vel[a]);
            __builtin_prefetch(&m_agents.fwd[a]);
            __builtin_prefetch(&m_agents.up[a]);
            __builtin_prefetch(&m_agents.nearIndex[std::size_t(a) * kMaxNeighbours]);
            __builtin_prefetch(&m_agents.wander[a]);
            __builtin_prefetch(&m_agents.radius[a]);
            __builtin_prefetch(&m_agents.nextPos[a], 1);
            __builtin_prefetch(&m_agents.nextVel[a], 1);
            __builtin_prefetch(&m_agents.nextFwd[a], 1);
        }
        if (!m_boids.runs(m_agents.info[i].typeIndex) || m_agents.stopped[i] || m_view.formations.inFormation(i)) {
            stepAgent(i, hasStatics, &sweep);
            continue;
        }
        const std::uint32_t cell = m_grid.cellIndex(m_agents.pos[i]);
        if (unsensed > 0 && cell != unsensedCell)
            senseHeld();
        if (held == kBoidBatch) {
            pass.steerBoids(boid, sensed, held);
            held = 0;
        }
        boid[held++] = i;
        unsensedCell = cell;
        if (++unsensed == kSenseLanes || held == kBoidBatch)
            senseHeld();
    }
    if (unsensed > 0)
        senseHeld();
    pass.steerBoids(boid, sensed, held);
}

// One agent's sense, steer and integrate: its next state from the old one.
void MovePhase::Pass::stepAgent(std::size_t i, bool hasStatics, NeighbourGrid::Sweep* sweep)
{
    const TypeSteering& s = m_types.steering[m_agents.info[i].typeIndex];
    if (m_agents.stopped[i]) {
        // An agent that has arrived stays put: no dodging, no yo-yo.
        m_agents.nextPos[i] = m_agents.pos[i];
        m_agents.nextVel[i] = glm::vec3(0.0f);
        m_agents.nextFwd[i] = m_agents.fwd[i];
        m_agents.nextSide[i] = m_agents.side[i];
        m_agents.nextUp[i] = m_agents.up[i];
        m_agents.nextWander[i] = m_agents.wander[i];
        m_agents.nearCount[i] = 0;
        m_boids.collideFree()[i] = 0;  // a stopped boid's last flag no longer holds: others may come
        return;
    }
    if (m_boids.runs(m_agents.info[i].typeIndex) && !m_view.formations.inFormation(i)) {
        // boids: sense, steer and integrate in one pass (BoidKernel.h)
        BoidPass(m_boids, m_view, m_agents).stepBoid(i, sweep);
        return;
    }
    if (m_walk.runs(m_agents.info[i].typeIndex) && m_agents.path[i] < 0 && !m_view.formations.inFormation(i)) {
        m_walk.step(m_view, m_brains, m_agents, i);  // walkers in the open: the same (WalkKernel.h)
        return;
    }
    // A boid flying in formation takes this path: the collide pass must check it again.
    if (m_boids.runs(m_agents.info[i].typeIndex))
        m_boids.collideFree()[i] = 0;
    SteeringAgent self = steeringAgent(m_agents, m_types, i);
    // An anchor walks at its formation's pace (Formations.h).
    self.maxSpeed *= m_view.formations.paceOf(i);
    // Sense: nearby agents in the perception cone.
    // (Uninitialised: only the first `count` are written, and only they are read.)
    UninitialisedArray<Neighbour, kMaxNeighbours> near;
    const std::size_t count = neighboursThisStep(i, near.data());
    // Steer: the type's behaviours, combined.
    WanderState wanderNext;
    glm::vec3 force = steer(m_view, m_brains, i, self, {near.data(), count}, wanderNext) +
                      m_brains.turnForce(i, self.forward, self.velocity, self.mass);
    // A walker that only keeps its distance, with an oncoming walker in its way, steps to its
    // right (KeepRight.h), as people do: two crowds meeting head-on form lanes instead of
    // pressing face to face for good.
    if (const float keepRight = m_types.keepRight[m_agents.info[i].typeIndex]; keepRight > 0.0f)
        for (std::size_t k = 0; k < count; ++k)
            if (oncomingInTheWay(self.position, self.forward, self.radius, near[k].position, near[k].forward,
                                 near[k].velocity, near[k].radius)) {
                force += keepRightForce(self.forward, self.maxForce, keepRight);
                break;
            }
    // Headway: a walker that keeps a time gap goes no faster than lets it stop behind the
    // body in the way it wants to go (Headway.h): along its path, toward its goal's
    // waypoint, else as it moves. Seen along its heading, or the way its forces push it, a
    // walker that stood facing the one beside it, or was pushed back by the one ahead,
    // never set off.
    if (const float gapS = m_types.timeGapS[m_agents.info[i].typeIndex]; gapS > 0.0f && self.maxSpeed > 0.0f) {
        const glm::vec2 wanted = wantedHeading(m_view, i);
        if (const float len = glm::length(wanted); len > 1e-4f) {
            const float free =
                freeGapAhead(xz(self.position), self.radius, wanted / len, {near.data(), count}, self.maxSpeed * gapS);
            self.maxSpeed = headwaySpeed(free, gapS, self.maxSpeed);
        }
    }
    if (s.on(Behaviour::ReciprocalAvoidance) && !s.vehicle.flying && m_clock.decide)
        force = avoidReciprocally(m_view, i, self, force, {near.data(), count}, s);
    // Between decisions (StepRate.h) a ground agent applies the force it decided last.
    if (!s.vehicle.flying) {
        if (m_clock.decide) {
            m_agents.heldForce[i] = force;
        } else {
            force = m_agents.heldForce[i];
            wanderNext = m_agents.wander[i];
        }
    }
    if (!m_traffic.signal.empty())
        force = m_traffic.obeySignal(m_view, i, self, force);
    // Integrate: the simple vehicle model (Reynolds 1999).
    SteeringAgent next = integrateVehicle(self, force, m_clock.dt, s.vehicle);
    if (m_brains.active())
        m_brains.capToSpeed(m_view, i, self.position, next.position, next.velocity);
    m_traffic.holdAtSignal(i, next.position);
    // Constrain: no agent ends a step inside a wall or obstacle; walkers stand on the ground.
    if (!s.vehicle.flying) {
        if (hasStatics)
            constrain(m_agents, m_set, m_clock.dt, i, self.position, next.position);
        next.position.y = m_set.groundHeight(next.position.x, next.position.z);
        next.velocity = (next.position - self.position) / m_clock.dt;
        next.velocity.y = 0.0f;
    } else if (const float floor = m_set.groundHeight(next.position.x, next.position.z) + self.radius;
               next.position.y < floor) {
        // Fliers may skim the ground but never pass through it; the dive turns into
        // level flight at no less than the stall speed.
        next.position.y = floor;
        next.velocity.y = std::max(next.velocity.y, 0.0f);
        const float stall = std::min(s.vehicle.minSpeed, m_agents.maxSpeed[i]), v = glm::length(next.velocity);
        if (v < stall)
            next.velocity = v > 1e-6f ? next.velocity * (stall / v) : next.forward * stall;
    }
    m_agents.nextPos[i] = next.position;
    m_agents.nextVel[i] = next.velocity;
    m_agents.nextFwd[i] = next.forward;
    m_agents.nextSide[i] = next.side;
    m_agents.nextUp[i] = next.up;
    m_agents.nextWander[i] = wanderNext;
}

// Agent i's neighbours: those the brain phase gathered this step, or from the grid.
std::size_t MovePhase::Pass::neighboursThisStep(std::size_t i, Neighbour* out)
{
    std::uint32_t* index = &m_agents.nearIndex[i * kMaxNeighbours];
    if (!m_brains.gatheredNeighbours(i)) {
        const std::size_t count = gatherNeighbours(m_view, i, out, index);
        m_agents.nearCount[i] = std::uint8_t(count);
        return count;
    }
    const std::size_t count = m_agents.nearCount[i];
    for (std::size_t k = 0; k < count; ++k) {
        const std::uint32_t j = index[k];
        out[k] = {m_agents.pos[j], m_agents.vel[j], m_agents.fwd[j], m_agents.radius[j], m_agents.info[j].id};
    }
    return count;
}

}  // namespace throng::sim
