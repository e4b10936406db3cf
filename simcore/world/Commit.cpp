// The commit phase (Commit.h): each agent's gait advances by the distance it walked, its
// arrival and its stop are noted, and the next state becomes the state.
#include "simcore/world/Commit.h"

#include "simcore/world/Constraints.h"
#include "simcore/world/StepView.h"

#include "simcore/steering/PathFollowing.h"
#include "simcore/world/detail/StepConstants.h"
#include "simcore/world/detail/StepGeometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <utility>

namespace throng::sim {

using namespace detail;

namespace {

void commitAgent(const StepView& v, AgentColumns& agents, std::size_t i, std::uint64_t& wallCrossings)
{
    const glm::vec2 from = xz(agents.pos[i]), to = xz(agents.nextPos[i]);
    // Fliers pass over walls; only walkers and vehicles can penetrate one.
    // Vehicles and heroes go where traffic and keyframes say (a car crosses a crosswalk's kerb).
    // One walking out of a box it started in crosses that box's side on purpose; any other
    // wall it crosses on its way out counts, as the trajectories show it.
    if (!v.set.walls.segments().empty() && !v.types.steering[agents.info[i].typeIndex].vehicle.flying &&
        !v.traffic.isDriven(i))
        v.set.walls.forEachNear((from + to) * 0.5f, 0.5f * glm::length(to - from) + 0.01f, [&](std::uint32_t k) {
            const Segment& s = v.set.walls.segment(k);
            if (segmentsCross(from, to, s.a, s.b) && !(agents.escaping[i] && sideOfBoxAround(v.set, s, from)))
                ++wallCrossings;
        });
    if (agents.escaping[i] && glm::distance(to, agents.escapeTo[i]) < 1e-4f)
        agents.escaping[i] = 0;
    // Animate: the gait advances by distance over stride length, so feet don't slide.
    // (fmod's exact answer without its call: for 0 <= x < 2^31, x - trunc(x) is exact,
    // since trunc(x) <= x < 2 trunc(x) once x >= 1 (Sterbenz), and +0 for whole x, as fmod
    // gives. A fast flier covers more than a stride a step, so x >= 2 happens.)
    const float phase = agents.phase[i] + glm::length(to - from) / agents.stride[i];
    agents.phase[i] = phase >= 0.0f && phase < 1.0f            ? phase
                      : phase >= 1.0f && phase < 2.0f          ? phase - 1.0f
                      : phase >= 2.0f && phase < 2147483648.0f ? phase - float(std::int32_t(phase))
                                                               : std::fmod(phase, 1.0f);
    if (agents.stopped[i])
        return;
    // Arrived (the stats' figure) = entered the goal's area, or joined the pile of those
    // who stopped at it; counted once. Stopped = frozen for good: at the end of an open
    // path, on its own spot in the goal or held to a crawl in it, or against someone with
    // the same goal who already stopped between it and its spot, so a shared goal fills
    // like sand from the inside out and the last comers settle at the edge of the pile.
    bool stop = false;
    auto arrive = [&] {
        if (!agents.arrived[i]) {
            agents.arrived[i] = 1;
            agents.arrivalTime[i] = float(double(v.clock.step + 1) * double(v.clock.dt));
        }
    };
    if (agents.path[i] >= 0) {
        const Path& path = v.set.paths[std::size_t(agents.path[i])];
        const SteeringPath spine{v.set.pathPoints[std::size_t(agents.path[i])], path.radiusM, path.closed};
        const PathFollowParams& follow = v.types.steering[agents.info[i].typeIndex].path;
        agents.pathAlong[i] =
            advancePathProgress(spine, agents.nextPos[i], agents.pathAlong[i],
                                pathReachM(spine, follow, agents.maxSpeed[i], v.clock.dt), follow.reverse);
        const float tolerance = std::max(0.1f, 0.25f * path.radiusM);
        const float toEnd = glm::distance(to, path.points.back());
        // Or, within the path's width of its end, held there to a crawl by those round it:
        // a ring of walkers all pressing for the end point may never let one reach it.
        const bool crawling = toEnd < path.radiusM && glm::distance(to, from) < kSettleSpeedMps * v.clock.dt;
        stop = !path.closed && (toEnd < tolerance || crawling);
        // Arrived = reached the path's end within the path's own width there; the walker
        // still walks on to the end point itself before it stops, unless the end is an
        // exit: then it leaves there (stopped, never perceived again), at its pace.
        if (!path.closed && toEnd < path.radiusM) {
            arrive();
            stop = stop || path.exit;
            agents.out[i] = path.exit ? 1 : 0;
        }
        // Against the pile at the end: a stopped walker of the same path, nearer the end
        // than this one and within half a body of touching it, so a group finishing one
        // path queues up behind those already there instead of pressing on forever. (Only
        // "between this one and the end" left walkers that had slid past the end beside
        // the pile of a narrow path pressing on for good, issue 23.)
        const std::uint32_t* near = &agents.nearIndex[i * kMaxNeighbours];
        for (std::size_t k = 0; !stop && !path.closed && !path.exit && k < agents.nearCount[i]; ++k) {
            const std::uint32_t j = near[k];
            const float reach = agents.radius[i] * 1.5f + agents.radius[j] + kSettleGapM;
            const glm::vec2 q = xz(agents.nextPos[j]);
            stop = agents.stoppedBefore[j] && agents.pointAt[j] < 0 && !agents.unstarted[j] &&
                   agents.path[j] == agents.path[i] && glm::distance(to, q) < reach &&
                   glm::distance(q, path.points.back()) < toEnd;
        }
        if (stop)
            arrive();
    } else if (agents.goal[i] >= 0) {
        const Goal& g = v.set.goals[std::size_t(agents.goal[i])];
        if (glm::distance(to, g.position) < g.radiusM) {
            // Or, in the goal since an earlier step, held to a crawl by those round it: a goal
            // that several share fills up, and with bodies that no longer press through each
            // other (issue 23) each walker could be kept off its spot by another kept off
            // its own, milling there for good, and the late-comers at the edge with them.
            const bool crawling = agents.arrived[i] && glm::distance(to, from) < kSettleSpeedMps * v.clock.dt;
            arrive();
            // Through an exit: the agent leaves the simulation (stopped, never perceived again).
            stop = g.exit || glm::distance(to, agents.goalSpot[i]) < kSpotToleranceM || crawling;
            agents.out[i] = g.exit ? 1 : 0;
        }
        // Against the pile: a stopped agent with the same goal, between this one and its
        // spot. Flags as they were when this phase began, and j's next position (which a
        // stopped agent shares with its current one): nothing another thread writes in
        // this phase is read here.
        // Within touch, or within the personal space its separation keeps (which held a
        // crowd of late-comers at arm's length from the pile, walking on the spot for good).
        const TypeSteering& s = v.types.steering[agents.info[i].typeIndex];
        const float gap = std::max(kSettleGapM, s.on(Behaviour::Separation) ? s.separation.rangeM : 0.0f);
        const std::uint32_t* near = &agents.nearIndex[i * kMaxNeighbours];
        for (std::size_t k = 0; !stop && !g.exit && k < agents.nearCount[i]; ++k) {
            const std::uint32_t j = near[k];
            const float contact = agents.radius[i] + agents.radius[j] + gap;
            const glm::vec2 q = xz(agents.nextPos[j]);
            stop = agents.stoppedBefore[j] && agents.pointAt[j] < 0 && !agents.unstarted[j] &&
                   agents.goal[j] == agents.goal[i] && glm::distance(to, q) < contact &&
                   glm::dot(q - to, agents.goalSpot[i] - to) > 0.0f;
        }
        if (stop)
            arrive();
    }
    if (stop) {
        agents.stopped[i] = 1;
        agents.nextVel[i] = glm::vec3(0.0f);  // the velocity World::step swaps in
    }
}

}  // namespace

CommitCounts commit(const StepView& v, AgentColumns& agents)
{
    const std::size_t n = agents.pos.size();
    agents.stoppedBefore = agents.stopped;
    // The new state's values that are not numbers are counted here, where each agent's
    // are already in cache, not in a pass of their own (CountPhase).
    std::atomic<std::uint64_t> crossings{0}, nonFinite{0};
    v.team.forChunks(n, 256, [&](std::size_t begin, std::size_t end, int) {
        std::uint64_t crossed = 0, notNumbers = 0;
        for (std::size_t i = begin; i < end; ++i) {
            commitAgent(v, agents, i, crossed);
            notNumbers += !isFinite(agents.nextPos[i]) || !isFinite(agents.nextVel[i]);
        }
        crossings.fetch_add(crossed, std::memory_order_relaxed);
        nonFinite.fetch_add(notNumbers, std::memory_order_relaxed);
    });
    std::swap(agents.pos, agents.nextPos);
    std::swap(agents.vel, agents.nextVel);
    std::swap(agents.fwd, agents.nextFwd);
    std::swap(agents.side, agents.nextSide);
    std::swap(agents.up, agents.nextUp);
    std::swap(agents.wander, agents.nextWander);
    return {crossings.load(), nonFinite.load()};
}

}  // namespace throng::sim
