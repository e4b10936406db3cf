// The steer phase (Steer.h): what an agent's type's behaviours ask of it, from what it
// senses (Sense.h). Reads only the previous state.
#include "simcore/world/Steer.h"

#include "simcore/world/BrainPhase.h"
#include "simcore/world/StepView.h"
#include "simcore/world/Formations.h"
#include "simcore/world/WorldPriority.h"

#include "simcore/steering/UninitialisedArray.h"
#include "simcore/world/DebugSink.h"
#include "simcore/world/Sense.h"
#include "simcore/world/detail/BehaviourStep.h"
#include "simcore/world/detail/StepGeometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace throng::sim {

using namespace detail;

namespace {

using detail::BehaviourStep;

// Asks each behaviour of `Rows` that agent's type runs for its forces, in the list's order,
// weighted by the type and the agent's brain, and tells the sink (describeAgent) what each
// asked for. A behaviour the type does not run (weight 0) is not asked.
template <class... Rows>
void requestBehaviours(BehaviourRows<Rows...>, const BehaviourStep& step, const TypeSteering& s,
                       const BrainPhase& brains, SteeringRequestList& requests, DebugSink* sink)
{
    auto one = [&]<class Row>(Row) {
        constexpr Behaviour b = Row::kBehaviour;
        using D = typename Row::Type;
        if (!s.on(b))
            return;
        D::request(step, s.*D::kParams, [&](glm::vec3 force) {
            const float weight = s.w(b) * brains.weight(step.i, b);
            requests.add(force, weight);
            if (sink)
                sink->force(b, force, weight);
        });
    };
    (one(Rows{}), ...);
}

// Whether a behaviour the type runs gives agent `step` somewhere to go without a goal, a
// path or a leader (a descriptor says so with leadsSomewhere; most do not).
template <class... Rows>
bool leadsSomewhere(BehaviourRows<Rows...>, const BehaviourStep& step, const TypeSteering& s)
{
    auto one = [&]<class Row>(Row) {
        if constexpr (requires { Row::Type::leadsSomewhere(step); })
            return s.on(Row::kBehaviour) && Row::Type::leadsSomewhere(step);
        else
            return false;
    };
    return (one(Rows{}) || ...);
}

template <Behaviour B>
using RowOf = typename BehaviourRowOf<BehaviourList, B>::Type;

}  // namespace

// Wall following's and obstacle avoidance's requests, in steer's order (after containment):
// the walker kernel (WalkKernel.cpp) adds them through here, so it and steer add the same
// forces with the same weights. Nothing when the world has no walls or obstacles.
void steerAroundStatics(const StepView& v, const BrainPhase& brains, std::size_t i, const SteeringAgent& self,
                        glm::vec3 goal, SteeringRequestList& requests, DebugSink* sink)
{
    const TypeSteering& s = v.types.steering[v.agents.info[i].typeIndex];
    const BehaviourStep step{.v = v, .i = i, .self = self, .flying = s.vehicle.flying, .goal = goal};
    requestBehaviours(BehaviourRows<RowOf<Behaviour::WallFollowing>, RowOf<Behaviour::ObstacleAvoidance>>{}, step, s,
                      brains, requests, sink);
}

// Steer: every behaviour the type runs, in the behaviour list's order (BehaviourTable.h),
// combined by blending or by prioritised allocation. Pure in the previous state; the new
// wander state goes out.
glm::vec3 steer(const StepView& v, const BrainPhase& brains, std::size_t i, const SteeringAgent& self,
                std::span<const Neighbour> near, WanderState& wanderOut, DebugSink* sink)
{
    const TypeSteering& s = v.types.steering[v.agents.info[i].typeIndex];
    SteeringRequestList requests;
    const glm::vec3 p = self.position;
    // A member of a formation or of companions walks to its slot round its anchor, not to
    // its goal or along its path, until the anchor has arrived (Formations.h).
    const Formations::SlotTarget slot = v.formations.target(i, v.agents, v.set);
    const std::int32_t anchor = slot.anchor;
    const bool hasGoal = v.agents.goal[i] >= 0 && anchor < 0;
    const std::int32_t leaderIndex = anchor >= 0 ? anchor : v.agents.leader[i];
    Neighbour leader;
    if (leaderIndex >= 0) {
        const auto j = std::size_t(leaderIndex);
        leader = {v.agents.pos[j], v.agents.vel[j], v.agents.fwd[j], v.agents.radius[j], v.agents.info[j].id};
    }
    // What wall following and obstacle avoidance steer round statics toward: the goal (the
    // navigation's waypoint), a member's slot, else straight on.
    const glm::vec3 goal = hasGoal     ? v.nav.goal(i, glm::vec3(v.agents.goalSpot[i].x, p.y, v.agents.goalSpot[i].y))
                           : anchor >= 0 ? pointInFrameOf(leader, slot.offsetM)
                                         : p + self.forward;
    // Separation and collision avoidance leave to lower-priority neighbours the whole
    // of making way (WorldPriority.h).
    // (The buffer is only written when priorities differ, and only as far as it is read.)
    UninitialisedArray<Neighbour, kMaxNeighbours> yielding;
    const std::span<const Neighbour> avoided =
        v.types.makingWay ? neighboursToAvoid(v, i, near, yielding.data()) : near;
    wanderOut = v.agents.wander[i];
    const BehaviourStep step{.v = v,
                             .i = i,
                             .self = self,
                             .flying = s.vehicle.flying,
                             .goal = goal,
                             .hasGoal = hasGoal,
                             .leader = leaderIndex >= 0 ? &leader : nullptr,
                             .avoided = avoided,
                             .near = near,
                             .wanderOut = &wanderOut,
                             .formed = anchor >= 0};
    requestBehaviours(BehaviourList{}, step, s, brains, requests, sink);
    if (anchor >= 0)
        requests.add(pursueOffset(self, leader, Formations::slotParams(slot)), Formations::kSlotWeight);
    // A walker or vehicle with nowhere to go comes to rest instead of coasting on what
    // separation or a collision gave it (the lowest priority: anything else comes first).
    const bool goesSomewhere =
        hasGoal || v.agents.path[i] >= 0 || leaderIndex >= 0 || leadsSomewhere(BehaviourList{}, step, s);
    if (!goesSomewhere && !s.vehicle.flying)
        requests.add(standStillForce(self.velocity, self.mass), 1.0f);
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
        oncoming += comesTheOtherWay(xz(self.position), fwd, o.position, xz(near[k].forward), stopped);
    }
    const PlanarBody body{xz(self.position), xz(self.velocity), self.radius, self.maxSpeed};
    return reciprocalForce(body, self.mass, force, {others.data(), count}, oncoming, s.keepRightTurn,
                           v.clock.decideDt, s.reciprocal);
}

}  // namespace throng::sim
