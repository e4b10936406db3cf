#pragma once
// The steering behaviours' formulas, each written once, as templates over a lane type:
// F is float (one agent, with glm::vec3 for its vectors) or a vector of floats from
// base/Lanes.h (F4 or F8 for four or eight agents at once, F1 for one), and V3 is the
// matching vector (Vec3Of<F>). The general steering functions (FlockingBehaviours.cpp,
// TargetBehaviours.cpp, PursuitBehaviours.cpp, Wander.cpp,
// UnalignedCollisionAvoidance.cpp), the walker kernel (WalkKernel.cpp) and the boids
// kernel (BoidKernel.cpp, BoidKernelLanes.cpp) all call these, so a change to a behaviour
// is made here and reaches every path.
//
// A choice one agent makes with a branch, several make with a lane mask: both sides are
// computed and select keeps one, which gives the branch's bits wherever the kept side is
// computed the same way. Every operation is what the scalar code did before, in the same
// order (simcore builds with -ffp-contract=off, so no fused multiply-add changes a bit),
// which kept every result to the bit (demos.TestGoldenRuns). Always inlined: an eight-float
// value may not cross a call into code not built for AVX (base/Lanes.h).
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include "simcore/base/Lanes.h"
#include "simcore/steering/FlockingBehaviours.h"
#include "simcore/steering/UnalignedCollisionAvoidance.h"
#include "simcore/steering/detail/SteeringConstants.h"
#include "simcore/steering/detail/SteeringMath.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>

namespace throng::sim::behave {

using simd::Lanes3;

// The vector of a lane type: glm::vec3 for one float, Lanes3 for a vector of floats.
template <class F>
struct Vec3Of_ {
    using type = Lanes3<F>;
};
template <>
struct Vec3Of_<float> {
    using type = glm::vec3;
};
template <class F>
using Vec3Of = typename Vec3Of_<F>::type;

template <class F>
inline constexpr bool kScalar = std::is_same_v<F, float>;

// The lane helpers for one float (base/Lanes.h has them for vectors); the same operations.
using simd::maxOf;
using simd::minOf;
using simd::select;
[[gnu::always_inline]] inline float sqrtOf(float x) { return std::sqrt(x); }
using simd::sqrtOf;
[[gnu::always_inline]] inline float dot(glm::vec3 a, glm::vec3 b) { return glm::dot(a, b); }
using simd::dot;
[[gnu::always_inline]] inline float length(glm::vec3 v) { return glm::length(v); }
using simd::length;
[[gnu::always_inline]] inline glm::vec3 cross(glm::vec3 a, glm::vec3 b) { return glm::cross(a, b); }
using simd::cross;
template <class F>
[[gnu::always_inline]] inline F splat(float x)
{
    if constexpr (kScalar<F>)
        return x;
    else
        return simd::splat<F>(x);
}
template <class V3>
[[gnu::always_inline]] inline V3 zero3()
{
    if constexpr (std::is_same_v<V3, glm::vec3>)
        return glm::vec3(0.0f);
    else
        return V3{};
}
// SteeringMath.h's normalizeOr (lengths up to kTiny count as zero) and truncate.
[[gnu::always_inline]] inline glm::vec3 normalizeOr(glm::vec3 v, glm::vec3 fallback)
{
    return detail::normalizeOr(v, fallback);
}
template <class F>
[[gnu::always_inline]] inline Lanes3<F> normalizeOr(Lanes3<F> v, Lanes3<F> fallback)
{
    return simd::normalizeOr(v, fallback, detail::kTiny);
}
[[gnu::always_inline]] inline glm::vec3 truncate(glm::vec3 v, float maxLength)
{
    return detail::truncate(v, maxLength);
}
using simd::truncate;

// --- Turning a desired velocity into a force ---------------------------------------------

// Reynolds 1999's steering = desired velocity - velocity, as the force that reaches it in
// the response time (gain = mass / response time: responseGain), truncated to maxForce
// (>= 0). One agent that already moves at the desired velocity, or whose force overflows,
// is asked for no force (+0 in every component); lanes keep what the formula gives there,
// which differs only in the sign of a zero or for a velocity past any speed. The general
// path's behaviours call it through steerTowards (below), the kernels directly.
template <class F, class V3 = Vec3Of<F>>
[[gnu::always_inline]] inline V3 towards(V3 velocity, V3 desired, F gain, F maxForce)
{
    const V3 dv = desired - velocity;
    const V3 f = dv * gain;
    const F f2 = dot(f, f);
    if constexpr (kScalar<F>) {
        if (dv == glm::vec3(0.0f) || !(f2 < detail::kInfinity))
            return glm::vec3(0.0f);
        return f2 > maxForce * maxForce ? f * (maxForce / sqrtOf(f2)) : f;
    } else {
        return select(f2 > maxForce * maxForce, f * (maxForce / sqrtOf(f2)), f);
    }
}

// --- Desired velocities ---------------------------------------------------------------

// Seek (Reynolds 1999): top speed straight at the target, `offset` = target - position;
// zero for a zero offset.
template <class F, class V3 = Vec3Of<F>>
[[gnu::always_inline]] inline V3 seekVelocity(V3 offset, F maxSpeed)
{
    return normalizeOr(offset, zero3<V3>()) * maxSpeed;
}

// Arrival (Reynolds 1999): the desired speed falls linearly from maxSpeed at slowingM
// (> 0) to zero at the target; `dist` is the length of `offset` (target - position), and
// the caller has checked it is above the tolerance and kTiny.
template <class F, class V3 = Vec3Of<F>>
[[gnu::always_inline]] inline V3 arrivalVelocity(V3 offset, F dist, F maxSpeed, F slowingM)
{
    return offset * (maxSpeed * minOf(splat<F>(1.0f), dist / slowingM) / dist);
}

// Arrival's desired velocity for one agent, `offset` = target - position: zero within the
// tolerance (or kTiny) of the target, else arrivalVelocity with the limits made usable
// (SteeringMath.h). TargetBehaviours.cpp's arrivalVelocity and the walker kernel call it.
[[gnu::always_inline]] inline glm::vec3 arrivalDesired(glm::vec3 offset, float maxSpeed, float slowingM,
                                                       float toleranceM)
{
    offset = detail::finiteOrZero(offset);
    const float dist = glm::length(offset);
    if (dist <= detail::nonNegative(toleranceM) || dist <= detail::kTiny)
        return glm::vec3(0.0f);
    return arrivalVelocity(offset, dist, detail::nonNegative(maxSpeed),
                           std::max(detail::nonNegative(slowingM), detail::kTiny));
}

// Pursuit (Reynolds 1999): seek where the quarry will be after distance / max speed,
// looking at most capS ahead.
template <class F, class V3 = Vec3Of<F>>
[[gnu::always_inline]] inline V3 pursuitVelocity(V3 position, V3 quarry, V3 quarryVelocity, F maxSpeed, F capS)
{
    F ahead;
    if constexpr (kScalar<F>)
        ahead = maxSpeed > detail::kTiny ? minOf(length(quarry - position) / maxSpeed, capS) : capS;
    else
        ahead = select(maxSpeed > detail::kTiny, minOf(length(quarry - position) / maxSpeed, capS), capS);
    return seekVelocity(quarry + quarryVelocity * ahead - position, maxSpeed);
}

// Alignment (Reynolds 1987) over n > 0 neighbours, from the sums of their velocities and
// (unit) headings: their mean velocity (matchSpeed), or their mean heading at the agent's
// speed, capped at its top speed. `aligned` is false where the headings cancel out (no
// force then).
template <class F>
struct Alignment {
    Vec3Of<F> desired;
    simd::MaskOf<F> aligned;
};
template <class F, class V3 = Vec3Of<F>>
[[gnu::always_inline]] inline Alignment<F> alignmentVelocity(V3 headings, V3 velocities, F n, F speed, F maxSpeed,
                                                             simd::MaskOf<F> matchSpeed)
{
    if constexpr (kScalar<F>) {
        if (matchSpeed)
            return {truncate(velocities / n, maxSpeed), true};
        const glm::vec3 dir = normalizeOr(headings, glm::vec3(0.0f));
        return {dir * minOf(speed, maxSpeed), dir != glm::vec3(0.0f)};
    } else {
        using M = simd::MaskOf<F>;
        const V3 matched = truncate(velocities / n, maxSpeed);
        const V3 dir = normalizeOr(headings, V3{});
        const M anyDir = (dir.x != 0.0f) | (dir.y != 0.0f) | (dir.z != 0.0f);
        return {select(matchSpeed, matched, dir * minOf(speed, maxSpeed)), matchSpeed | anyDir};
    }
}

// Cohesion (Reynolds 1987): arrive at the centre of n > 0 neighbours (the sum of their
// positions), slowing within slowingM.
template <class F, class V3 = Vec3Of<F>>
[[gnu::always_inline]] inline V3 cohesionVelocity(V3 position, V3 positions, F n, F maxSpeed, F slowingM)
{
    const V3 offset = positions / n - position;
    const F dist = length(offset);
    if constexpr (kScalar<F>)
        return dist > detail::kTiny ? arrivalVelocity(offset, dist, maxSpeed, slowingM) : glm::vec3(0.0f);
    else
        return select(dist > detail::kTiny, arrivalVelocity(offset, dist, maxSpeed, slowingM), V3{});
}

// Wander (Reynolds 1999), its target: jittered on the unit sphere (or circle), kept unit
// from step to step; the previous target where the jitter cancels it.
template <class F, class V3 = Vec3Of<F>>
[[gnu::always_inline]] inline V3 wanderTarget(V3 previous, F radiusM, V3 jitter)
{
    return normalizeOr(previous * radiusM + jitter, previous);
}

// Wander's aim: the target on the sphere of radiusM distanceM ahead, in the frame of
// heading, right and up.
template <class F, class V3 = Vec3Of<F>>
[[gnu::always_inline]] inline V3 wanderAim(V3 heading, V3 right, V3 up, V3 target, F radiusM, F distanceM)
{
    return heading * distanceM + (right * target.x + up * target.y + heading * target.z) * radiusM;
}

// --- Separation ------------------------------------------------------------------------

// Separation's parameters as its push takes them (addSeparation): the range, >= 0, and
// the damping gain, the agent's mass (effectiveMass) over the damping time of at least
// kMinResponseTimeS. separate works them out per agent, the kernels once per type.
struct SeparationGains {
    float range = 0.0f, damping = 0.0f;
};
inline SeparationGains separationGains(const SeparationParams& params, float mass)
{
    return {detail::nonNegative(params.rangeM),
            mass / std::max(detail::nonNegative(params.dampingTimeS), detail::kMinResponseTimeS)};
}

// The floor of separation's weight, reference / kMaxSeparationWeight, kept between the
// neighbours of one agent: it is the same for every neighbour of the same contact
// distance (all of them, where a crowd has one radius), and a division per neighbour
// costs as much as the rest of the push.
struct SeparationFloor {
    float contact = NAN, rangeM = NAN, floor = 0.0f;
};

// One neighbour's push in separation (Reynolds 1999), for a neighbour whose distance d
// is below contact + rangeM (the caller checks: it has d from its search or a length):
//   fade * (maxForce * w - damping * opening speed) * away,
// w = reference / d capped at kMaxSeparationWeight, reference the contact distance (the
// range where the bodies have no size), fading to zero at the edge of the range; the
// damper on the closing speed lets a squeezed pair settle instead of bouncing like two
// springs, and leaves side-by-side walkers alone. `rel` is position - the neighbour's,
// `relVelocity` velocity - the neighbour's; where the two coincide (d up to kTiny) the
// push leaves along axis() (separationAxis), asked only then. One agent's form keeps the
// weight's floor in `kept` (SeparationFloor); the lanes' computes it.
template <class F, class V3 = Vec3Of<F>, class Axis>
[[gnu::always_inline]] inline V3 separationPush(V3 rel, F d, F contact, F rangeM, F maxForce, F damping,
                                                V3 relVelocity, Axis&& axis, SeparationFloor& kept)
{
    const F reach = contact + rangeM;
    V3 away;
    F reference, fade, floor;
    if constexpr (kScalar<F>) {
        reference = contact > detail::kTiny ? contact : rangeM;
        if (!(contact == kept.contact && rangeM == kept.rangeM))
            kept = {contact, rangeM, reference / kMaxSeparationWeight};
        floor = kept.floor;
        // rel / d and (reach - d) / range, the same divisions in one instruction.
        const simd::F4 q = simd::F4{rel.x, rel.y, rel.z, reach - d} / simd::F4{d, d, d, rangeM};
        fade = rangeM > detail::kTiny ? minOf(1.0f, q[3]) : 1.0f;
        away = d > detail::kTiny ? glm::vec3(q[0], q[1], q[2]) : axis();
    } else {
        reference = select(contact > detail::kTiny, contact, rangeM);
        floor = reference / kMaxSeparationWeight;
        fade = select(rangeM > detail::kTiny, minOf(splat<F>(1.0f), (reach - d) / rangeM), splat<F>(1.0f));
        const auto apart = d > detail::kTiny;
        away = select(apart, rel / d, simd::any(~apart) ? axis() : V3{});
    }
    const F w = reference / maxOf(d, floor);
    const F opening = dot(relVelocity, away);
    return away * (fade * (maxForce * w - damping * opening));
}

// Separation's push from one neighbour, added to `push` where the bodies' gap (`d` apart,
// `contact` = the sum of their radii) is within range; `rel` = the agent - the neighbour,
// relVelocity likewise. One agent at a time, as separate (FlockingBehaviours.cpp) and the
// walker kernel sum it.
template <class Axis>
[[gnu::always_inline]] inline void addSeparation(glm::vec3& push, SeparationFloor& floor, glm::vec3 rel, float d,
                                                 float contact, float rangeM, float maxForce, float damping,
                                                 glm::vec3 relVelocity, Axis&& axis)
{
    if (d < contact + rangeM)
        push += separationPush(rel, d, contact, rangeM, maxForce, damping, relVelocity, axis, floor);
}

// --- A flier's step of the vehicle model --------------------------------------------------
// (Reynolds 1999, banking as OpenSteer's SimpleVehicle.) integrateVehicle (VehicleModel.cpp)
// steps one flier with these, the boids kernel four or eight at once.

// The velocity the force (truncated already) gives over the step: within maxSpeed, and
// lifted to minSpeed (<= maxSpeed) along itself or, all but stopped, along forward.
template <class F, class V3 = Vec3Of<F>>
[[gnu::always_inline]] inline V3 flierVelocity(V3 velocity, V3 force, F dtOverMass, F maxSpeed, F minSpeed,
                                               V3 forward)
{
    const V3 v = truncate(velocity + force * dtOverMass, maxSpeed);
    const F speed = length(v);
    if constexpr (kScalar<F>)
        return speed < minSpeed ? (speed > detail::kStoppedSpeed ? v / speed : forward) * minSpeed : v;
    else
        return select(speed < minSpeed, select(speed > detail::kStoppedSpeed, v / speed, forward) * minSpeed, v);
}

// The flier's new up: from `up`, `blend` of the way (the banking response over the step)
// toward the world's up leant by its lateral acceleration (bankGain >= 0, s^2/m), the part
// of `acceleration` across its new `forward`.
template <class F, class V3 = Vec3Of<F>>
[[gnu::always_inline]] inline V3 bankedUp(V3 up, V3 forward, V3 acceleration, F bankGain, F blend)
{
    V3 worldUp;
    if constexpr (kScalar<F>)
        worldUp = detail::kWorldUp;
    else
        worldUp = V3{F{}, splat<F>(1.0f), F{}};
    const V3 lateral = acceleration - forward * dot(acceleration, forward);
    const V3 target = normalizeOr(worldUp + lateral * bankGain, worldUp);
    return normalizeOr(up + (target - up) * blend, worldUp);
}

// bankedUp's blend for a step of dt (s): 1 - e^(-dt / response), the banking's response
// time at least kMinResponseTimeS.
inline float bankingBlend(float bankingResponseS, float dt)
{
    const float response = std::max(detail::nonNegative(bankingResponseS), detail::kMinResponseTimeS);
    return 1.0f - std::exp(-dt / response);
}

// The flier's frame made square to its new `forward` (unit) from its banked `up` (unit):
// side = forward x up made unit, then up = side x forward, unit already (both unit and
// square to each other; not normalised again, which would cost the boids kernel a square
// root a lane for a change in the last bits). `square` holds where that is so; elsewhere
// (forward along up, or a value not finite) each agent takes squareFrameAlong's frame.
template <class F>
struct SquareFrame {
    Vec3Of<F> side, up;
    simd::MaskOf<F> square;
};
template <class F, class V3 = Vec3Of<F>>
[[gnu::always_inline]] inline SquareFrame<F> squareFrame(V3 forward, V3 up)
{
    const V3 sideRaw = cross(forward, up);
    const F sideLen = length(sideRaw);
    const V3 side = sideRaw * (1.0f / sideLen);
    if constexpr (kScalar<F>)
        return {side, cross(side, forward), sideLen > 0.5f && sideLen < detail::kInfinity};
    else
        return {side, cross(side, forward), (sideLen > 0.5f) & (sideLen < simd::kLaneInfinity)};
}

// squareFrame for one agent where it is not square: side from forward x up where that has
// a length, else the agent's last side; up square to both, else the world's.
[[gnu::always_inline]] inline SquareFrame<float> squareFrameAlong(glm::vec3 forward, glm::vec3 up,
                                                                   glm::vec3 lastSide)
{
    const glm::vec3 side = normalizeOr(glm::cross(forward, up), lastSide);
    return {side, normalizeOr(glm::cross(side, forward), detail::kWorldUp), true};
}

// --- Unaligned collision avoidance ------------------------------------------------------
// (Reynolds 1999.) One agent at a time: no lane kernel runs it yet.

// Its parameters as the formulas take them: the horizon (s) and the margin (m), both
// >= 0, and the share of the force that brakes, in [0, 1] (0 where it is not a number).
struct UnalignedGains {
    float horizonS = 0.0f, marginM = 0.0f, brake = 0.0f;
};
inline UnalignedGains unalignedGains(const UnalignedAvoidanceParams& params)
{
    return {detail::nonNegative(params.horizonS), detail::nonNegative(params.marginM),
            std::clamp(detail::finiteOr(params.brakeFraction, 0.0f), 0.0f, 1.0f)};
}

// Whether a neighbour `dp` away (its position - the agent's), moving at `dv` relative to
// the agent, comes nearer than `clear` within horizonS: then the time of nearest approach
// and the neighbour's offset at that time. Two moving together never close the gap.
[[gnu::always_inline]] inline bool approachesWithin(glm::vec3 dp, glm::vec3 dv, float horizonS, float clear, float& t,
                                                    glm::vec3& offset)
{
    const float dv2 = glm::dot(dv, dv);
    if (!(dv2 > detail::kTiny * detail::kTiny))
        return false;
    t = -glm::dot(dp, dv) / dv2;
    if (!(t >= 0.0f && t <= horizonS))
        return false;
    offset = dp + dv * t;
    return glm::length(offset) < clear;
}

// The soonest threat among the neighbours (the earliest nearest approach, ties by id),
// considered one neighbour at a time. `who` is the caller's name for the neighbour (its
// place in a list, or its index), so the caller can read the threat's motion afterwards.
struct SoonestApproach {
    float timeS = -1.0f;  // < 0: none yet
    std::uint32_t id = 0;
    std::uint32_t who = 0;
    glm::vec3 offset{0.0f};  // the threat minus the agent at the time of nearest approach

    // A neighbour `dp` away (its position - the agent's), moving at `dv` relative to the
    // agent: a threat where it comes nearer than `clear` (both radii and the margin) within
    // horizonS (approachesWithin).
    [[gnu::always_inline]] void consider(glm::vec3 dp, glm::vec3 dv, float horizonS, float clear, std::uint32_t idOf,
                                         std::uint32_t whoOf)
    {
        float t;
        glm::vec3 at;
        if (!approachesWithin(dp, dv, horizonS, clear, t, at))
            return;
        if (timeS < 0.0f || t < timeS || (t == timeS && idOf < id)) {
            timeS = t;
            id = idOf;
            who = whoOf;
            offset = at;
        }
    }
    bool found() const { return timeS >= 0.0f; }
};

// The force that avoids the soonest threat: to the side away from where it will be (right
// when it comes dead ahead), harder the sooner it comes. Head on, the agent also brakes
// with `brake` of the budget (when moving along its heading h) and steers with `lateral`
// = sqrt(1 - brake^2), so the two together never exceed maxForce.
[[gnu::always_inline]] inline glm::vec3 unalignedAvoidance(glm::vec3 h, glm::vec3 right, glm::vec3 offset, float t,
                                                           float horizonS, bool headOn, float brake, float lateral,
                                                           bool moving, float maxForce)
{
    const float sideSign = glm::dot(offset, right) > detail::kDeadAheadM ? -1.0f : 1.0f;
    const float urgency = 1.0f - t / horizonS;
    const float braking = headOn ? brake : 0.0f;
    const glm::vec3 lateralPart = right * (sideSign * (headOn ? lateral : 1.0f));
    const glm::vec3 brakePart = moving ? -h * braking : glm::vec3(0.0f);
    return (lateralPart + brakePart) * (maxForce * urgency);
}

// Unaligned collision avoidance's force from the soonest threat (found()): the agent's
// heading (its velocity when moving, else its forward) and right (with its up), whether the
// threat, moving at threatVelocity with forward threatForward, comes head on (its heading
// within headOnCosine of the opposite), and unalignedAvoidance. brake is clamped to [0, 1],
// horizonS > kTiny; maxForce >= 0.
[[gnu::always_inline]] inline glm::vec3 avoidSoonest(glm::vec3 velocity, glm::vec3 forward, glm::vec3 up,
                                                     const SoonestApproach& threat, glm::vec3 threatVelocity,
                                                     glm::vec3 threatForward, float horizonS, float headOnCosine,
                                                     float brake, float maxForce)
{
    const float speed = glm::length(velocity);
    const glm::vec3 h = speed > detail::kTiny && speed < detail::kInfinity
                            ? velocity * (1.0f / speed)
                            : detail::normalizeOr(forward, glm::vec3(0.0f, 0.0f, 1.0f));  // heading (SteeringMath.h)
    const glm::vec3 right =
        detail::normalizeOr(glm::cross(h, detail::normalizeOr(up, detail::kWorldUp)), detail::rightOfForward(h));
    const glm::vec3 threatHeading =
        detail::normalizeOr(threatVelocity, detail::normalizeOr(threatForward, glm::vec3(0.0f)));
    const bool headOn = glm::dot(h, threatHeading) < headOnCosine;
    return unalignedAvoidance(h, right, threat.offset, threat.timeS, horizonS, headOn, brake,
                              std::sqrt(1.0f - brake * brake), detail::finiteOrZero(velocity) != glm::vec3(0.0f),
                              maxForce);
}

}  // namespace throng::sim::behave

namespace throng::sim::detail {

// An agent's steering force towards a desired velocity (behave::towards), from a state and
// request made finite, with the agent's own mass, response time and force.
inline glm::vec3 steerTowards(const SteeringAgent& agent, glm::vec3 desiredVelocity, float responseTimeS)
{
    return behave::towards(finiteOrZero(agent.velocity), finiteOrZero(desiredVelocity),
                           responseGain(effectiveMass(agent.mass), responseTimeS), nonNegative(agent.maxForce));
}

}  // namespace throng::sim::detail
