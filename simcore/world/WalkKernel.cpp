// The walker kernel: one agent step (sense, steer, avoid, integrate, constrain) for a
// ground type whose behaviours are only arrival, seek, separation, unaligned collision
// avoidance, containment, wall following, obstacle avoidance, wander and reciprocal
// avoidance (those of `cross`, `corridor` and of an ordinary crowd), fused. It computes
// what steer, avoidReciprocally (Steer.h) and integrateVehicle compute for such an
// agent, operation for operation in the same order, so the result is bit-identical to
// the general path (TestWalkKernel checks it, with brains and without); but in one pass
// over the neighbours, read by index (no Neighbour copies, no request list), with the
// squared distances the search already has and the type's constants made usable once
// instead of per agent.
#include "simcore/world/WalkKernel.h"

#include "simcore/world/BrainPhase.h"

#include "simcore/world/Constraints.h"
#include "simcore/world/Sense.h"
#include "simcore/world/Steer.h"

#include "simcore/steering/KeepRight.h"
#include "simcore/world/NearestList.h"

#include "simcore/steering/UninitialisedArray.h"
#include "simcore/steering/detail/SteeringConstants.h"
#include "simcore/steering/detail/BehaviourMath.h"
#include "simcore/steering/detail/GroundMove.h"
#include "simcore/steering/detail/SteeringMath.h"
#include "simcore/steering/detail/WeightedBlend.h"
#include "simcore/world/detail/StepConstants.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>
#include <cmath>

namespace throng::sim {

using namespace detail;

namespace {

// steerTowards (BehaviourMath.h) with its gain (mass / response time) made once per type.
[[gnu::always_inline]] inline glm::vec3 towardsVelocity(glm::vec3 velocity, glm::vec3 desired, float gain,
                                                        float maxForce)
{
    return behave::towards(velocity, finiteOrZero(desired), gain, maxForce);
}

// Behaviours the kernel computes. Path following only for agents without a path (then
// steer (Steer.h) asks nothing of it either; the move phase sends the others the general way).
bool fitsWalkKernel(const TypeSteering& s)
{
    using B = Behaviour;
    if (s.vehicle.flying || s.wander.flying || s.priority)
        return false;
    for (std::size_t b = 0; b < kBehaviourCount; ++b) {
        const auto behaviour = Behaviour(b);
        const bool allowed = behaviour == B::Containment || behaviour == B::WallFollowing ||
                             behaviour == B::ObstacleAvoidance || behaviour == B::Separation ||
                             behaviour == B::UnalignedCollisionAvoidance || behaviour == B::PathFollowing ||
                             behaviour == B::Arrival || behaviour == B::Seek || behaviour == B::Wander ||
                             behaviour == B::ReciprocalAvoidance;
        if (s.weight[b] > 0.0f && !allowed)
            return false;
    }
    return true;
}

}  // namespace

void WalkKernel::build(const AgentTypes& types, const StaticSet& set, float dt, bool enabled, bool plain)
{
    // Layers or priorities change whom an agent perceives and avoids, and signals hold
    // agents back: those worlds keep the general path. Brains the kernel takes up as the
    // general path does (step, below). Walls and obstacles the kernel steers round and
    // constrains against as steer and the general path do (MovePhase.cpp), through the same
    // functions (steerAroundStatics, constrain).
    plain = plain && enabled;
    const bool walls = !set.walls.segments().empty(), obstacles = !set.circles.empty() || !set.boxes.empty();
    m_runs.assign(types.steering.size(), 0);
    m_walkTypes.assign(types.steering.size(), WalkType{});
    for (std::size_t t = 0; t < types.steering.size(); ++t) {
        const TypeSteering& s = types.steering[t];
        // A walker that keeps a time gap (Headway.h) takes the general path, which applies it.
        m_runs[t] = plain && types.params[t].kind != AgentKind::Flier && fitsWalkKernel(s) && types.timeGapS[t] <= 0.0f
                        ? 1
                        : 0;
        // Each constant as the behaviour's function computes it from the parameters.
        const float mass = effectiveMass(types.params[t].mass);
        WalkType& w = m_walkTypes[t];
        w.wContainment = s.weightIfOn(Behaviour::Containment);
        w.wSeparation = s.weightIfOn(Behaviour::Separation);
        w.wUnaligned = s.weightIfOn(Behaviour::UnalignedCollisionAvoidance);
        w.wArrival = s.weightIfOn(Behaviour::Arrival);
        w.wSeek = s.weightIfOn(Behaviour::Seek);
        w.wWander = s.weightIfOn(Behaviour::Wander);
        w.reciprocal = s.on(Behaviour::ReciprocalAvoidance);
        w.keepRight = types.keepRight[t];
        w.aroundStatics =
            (walls && s.on(Behaviour::WallFollowing)) || (obstacles && s.on(Behaviour::ObstacleAvoidance));
        w.constrained = walls || !set.circles.empty();  // as the move phase's hasStatics
        w.maxForce = nonNegative(types.params[t].maxForce);
        const behave::SeparationGains separation = behave::separationGains(s.separation, mass);
        w.range = separation.range;
        w.damping = separation.damping;
        const behave::UnalignedGains unaligned = behave::unalignedGains(s.unaligned);
        w.horizonS = unaligned.horizonS;
        w.marginM = unaligned.marginM;
        w.brake = unaligned.brake;
        w.gainArrival = responseGain(mass, s.arrival.responseTimeS);
        w.gainSeek = responseGain(mass, s.seek.responseTimeS);
        w.dtOverMass = dt / mass;
    }
}

void WalkKernel::step(const StepView& view, const BrainPhase& brains, AgentColumns& agents, std::size_t i) const
{
    // The brains' and the ties' code only where the World has them: a plain walker pays
    // for neither (about 3 % of the cross's step).
    const bool brain = brains.active(), watch = !view.ties.byIndex();
    if (brain)
        watch ? stepAgent<true, true>(view, brains, agents, i) : stepAgent<true, false>(view, brains, agents, i);
    else
        watch ? stepAgent<false, true>(view, brains, agents, i) : stepAgent<false, false>(view, brains, agents, i);
}

template <bool kBrain, bool kWatch>
void WalkKernel::stepAgent(const StepView& view, const BrainPhase& brains, AgentColumns& agents, std::size_t i) const
{
    const std::uint16_t type = agents.info[i].typeIndex;
    const TypeSteering& s = view.types.steering[type];
    const TypeParams& t = view.types.params[type];
    const WalkType& w = m_walkTypes[type];
    const glm::vec3 p = agents.pos[i], v = agents.vel[i], fwd = agents.fwd[i];
    const float radius = agents.radius[i], maxSpeed = agents.maxSpeed[i];
    const AgentId id = agents.info[i].id;

    // Sense: the k nearest in the perception radius and view cone, nearest first, ties by
    // id (gatherNeighbours, without the layers and priorities this world lacks).
    constexpr std::size_t k = kMaxNeighbours;
    NearestList<k> best;
    const float perception2 = t.perception * t.perception;
    float bound = perception2;
    const float c = t.cosHalfView;
    // Where ids do not rise with the index (kWatch), watch for ties, and should one come,
    // search again with ranks for indices (TieOrder.h).
    auto search = [&](float startBound, bool byRank) {
        best.clear();
        best.byRank = byRank;
        bound = startBound;
        view.grid.forEachNearest(p, t.perception, [&] { return bound; }, [&](std::uint32_t j, const glm::vec3& q) {
            const glm::vec3 d = q - p;
            const float d2 = glm::dot(d, d);
            if (d2 > bound || j == i)
                return;
            if (outsideViewCone(d, d2, fwd, c)) {
                const float contact = radius + agents.radius[j];
                if (d2 > contact * contact)
                    return;
            }
            const std::uint64_t key = nearestKey(d2, kWatch && byRank ? view.ties.rank(j) : j);
            if ((kWatch ? best.insertWatchingTies(key) : best.insert(key)) && best.full())
                bound = best.worstDistance2();
        });
    };
    // As in the boids kernel: start from last step's k nearest, and search in full only
    // when fewer than k lie within them (the result is the same either way).
    const float guess2 = view.warmSearch ? lastNearestBound(agents, i, p, perception2) : perception2;
    // A brain's sense phase may have found them this step (gatherNeighbours), as the general
    // path then takes them (MovePhase.cpp).
    const BrainPhase::Row brain = kBrain ? brains.row(i) : BrainPhase::Row{};  // looked up once
    const bool gathered = kBrain && brain.gathered();
    if (!gathered) {
        search(guess2, false);
        finishNearest(best, guess2, perception2, kWatch, search);
    }
    const std::size_t count = gathered ? agents.nearCount[i] : best.count;
    agents.nearCount[i] = std::uint8_t(count);

    std::uint32_t* nearIndex = &agents.nearIndex[i * k];
    // Between decisions (StepRate.h) the force decided last holds and wander stands still:
    // nothing is steered or avoided, and of the neighbours only the list is kept, which the
    // collide pass reads (Collide.cpp).
    glm::vec3 force = agents.heldForce[i];
    WanderState wanderNext = agents.wander[i];
    if (!view.clock.decide) {
        if (!gathered)
            for (std::size_t n = 0; n < count; ++n)
                nearIndex[n] = best.index(n, view.ties);
    } else {
        // One pass over the neighbours: separation's push (separate), the soonest threat
        // (avoidUnalignedCollisions), and the planar neighbours and oncoming walkers of
        // reciprocal avoidance (avoidReciprocally (Steer.h)).
        const float r = nonNegative(radius), range = w.range, maxForce = w.maxForce;
        const float horizon = w.horizonS;
        const bool unaligned = w.wUnaligned > 0.0f && horizon > kTiny;
        glm::vec3 push(0.0f);
        behave::SeparationFloor floor;
        behave::SoonestApproach threat;  // its `who`: the neighbour's index
        UninitialisedArray<PlanarNeighbour, kMaxNeighbours> others;  // the first `count` are written, and read
        std::size_t oncoming = 0;
        bool oncomingInTheWayAhead = false;  // keeping right (KeepRight.h), as the general path (MovePhase.cpp)
        const glm::vec2 fwd2 = xz(fwd), p2 = xz(p);
        for (std::size_t n = 0; n < count; ++n) {
            const auto j = gathered ? nearIndex[n] : best.index(n, view.ties);
            nearIndex[n] = j;
            const glm::vec3 q = agents.pos[j], vj = agents.vel[j];
            const float rj = agents.radius[j];
            if (w.wSeparation > 0.0f) {
                // The squared distance is the search key's (the same dot product, negated offset).
                const float contact = r + nonNegative(rj);
                const glm::vec3 offset = q - p;
                const float d = std::sqrt(gathered ? glm::dot(offset, offset) + 0.0f
                                                   : std::bit_cast<float>(std::uint32_t(best.keys[n] >> 32)));
                behave::addSeparation(push, floor, p - q, d, contact, range, maxForce, w.damping, v - vj,
                                      [&] { return separationAxis(id, agents.info[j].id); });
            }
            if (unaligned)
                threat.consider(q - p, vj - v, horizon, r + nonNegative(rj) + w.marginM, agents.info[j].id, j);
            if (w.keepRight > 0.0f && !oncomingInTheWayAhead)
                oncomingInTheWayAhead = oncomingInTheWay(p, fwd, radius, q, agents.fwd[j], vj, rj);
            if (w.reciprocal) {
                const bool stopped = agents.stopped[j] != 0;
                PlanarNeighbour& o = others[n];
                o = {xz(q), xz(vj), rj, stopped ? 1.0f : 0.5f};
                oncoming += comesTheOtherWay(p2, fwd2, o.position, xz(agents.fwd[j]), stopped);
            }
        }

        // Steer: steer's (Steer.h) requests in its order, blended (blendWeighted), each weighted
        // by the type and the agent's brain (requestBehaviours, Steer.cpp).
        const bool hasGoal = agents.goal[i] >= 0;
        WeightedBlend blend;  // blendWeighted's sum (SteeringCombination.h), request by request
        auto add = [&](glm::vec3 request, float weight) { blend.add(request, weight); };
        auto brainWeight = [&](Behaviour b) { return kBrain ? brain.weight(b) : 1.0f; };
        // Where seek and arrival aim: the goal's spot for this agent, or its navigation target (navGoal).
        const glm::vec3 goal = !hasGoal ? p + fwd
                               : view.nav.active && view.nav.hasTarget[i]
                                   ? glm::vec3(view.nav.target[i].x, p.y, view.nav.target[i].y)
                                   : glm::vec3(agents.goalSpot[i].x, p.y, agents.goalSpot[i].y);
        const float speedNow = glm::length(v);
        if (w.wContainment > 0.0f &&
            ContainmentBehaviour::probesReach(p, speedNow, radius, view.set.bounds, s.containment, false))
            add(stayInside(steeringAgent(agents, view.types, i), view.set.bounds, s.containment),
                w.wContainment * brainWeight(Behaviour::Containment));
        if (w.aroundStatics) {
            // Wall following and obstacle avoidance: steer's own requests (Steer.cpp).
            SteeringRequestList around;
            steerAroundStatics(view, brains, i, steeringAgent(agents, view.types, i), goal, around);
            for (const SteeringRequest& request : around.requests())
                add(request.force, request.weight);
        }
        if (w.wSeparation > 0.0f)
            add(push, w.wSeparation * brainWeight(Behaviour::Separation));
        if (w.wUnaligned > 0.0f) {
            const glm::vec3 dodge =
                threat.found() ? behave::avoidSoonest(v, fwd, agents.up[i], threat, agents.vel[threat.who],
                                                      agents.fwd[threat.who], horizon, s.unaligned.headOnCosine,
                                                      w.brake, maxForce)
                               : glm::vec3(0.0f);
            add(dodge, w.wUnaligned * brainWeight(Behaviour::UnalignedCollisionAvoidance));
        }
        if (hasGoal && w.wArrival > 0.0f) {
            // Arrival (ArrivalBehaviour): through an exit at full speed, it is walked through.
            const float slowing =
                view.walksThroughGoal(i) ? ArrivalBehaviour::kThroughSlowingM : s.arrival.slowingDistanceM;
            const glm::vec3 desired = behave::arrivalDesired(goal - p, maxSpeed, slowing, s.arrival.toleranceM);
            add(towardsVelocity(v, desired, w.gainArrival, maxForce), w.wArrival * brainWeight(Behaviour::Arrival));
        }
        if (hasGoal && w.wSeek > 0.0f)
            add(towardsVelocity(v, behave::seekVelocity(finiteOrZero(goal - p), nonNegative(maxSpeed)), w.gainSeek,
                                maxForce),
                w.wSeek * brainWeight(Behaviour::Seek));
        if (w.wWander > 0.0f) {
            const WanderResult result = wander(steeringAgent(agents, view.types, i), agents.wander[i],
                                               wanderDraws(view.seed, id, view.clock.step), s.wander);
            wanderNext = result.state;
            add(result.force, w.wWander * brainWeight(Behaviour::Wander));
        }
        // A walker with nowhere to go comes to rest (as in steer, Steer.h).
        if (!hasGoal && agents.leader[i] < 0 && !(w.wWander > 0.0f))
            add(standStillForce(v, t.mass), 1.0f);
        // The brain's turn, as the general path adds it (MovePhase.cpp); its speed cap reads the
        // same old state below.
        const glm::vec3 turn = kBrain ? brain.turnForce(fwd, v, t.mass) : glm::vec3(0.0f);
        force = blend.total(t.maxForce) + turn;
        if (oncomingInTheWayAhead)
            force += keepRightForce(fwd, t.maxForce, w.keepRight);

        // Avoid: the velocity the blend asks for becomes the nearest that touches no neighbour
        // within the horizon (avoidReciprocally (Steer.h) between equals).
        if (w.reciprocal && t.mass > 0.0f && view.clock.decideDt > 0.0f)
            force = reciprocalForce({p2, xz(v), radius, maxSpeed}, t.mass, force, {others.data(), count}, oncoming,
                                    s.keepRightTurn, view.clock.decideDt, s.reciprocal);
        agents.heldForce[i] = force;
    }

    // Integrate: integrateVehicle's walker step (groundMove, VehicleModel.cpp) on a finite
    // state, then stand on the ground (as the general path, MovePhase.cpp).
    const GroundMove move =
        groundMove(p, v, fwd, force, t.maxForce, w.dtOverMass, nonNegative(maxSpeed), view.clock.dt);
    glm::vec3 pos = move.position;
    const glm::vec3 nextFwd = move.forward;
    // The brain's speed caps the step (BrainPhase::capToSpeed), after the frame is set.
    if constexpr (kBrain) {
        glm::vec3 capped = move.velocity;  // the position follows it; the velocity is the move's (below)
        brains.capToSpeed(view, brain, i, p, pos, capped);
    }
    // Constrain: out of walls and obstacles, never through a wall (constrain, Constraints.h).
    if (w.constrained)
        constrain(agents, view.set, view.clock.dt, i, p, pos);
    pos.y = view.set.terrain.heights.empty() ? 0.0f : view.set.groundHeight(pos.x, pos.z);  // no terrain: flat at 0
    glm::vec3 nextVel = (pos - p) / view.clock.dt;
    nextVel.y = 0.0f;
    agents.nextPos[i] = pos;
    agents.nextVel[i] = nextVel;
    agents.nextFwd[i] = nextFwd;
    agents.nextSide[i] = rightOfForward(nextFwd);
    agents.nextUp[i] = kWorldUp;
    agents.nextWander[i] = wanderNext;
}

}  // namespace throng::sim
