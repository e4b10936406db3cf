// World::step: one fixed time step as a column of phases (DetourCrowd's dtCrowd::update
// reads the same way). Every agent reads the previous state and writes only its own next
// state (RVO2's doStep computes all new velocities before committing any), so the result
// is the same for any thread count.
#include "simcore/world/World.h"

#include "simcore/world/Collide.h"
#include "simcore/world/Constraints.h"
#include "simcore/world/Sense.h"

#include "simcore/scene/StepRate.h"

#include "simcore/steering/KeepRight.h"
#include "simcore/steering/UninitialisedArray.h"
#include "simcore/base/Rng.h"
#include "simcore/world/detail/StepGeometry.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <utility>

namespace throng::sim {

using namespace detail;

void World::step()
{
    for (int k = 0; k < m_clock.subSteps; ++k)
        stepOnce();
}

void World::stepOnce()
{
    const std::size_t n = m_agents.pos.size();
    // Anything to constrain walkers against? Not in an open field like `cross`.
    const bool hasStatics = m_set.hasStatics();

    // Grid: index agents by cell for neighbour queries (the last step's grid phase, at
    // the end of this function, left it current for these positions).
    if (!m_gridCurrent)
        m_grid.rebuild(m_agents.pos, m_hasFliers, m_agents.out, &m_team);
    m_gridCurrent = false;
    // Decide, or apply the forces decided (StepRate.h).
    m_clock.decide = decisionAt(m_clock.step, double(m_clock.dt));
    m_clock.decideDt = m_clock.decide ? float(decisionIntervalS(m_clock.step, double(m_clock.dt))) : m_clock.decideDt;
    // Navigate: plans and each walker's waypoint or flow direction (WorldNav.cpp).
    m_nav.beforeStep(view());
    // Brain: sensors from this (previous) state, then each type's program; before the
    // traffic step, which drives brain-driven vehicles by their brains' speeds.
    if (m_brains.active())
        m_brains.run(view(), m_agents, m_traffic);
    m_traffic.beforeStep(m_agents);

    // With fliers, agents are stepped in the grid's order (by cell, then by height) when it
    // holds them all: consecutive boids then query the same columns at rising heights
    // (NeighbourGrid::forEachNearestSweep) and read neighbours that are already in cache.
    // Each agent still reads only the old state and writes only its own next state, so
    // the order changes nothing in the result. The order is cut into runs of consecutive
    // cells, and each thread takes runs as it comes free: a run is a region of space, so
    // the threads write the next state in regions of their own (in short interleaved runs
    // both threads wrote the same cache lines: 2 threads gained 2 % over 1 thread's 19 %,
    // instead of 17 %), and a flock that gathers in one part of the order, or a thread
    // that the machine holds off its core, unbalances nothing.
    const std::span<const std::uint32_t> gridOrder = m_grid.order();
    if (m_neighbourSweep && m_grid.sortedByHeight() && gridOrder.size() == n) {
        const std::uint32_t* order = gridOrder.data();
        const std::size_t run = std::max<std::size_t>(1024, n / (std::size_t(m_team.size()) * 16));
        m_team.forChunks(n, run, [&](std::size_t first, std::size_t last, int) {
            NeighbourGrid::Sweep sweep;
            stepInGridOrder(order, first, last, hasStatics, sweep);
        });
    } else {
        m_team.forEach(n, 256, [&](std::size_t i) { stepAgent(i, hasStatics, nullptr); });
    }
    m_traffic.drive(m_clock, m_set, m_agents);

    // Collide: bodies still overlapping move apart, and on each decision the contact
    // rounds part those still pressed together (Collide.h).
    collide(view(), m_brains, m_agents, m_collideFree, m_boidSlackM, hasStatics);
    m_traffic.afterCollide(view(), m_agents);

    // Commit: animate and note arrivals, then swap in the new state (no copying: every path
    // of the step (stopped, boids, walkers, the general one, traffic and heroes over those)
    // writes all six next columns of every agent, so the old state left in m_next* is never
    // read before it is overwritten).
    m_agents.stoppedBefore = m_agents.stopped;
    // The new state's values that are not numbers are counted here, where each agent's
    // are already in cache, not in a pass of their own (CountPhase).
    std::atomic<std::uint64_t> crossings{0}, nonFinite{0};
    m_team.forChunks(n, 256, [&](std::size_t begin, std::size_t end, int) {
        std::uint64_t crossed = 0, notNumbers = 0;
        for (std::size_t i = begin; i < end; ++i) {
            commit(i, crossed);
            notNumbers += !isFinite(m_agents.nextPos[i]) || !isFinite(m_agents.nextVel[i]);
        }
        crossings.fetch_add(crossed, std::memory_order_relaxed);
        nonFinite.fetch_add(notNumbers, std::memory_order_relaxed);
    });
    std::swap(m_agents.pos, m_agents.nextPos);
    std::swap(m_agents.vel, m_agents.nextVel);
    std::swap(m_agents.fwd, m_agents.nextFwd);
    std::swap(m_agents.side, m_agents.nextSide);
    std::swap(m_agents.up, m_agents.nextUp);
    std::swap(m_agents.wander, m_agents.nextWander);
    m_count.addWallCrossings(crossings.load());
    ++m_clock.step;

    // Grid: index the new positions, for the count and the next step's senses.
    m_grid.rebuild(m_agents.pos, m_hasFliers, m_agents.out, &m_team);
    m_gridCurrent = true;
    // Count: the run's figures on the positions the step ended at (CountPhase.h).
    m_count.count(view(), m_agents.onCrosswalk, nonFinite.load());
    m_traffic.afterStep(m_agents);
}

// Boids in batches of kBoidBatch (World.h, BoidSense): their senses, then their steering.
void World::stepInGridOrder(const std::uint32_t* order, std::size_t begin, std::size_t end, bool hasStatics,
                            NeighbourGrid::Sweep& sweep)
{
    constexpr std::size_t kBoidBatch = 16;  // 8 to 32 measured alike, 1 about 5 % slower
    constexpr std::size_t kSenseLanes = 4;  // boids sensed together (senseFourBoids)
    constexpr std::size_t kPrefetchAhead = 32;
    BoidSense sensed[kBoidBatch]{};  // zeros: the lanes past a boid's count are read (steerLanes)
    std::uint32_t boid[kBoidBatch];
    static_assert(kBoidBatch % kSenseLanes == 0);
    // boid[held - unsensed, held) await their senses, all in cell unsensedCell.
    std::size_t held = 0, unsensed = 0;
    std::uint32_t unsensedCell = 0;
    auto senseHeld = [&] {
        senseFourBoids(&boid[held - unsensed], int(unsensed), sweep, &sensed[held - unsensed]);
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
        if (!m_boidKernel[m_agents.info[i].typeIndex] || m_agents.stopped[i]) {
            stepAgent(i, hasStatics, &sweep);
            continue;
        }
        const std::uint32_t cell = m_grid.cellIndex(m_agents.pos[i]);
        if (unsensed > 0 && cell != unsensedCell)
            senseHeld();
        if (held == kBoidBatch) {
            steerBoids(boid, sensed, held);
            held = 0;
        }
        boid[held++] = i;
        unsensedCell = cell;
        if (++unsensed == kSenseLanes || held == kBoidBatch)
            senseHeld();
    }
    if (unsensed > 0)
        senseHeld();
    steerBoids(boid, sensed, held);
}

// One agent's sense, steer and integrate: its next state from the old one.
void World::stepAgent(std::size_t i, bool hasStatics, NeighbourGrid::Sweep* sweep)
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
        m_collideFree[i] = 0;  // a stopped boid's last flag no longer holds: others may come
        return;
    }
    if (m_boidKernel[m_agents.info[i].typeIndex]) {
        stepBoid(i, sweep);  // boids: sense, steer and integrate in one pass (WorldFlock.cpp)
        return;
    }
    if (m_walkKernel[m_agents.info[i].typeIndex] && m_agents.path[i] < 0) {
        stepWalker(i);  // walkers in the open: the same (WorldWalk.cpp)
        return;
    }
    const SteeringAgent self = steeringAgent(m_agents, m_types, i);
    // Sense: nearby agents in the perception cone.
    // (Uninitialised: only the first `count` are written, and only they are read.)
    UninitialisedArray<Neighbour, kMaxNeighbours> near;
    const std::size_t count = neighboursThisStep(i, near.data());
    // Steer: the type's behaviours, combined.
    WanderState wanderNext;
    glm::vec3 force = steer(i, self, {near.data(), count}, wanderNext) + m_brains.turnForce(i, self);
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
    if (s.on(Behaviour::ReciprocalAvoidance) && !s.vehicle.flying && m_clock.decide)
        force = avoidReciprocally(i, self, force, {near.data(), count}, s);
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
        force = m_traffic.obeySignal(view(), i, self, force);
    // Integrate: the simple vehicle model (Reynolds 1999).
    SteeringAgent next = integrateVehicle(self, force, m_clock.dt, s.vehicle);
    if (m_brains.active())
        m_brains.capToSpeed(view(), i, self, next);
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

void World::commit(std::size_t i, std::uint64_t& wallCrossings)
{
    const glm::vec2 from = xz(m_agents.pos[i]), to = xz(m_agents.nextPos[i]);
    // Fliers pass over walls; only walkers and vehicles can penetrate one.
    // Vehicles and heroes go where traffic and keyframes say (a car crosses a crosswalk's kerb).
    // One walking out of a box it started in crosses that box's side on purpose; any other
    // wall it crosses on its way out counts, as the trajectories show it.
    if (!m_set.walls.segments().empty() && !m_types.steering[m_agents.info[i].typeIndex].vehicle.flying &&
        !m_traffic.isDriven(i))
        m_set.walls.forEachNear((from + to) * 0.5f, 0.5f * glm::length(to - from) + 0.01f, [&](std::uint32_t k) {
        const Segment& s = m_set.walls.segment(k);
        if (segmentsCross(from, to, s.a, s.b) && !(m_agents.escaping[i] && sideOfBoxAround(m_set, s, from)))
            ++wallCrossings;
    });
    if (m_agents.escaping[i] && glm::distance(to, m_agents.escapeTo[i]) < 1e-4f)
        m_agents.escaping[i] = 0;
    // Animate: the gait advances by distance over stride length, so feet don't slide.
    // (fmod's exact answer without its call: for 0 <= x < 2^31, x - trunc(x) is exact,
    // since trunc(x) <= x < 2 trunc(x) once x >= 1 (Sterbenz), and +0 for whole x, as fmod
    // gives. A fast flier covers more than a stride a step, so x >= 2 happens.)
    const float phase = m_agents.phase[i] + glm::length(to - from) / m_agents.stride[i];
    m_agents.phase[i] = phase >= 0.0f && phase < 1.0f            ? phase
                 : phase >= 1.0f && phase < 2.0f          ? phase - 1.0f
                 : phase >= 2.0f && phase < 2147483648.0f ? phase - float(std::int32_t(phase))
                                                          : std::fmod(phase, 1.0f);
    if (m_agents.stopped[i])
        return;
    // Arrived (the stats' figure) = entered the goal's area, or joined the pile of those
    // who stopped at it; counted once. Stopped = frozen for good: at the end of an open
    // path, on its own spot in the goal or held to a crawl in it, or against someone with
    // the same goal who already stopped between it and its spot, so a shared goal fills
    // like sand from the inside out and the last comers settle at the edge of the pile.
    bool stop = false;
    auto arrive = [&] {
        if (!m_agents.arrived[i]) {
            m_agents.arrived[i] = 1;
            m_agents.arrivalTime[i] = float(double(m_clock.step + 1) * double(m_clock.dt));
        }
    };
    if (m_agents.path[i] >= 0) {
        const Path& path = m_set.paths[std::size_t(m_agents.path[i])];
        const SteeringPath spine{m_set.pathPoints[std::size_t(m_agents.path[i])], path.radiusM, path.closed};
        const PathFollowParams& follow = m_types.steering[m_agents.info[i].typeIndex].path;
        m_agents.pathAlong[i] =
            advancePathProgress(spine, m_agents.nextPos[i], m_agents.pathAlong[i],
                                pathReachM(spine, follow, m_agents.maxSpeed[i], m_clock.dt), follow.reverse);
        const float tolerance = std::max(0.1f, 0.25f * path.radiusM);
        const float toEnd = glm::distance(to, path.points.back());
        // Or, within the path's width of its end, held there to a crawl by those round it:
        // a ring of walkers all pressing for the end point may never let one reach it.
        const bool crawling = toEnd < path.radiusM && glm::distance(to, from) < kSettleSpeedMps * m_clock.dt;
        stop = !path.closed && (toEnd < tolerance || crawling);
        // Arrived = reached the path's end within the path's own width there; the walker
        // still walks on to the end point itself before it stops.
        if (!path.closed && toEnd < path.radiusM)
            arrive();
        // Against the pile at the end: a stopped walker of the same path, nearer the end
        // than this one and within half a body of touching it, so a group finishing one
        // path queues up behind those already there instead of pressing on forever. (Only
        // "between this one and the end" left walkers that had slid past the end beside
        // the pile of a narrow path pressing on for good, issue 23.)
        const std::uint32_t* near = &m_agents.nearIndex[i * kMaxNeighbours];
        for (std::size_t k = 0; !stop && !path.closed && k < m_agents.nearCount[i]; ++k) {
            const std::uint32_t j = near[k];
            const float reach = m_agents.radius[i] * 1.5f + m_agents.radius[j] + kSettleGapM;
            const glm::vec2 q = xz(m_agents.nextPos[j]);
            stop = m_agents.stoppedBefore[j] && m_agents.path[j] == m_agents.path[i] && glm::distance(to, q) < reach &&
                   glm::distance(q, path.points.back()) < toEnd;
        }
        if (stop)
            arrive();
    } else if (m_agents.goal[i] >= 0) {
        const Goal& g = m_set.goals[std::size_t(m_agents.goal[i])];
        if (glm::distance(to, g.position) < g.radiusM) {
            // Or, in the goal since an earlier step, held to a crawl by those round it: a goal
            // that several share fills up, and with bodies that no longer press through each
            // other (issue 23) each walker could be kept off its spot by another kept off
            // its own, milling there for good, and the late-comers at the edge with them.
            const bool crawling = m_agents.arrived[i] && glm::distance(to, from) < kSettleSpeedMps * m_clock.dt;
            arrive();
            // Through an exit: the agent leaves the simulation (stopped, never perceived again).
            stop = g.exit || glm::distance(to, m_agents.goalSpot[i]) < kSpotToleranceM || crawling;
            m_agents.out[i] = g.exit ? 1 : 0;
        }
        // Against the pile: a stopped agent with the same goal, between this one and its
        // spot. Flags as they were when this phase began, and j's next position (which a
        // stopped agent shares with its current one): nothing another thread writes in
        // this phase is read here.
        // Within touch, or within the personal space its separation keeps (which held a
        // crowd of late-comers at arm's length from the pile, walking on the spot for good).
        const TypeSteering& s = m_types.steering[m_agents.info[i].typeIndex];
        const float gap = std::max(kSettleGapM, s.on(Behaviour::Separation) ? s.separation.rangeM : 0.0f);
        const std::uint32_t* near = &m_agents.nearIndex[i * kMaxNeighbours];
        for (std::size_t k = 0; !stop && !g.exit && k < m_agents.nearCount[i]; ++k) {
            const std::uint32_t j = near[k];
            const float contact = m_agents.radius[i] + m_agents.radius[j] + gap;
            const glm::vec2 q = xz(m_agents.nextPos[j]);
            stop = m_agents.stoppedBefore[j] && m_agents.goal[j] == m_agents.goal[i] &&
                   glm::distance(to, q) < contact && glm::dot(q - to, m_agents.goalSpot[i] - to) > 0.0f;
        }
        if (stop)
            arrive();
    }
    if (stop) {
        m_agents.stopped[i] = 1;
        m_agents.nextVel[i] = glm::vec3(0.0f);  // the velocity World::step swaps in
    }
}

// Agent i's neighbours: those the brain phase gathered this step, or from the grid.
std::size_t World::neighboursThisStep(std::size_t i, Neighbour* out)
{
    std::uint32_t* index = &m_agents.nearIndex[i * kMaxNeighbours];
    if (!m_brains.gatheredNeighbours(i)) {
        const std::size_t count = gatherNeighbours(view(), i, out, index);
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
