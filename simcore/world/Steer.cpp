// The steer phase (Steer.h): what an agent's type's behaviours ask of it, from what it
// senses (Sense.h). Reads only the previous state.
#include "simcore/world/Steer.h"

#include "simcore/world/BrainPhase.h"
#include "simcore/world/StepView.h"
#include "simcore/world/WorldPriority.h"

#include "simcore/base/Rng.h"
#include "simcore/steering/UninitialisedArray.h"
#include "simcore/world/DebugSink.h"
#include "simcore/world/Sense.h"
#include "simcore/world/detail/StepGeometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace throng::sim {

namespace {

// Adds behaviour b's force, weighted by its type and the agent's brain, to the requests
// when the type runs it, and tells the sink (describeAgent) what it asked for. The force
// is only computed for a behaviour that runs.
template <class Force>
void requestBehaviour(const TypeSteering& s, Behaviour b, float brainWeight, Force&& force,
                      SteeringRequestList& requests, DebugSink* sink)
{
    if (!s.on(b))
        return;
    const glm::vec3 f = force();
    const float weight = s.w(b) * brainWeight;
    requests.add(f, weight);
    if (sink)
        sink->force(b, f, weight);
}

}  // namespace

using namespace detail;

namespace {

// Head-on to a wall, a walker sliding along it faster than this keeps its way.
constexpr float kSlideOnMps = 0.1f;

// Wall following (Reynolds 1999): an agent whose way leads into a nearby wall travels
// along it toward the end nearer its way, instead of pressing against its face (the
// local minimum a goal straight behind a wall makes). Zero when no wall is in the way.
glm::vec3 slideAlongWall(const SteeringAgent& self, std::span<const WallSegment> walls, glm::vec3 target,
                         const WallAvoidanceParams& params)
{
    const glm::vec2 p(self.position.x, self.position.z);
    glm::vec2 way(target.x - p.x, target.z - p.y);
    if (glm::dot(way, way) < 1e-8f)
        way = glm::vec2(self.forward.x, self.forward.z);
    if (glm::dot(way, way) < 1e-8f)
        return glm::vec3(0.0f);
    way = glm::normalize(way);
    const float reach = self.radius + params.standoffM + 0.5f;
    float nearest = reach;
    glm::vec2 tangent(0.0f);
    for (const WallSegment& w : walls) {
        const glm::vec2 a(w.a.x, w.a.z), b(w.b.x, w.b.z);
        const glm::vec2 c = closestOnSegment(p, a, b);
        const float d = glm::distance(p, c);
        const glm::vec2 along = b - a;
        if (d >= nearest || glm::dot(along, along) < 1e-8f || d < 1e-6f)
            continue;
        // Only a wall that the way actually runs into (a ray from the body's centre
        // widened by its radius) counts; door jambs beside the way do not.
        const glm::vec2 sideways(-way.y, way.x);
        bool blocked = false;
        for (float offset : {-self.radius, 0.0f, self.radius})
            blocked = blocked || segmentsCross(p + sideways * offset, p + sideways * offset + way * reach, a, b);
        if (!blocked)
            continue;
        glm::vec2 t = glm::normalize(along);
        float side = glm::dot(way, t);
        if (std::fabs(side) < 0.2f) {
            // Nearly head-on: keep on the way it already slides, so a walker near the middle
            // of a face does not turn back each time the nearer end changes; from a stand,
            // go round the nearer end.
            const float sliding = glm::dot(glm::vec2(self.velocity.x, self.velocity.z), t);
            if (std::fabs(sliding) > kSlideOnMps)
                side = sliding;
            else
                side = glm::distance(c, a) < glm::distance(c, b) ? -1.0f : 1.0f;
        }
        tangent = side < 0.0f ? -t : t;
        nearest = d;
    }
    return glm::vec3(tangent.x, 0.0f, tangent.y) * self.maxForce;
}


}  // namespace

// Wall following and obstacle avoidance's requests, in steer's order (after containment):
// shared by steer (Steer.h) and the walker kernel (WalkKernel.cpp), so the two add the same
// forces with the same weights. Nothing when the world has no walls or obstacles.
void steerAroundStatics(const StepView& v, const BrainPhase& brains, std::size_t i, const SteeringAgent& self,
                        glm::vec3 goal, SteeringRequestList& requests, DebugSink* sink)
{
    const TypeSteering& s = v.types.steering[v.agents.info[i].typeIndex];
    using B = Behaviour;
    auto request = [&](B b, auto&& force) {
        requestBehaviour(s, b, brains.weight(i, b), force, requests, sink);
    };
    const glm::vec3 p = self.position;
    if (s.on(B::WallFollowing) && !v.set.walls.segments().empty()) {
        std::array<WallSegment, kMaxNearWalls> walls;
        std::size_t n = 0;
        const float reach = s.walls.feelerMinM + s.walls.feelerLookaheadS * self.speed() + s.walls.standoffM +
                            self.radius;
        v.set.walls.forEachNear(xz(p), reach, [&](std::uint32_t k) {
            if (n < walls.size()) {
                const Segment& seg = v.set.walls.segment(k);
                walls[n++] = {glm::vec3(seg.a.x, 0.0f, seg.a.y), glm::vec3(seg.b.x, 0.0f, seg.b.y)};
            }
        });
        if (n > 0) {
            request(B::WallFollowing, [&] { return avoidWalls(self, {walls.data(), n}, s.walls, &goal); });
            request(B::WallFollowing, [&] { return slideAlongWall(self, {walls.data(), n}, goal, s.walls); });
        }
    }
    if (s.on(B::ObstacleAvoidance) && (!v.set.circles.empty() || !v.set.boxes.empty())) {
        std::array<CircleObstacle, kMaxNearObstacles> circles;
        std::array<BoxObstacle, kMaxNearObstacles> boxes;
        std::size_t nc = 0, nb = 0;
        const float reach = s.obstacles.minLengthM + s.obstacles.lookaheadS * self.speed() + self.radius +
                            s.obstacles.marginM;
        v.set.obstacleGrid.forEachNear(xz(p), reach, [&](std::uint32_t k) {
            if (k < v.set.circles.size()) {
                if (nc < circles.size())
                    circles[nc++] = v.set.circles[k];
            } else if (nb < boxes.size()) {
                boxes[nb++] = v.set.boxes[k - v.set.circles.size()];
            }
        });
        request(B::ObstacleAvoidance,
                [&] { return avoidObstacles(self, {circles.data(), nc}, {boxes.data(), nb}, goal, s.obstacles); });
    }
}

// Steer: every behaviour the type runs, in priority order, combined by blending or by
// prioritised allocation. Pure in the previous state; the new wander state goes out.
glm::vec3 steer(const StepView& v, const BrainPhase& brains, std::size_t i, const SteeringAgent& self,
                std::span<const Neighbour> near, WanderState& wanderOut, DebugSink* sink)
{
    const TypeSteering& s = v.types.steering[v.agents.info[i].typeIndex];
    using B = Behaviour;
    SteeringRequestList requests;
    auto request = [&](B b, auto&& force) {
        requestBehaviour(s, b, brains.weight(i, b), force, requests, sink);
    };
    const glm::vec3 p = self.position;
    const bool hasGoal = v.agents.goal[i] >= 0;
    const glm::vec3 goal =
        hasGoal ? v.nav.goal(i, glm::vec3(v.agents.goalSpot[i].x, p.y, v.agents.goalSpot[i].y)) : p + self.forward;
    const std::int32_t leaderIndex = v.agents.leader[i];
    Neighbour leader;
    if (leaderIndex >= 0) {
        const auto j = std::size_t(leaderIndex);
        leader = {v.agents.pos[j], v.agents.vel[j], v.agents.fwd[j], v.agents.radius[j], v.agents.info[j].id};
    }

    if (s.on(B::Containment)) {
        // Only agents whose probes can reach the bounds ask; the rest are far inside.
        const float probe = s.containment.probeMinM + s.containment.probeLookaheadS * self.speed() + self.radius;
        const glm::vec3 lo = p - v.set.bounds.min, hi = v.set.bounds.max - p;
        const float nearest = s.vehicle.flying ? std::min({lo.x, lo.y, lo.z, hi.x, hi.y, hi.z})
                                               : std::min({lo.x, lo.z, hi.x, hi.z});  // walkers ignore height
        if (nearest < probe)
            request(B::Containment, [&] { return stayInside(self, v.set.bounds, s.containment); });
    }
    steerAroundStatics(v, brains, i, self, goal, requests, sink);
    // Separation and collision avoidance leave to lower-priority neighbours the whole
    // of making way (WorldPriority.h).
    // (The buffer is only written when priorities differ, and only as far as it is read.)
    UninitialisedArray<Neighbour, kMaxNeighbours> yielding;
    const std::span<const Neighbour> avoided =
        v.types.makingWay ? neighboursToAvoid(v, i, near, yielding.data()) : near;
    request(B::Separation, [&] { return separate(self, avoided, s.separation); });
    request(B::UnalignedCollisionAvoidance, [&] { return avoidUnalignedCollisions(self, avoided, s.unaligned); });
    if (leaderIndex >= 0) {
        request(B::Evasion, [&] { return evade(self, leader, s.evasion); });
        request(B::Flee, [&] { return flee(self, leader.position, s.flee); });
        request(B::LeaderFollowing, [&] { return followLeader(self, leader, s.leader); });
        request(B::OffsetPursuit, [&] { return pursueOffset(self, leader, s.offsetPursuit); });
        request(B::Pursuit, [&] { return pursue(self, leader, s.pursuit); });
    } else if (hasGoal) {
        request(B::Flee, [&] { return flee(self, goal, s.flee); });
    }
    if (v.agents.path[i] >= 0) {
        const auto k = std::size_t(v.agents.path[i]);
        const SteeringPath path{v.set.pathPoints[k], v.set.paths[k].radiusM, v.set.paths[k].closed};
        // Paths lie on the ground; a flier follows one in the horizontal at its own height.
        SteeringAgent flat = self;
        if (s.vehicle.flying)
            flat.position.y = flat.velocity.y = 0.0f;
        request(B::PathFollowing, [&] { return followPath(flat, path, s.path, v.agents.pathAlong[i]); });
    }
    if (!v.set.flow.empty())
        request(B::FlowFieldFollowing,
                [&] { return followFlow(self, flowDirection(v, flowSamplePoint(self, s.flow)), s.flow); });
    if (hasGoal && v.agents.path[i] < 0) {
        // An exit is walked through, not stopped at: slowing down short of it, a walker
        // whose door posts pushed it back (wall following) stood in front of the door for
        // good (issue 23). Walkers with a navigation target keep their slowing: it sets a
        // flow-field walker's pace in a crowd (WorldNav.cpp, Weidmann).
        request(B::Arrival, [&] {
            if (!v.set.goals[std::size_t(v.agents.goal[i])].exit || (v.nav.active && v.nav.hasTarget[i]))
                return arrive(self, goal, s.arrival);
            ArrivalParams through = s.arrival;
            through.slowingDistanceM = 1e-6f;
            return arrive(self, goal, through);
        });
        request(B::Seek, [&] { return seek(self, goal, s.seek); });
    }
    request(B::Alignment, [&] { return align(self, near, s.alignment); });
    request(B::Cohesion, [&] { return cohere(self, near, s.cohesion); });
    wanderOut = v.agents.wander[i];
    if (s.on(B::Wander)) {
        const std::uint64_t key = rngKey(v.seed, v.agents.info[i].id, v.clock.step);
        const glm::vec3 random(rngRangeOf(key, kWanderX, -1.0f, 1.0f), rngRangeOf(key, kWanderY, -1.0f, 1.0f),
                               rngRangeOf(key, kWanderZ, -1.0f, 1.0f));
        const WanderResult w = wander(self, v.agents.wander[i], random, s.wander);
        wanderOut = w.state;
        requests.add(w.force, s.w(B::Wander) * brains.weight(i, B::Wander));
        if (sink)
            sink->force(B::Wander, w.force, s.w(B::Wander) * brains.weight(i, B::Wander));
    }
    // A walker or vehicle with nowhere to go comes to rest instead of coasting on what
    // separation or a collision gave it (the lowest priority: anything else comes first).
    const bool goesSomewhere = hasGoal || v.agents.path[i] >= 0 || leaderIndex >= 0 || s.on(B::Wander) ||
                               (!v.set.flow.empty() && s.on(B::FlowFieldFollowing));
    if (!goesSomewhere && !s.vehicle.flying)
        requests.add(-self.velocity * (self.mass / kStandStillResponseS), 1.0f);
    return s.priority ? allocateByPriority(requests, self.maxForce) : blendWeighted(requests, self.maxForce);
}

// The neighbours agent i avoids: all but those of lower priority, which make way for it.
// `near` itself when nobody is of lower priority (always, between equals).
std::span<const Neighbour> neighboursToAvoid(const StepView& v, std::size_t i, std::span<const Neighbour> near,
                                             Neighbour* buffer)
{
    if (!v.types.makingWay)
        return near;  // all equals: nobody makes way
    const std::uint32_t* index = &v.agents.nearIndex[i * kMaxNeighbours];
    const float priority = v.collision(i).priority;
    std::size_t n = 0;
    for (std::size_t k = 0; k < near.size(); ++k)
        if (v.collision(index[k]).priority >= priority)
            buffer[n++] = near[k];
    return n == near.size() ? near : std::span<const Neighbour>(buffer, n);
}

// Reciprocal avoidance (ORCA) on the ground: the velocity the blend asks for becomes the
// nearest one that touches no neighbour within the horizon. Each pair splits the
// avoidance by priority (WorldPriority.h): an agent that has stopped will not move and
// one of higher priority will not yield, so the other takes all of it; against one of
// lower priority an agent takes none and does not see it here at all.
glm::vec3 avoidReciprocally(const StepView& v, std::size_t i, const SteeringAgent& self, glm::vec3 force,
                            std::span<const Neighbour> near, const TypeSteering& s)
{
    // Decided for the time until the next decision (StepRate.h), v.clock.decideDt.
    if (self.mass <= 0.0f || v.clock.decideDt <= 0.0f)
        return force;
    const glm::vec3 wanted = self.velocity + force * (v.clock.decideDt / self.mass);
    glm::vec2 preferred(wanted.x, wanted.z);
    const float speed = glm::length(preferred);
    if (speed > self.maxSpeed && speed > 0.0f)
        preferred *= self.maxSpeed / speed;
    UninitialisedArray<PlanarNeighbour, kMaxNeighbours> others;  // the first `count` are written, and read
    const std::uint32_t* index = &v.agents.nearIndex[i * kMaxNeighbours];
    const glm::vec2 fwd = xz(self.forward);
    std::size_t oncoming = 0, count = 0;
    const TypeCollision& mine = v.collision(i);
    for (std::size_t k = 0; k < near.size(); ++k) {
        const bool stopped = v.agents.stopped[index[k]] != 0;
        // Between equals (no priorities in the scene) the share is 1 or 1/2, as avoidanceShare says.
        const float share =
            v.types.makingWay ? avoidanceShare(mine, v.collision(index[k]), stopped) : (stopped ? 1.0f : 0.5f);
        if (share <= 0.0f)
            continue;
        PlanarNeighbour& o = others[count++];
        o = {xz(near[k].position), xz(near[k].velocity), near[k].radius, share};
        if (!stopped && glm::dot(xz(near[k].forward), fwd) < -0.5f &&
            glm::dot(o.position - xz(self.position), fwd) > 0.0f)
            ++oncoming;
    }
    // Keep to the right of oncoming walkers (the pedestrians' convention), more the more
    // of them come: opposing streams then pass side by side instead of meeting head-on.
    if (oncoming > 0 && s.reciprocal.keepRightRad > 0.0f) {
        const glm::vec2 turn = s.keepRightTurn[std::min<std::size_t>(oncoming, 3) - 1];
        const glm::vec2 right(-preferred.y, preferred.x);
        preferred = preferred * turn.x + right * turn.y;
    }
    const PlanarBody body{xz(self.position), xz(self.velocity), self.radius, self.maxSpeed};
    const glm::vec2 chosen =
        sim::avoidReciprocally(body, preferred, {others.data(), count}, v.clock.decideDt, s.reciprocal);
    return (glm::vec3(chosen.x, 0.0f, chosen.y) - glm::vec3(self.velocity.x, 0.0f, self.velocity.z)) *
           (self.mass / v.clock.decideDt);
}

}  // namespace throng::sim
