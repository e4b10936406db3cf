// The boids kernel's steering and integration (the second half of its step; BoidKernel.cpp
// senses), written once for one, four or eight boids at once, one per lane of a float
// vector (base/Lanes.h): steerBoid runs it with one lane, steerBoids with four or eight.
// Each behaviour's formula comes from steering/detail/BehaviourMath.h, which the general
// path uses too. What each boid's state and type decide (whether it pursues, aligns or
// wanders, which side of a threshold it lies on) becomes a lane mask, and both sides are
// computed and one is kept; the rare cases that need more (containment near the bounds, a
// frame whose up had to fall back, the ground) are done for their lane alone. The result
// is the same to the bit at every width (TestNeighbourSweep steers the same flock one
// boid at a time and by fours and eights). The square roots and divisions of four boids
// go together: a step of 100,000 birds takes about 12 % less time than one boid at a time
// (1 thread). Where the CPU has AVX2, eight go together in one function built for it
// (steerEightBoids), chosen at run time, so the build still runs on any x86-64: about 7 %
// less again (2 threads).
// GCC takes the arrays steerLanes gathers into for unset in its one-lane form (steerBoid),
// though the gather writes every lane of each: a false -Wmaybe-uninitialized, which the
// braces that would silence it cost the four- and eight-lane forms 4 % of a flock's step.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include "simcore/world/BoidKernel.h"

#include "simcore/world/Sense.h"

#include "simcore/steering/detail/SteeringConstants.h"
#include "simcore/steering/detail/BehaviourMath.h"
#include "simcore/steering/detail/SteeringMath.h"
#include "simcore/steering/detail/WeightedBlend.h"
#include "simcore/base/Lanes.h"
#include "simcore/world/detail/StepConstants.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

namespace throng::sim {

using namespace detail;
using namespace simd;

namespace {

template <class F>
[[gnu::always_inline]] inline Lanes3<F> lanes(const glm::vec3* v)
{
    Lanes3<F> r;
    for (int l = 0; l < kWidth<F>; ++l) {
        r.x[l] = v[l].x;
        r.y[l] = v[l].y;
        r.z[l] = v[l].z;
    }
    return r;
}

template <class F>
[[gnu::always_inline]] inline glm::vec3 lane(const Lanes3<F>& v, int l)
{
    return {v.x[l], v.y[l], v.z[l]};
}

template <class F>
[[gnu::always_inline]] inline void setLane(Lanes3<F>& v, int l, glm::vec3 x)
{
    v.x[l] = x.x;
    v.y[l] = x.y;
    v.z[l] = x.z;
}

// finishBoid's collide-free check for one boid at `at`, its k nearest a vector at a time:
// none of them within its keep-out distance (plus the margin) of where it drifts. The
// lanes past `count` hold another boid's neighbours (or zeros) and are left out.
template <class F>
[[gnu::always_inline]] inline bool collideFree(glm::vec3 at, const float* driftX, const float* driftY,
                                               const float* driftZ, const float* keepOut, std::size_t count,
                                               float slack)
{
    constexpr std::size_t kLanes = std::size_t(kWidth<F>);
    static_assert(kMaxNeighbours % kLanes == 0);
    if (!(slack > 0.0f))
        return false;
    const float margin = 1e-4f + 4e-6f * (std::fabs(at.x) + std::fabs(at.y) + std::fabs(at.z));
    for (std::size_t first = 0; first < count; first += kLanes) {
        F x, y, z, keep;
        std::memcpy(&x, driftX + first, sizeof x);
        std::memcpy(&y, driftY + first, sizeof y);
        std::memcpy(&z, driftZ + first, sizeof z);
        std::memcpy(&keep, keepOut + first, sizeof keep);
        const F dx = at.x - x, dy = at.y - y, dz = at.z - z;
        const F reach = keep + margin;
        const unsigned near = bitsOf(~(dx * dx + dy * dy + dz * dz > reach * reach));
        const std::size_t valid = std::min(count - first, kLanes);
        if ((near & ((1u << valid) - 1u)) != 0)
            return false;
    }
    return true;
}

}  // namespace

// Always inlined, as its helpers are, so that in steerEightBoids all of it is built for
// AVX2 and no eight-float value crosses a call (base/Lanes.h).
template <class F>
[[gnu::always_inline]] inline void BoidPass::steerLanes(const std::uint32_t* boid, const BoidSense* sensed)
{
    constexpr int kLanes = kWidth<F>;
    using M = MaskOf<F>;
    using V3 = Lanes3<F>;
    // Gather: each lane's state, its type's parameters and its neighbours' sums, and the
    // parts that take a branch of their own (containment, pursuit's quarry, wander's
    // random jitter). Every lane of each is written below.
    glm::vec3 p[kLanes], v[kLanes], fwd[kLanes], up0[kLanes], contain[kLanes], quarry[kLanes], quarryVel[kLanes],
        jitter[kLanes], prevTarget[kLanes], push[kLanes], headings[kLanes], velocities[kLanes], centre[kLanes];
    F maxSpeed, n, radius, probeMin, probeAhead;
    M pursues, matchSpeed, wanders;
    const BoidType* types[kLanes];
    bool oneType = true;
    for (int l = 0; l < kLanes; ++l) {
        const std::size_t i = boid[l];
        const std::uint16_t type = m_agents.info[i].typeIndex;
        const TypeSteering& s = m_types.steering[type];
        const BoidType& b = m_boidTypes[type];
        types[l] = &b;
        oneType = oneType && types[l] == types[0];
        const BoidSense& in = sensed[l];
        p[l] = m_agents.pos[i];
        v[l] = m_agents.vel[i];
        fwd[l] = m_agents.fwd[i];
        up0[l] = m_agents.up[i];
        maxSpeed[l] = nonNegative(m_agents.maxSpeed[i]);
        radius[l] = m_agents.radius[i];
        probeMin[l] = s.containment.probeMinM;
        probeAhead[l] = s.containment.probeLookaheadS;
        push[l] = in.push;
        headings[l] = in.headings;
        velocities[l] = in.velocities;
        centre[l] = in.centre;
        n[l] = float(in.count);
        matchSpeed[l] = s.alignment.matchSpeed ? -1 : 0;
        contain[l] = glm::vec3(0.0f);
        const std::int32_t leader = m_agents.leader[i];
        pursues[l] = leader >= 0 && b.wPursuit > 0.0f ? -1 : 0;
        quarry[l] = pursues[l] ? m_agents.pos[std::size_t(leader)] : glm::vec3(0.0f);
        quarryVel[l] = pursues[l] ? m_agents.vel[std::size_t(leader)] : glm::vec3(0.0f);
        wanders[l] = b.wWander > 0.0f ? -1 : 0;
        prevTarget[l] = m_agents.wander[i].target;
        jitter[l] = glm::vec3(0.0f);
        if (wanders[l]) {
            jitter[l] = wanderDraws(m_seed, m_agents.info[i].id, m_clock.step) * b.jitterM;
        }
    }
    // A type's parameter in each lane (one load when the lanes share their type, as a
    // flock mostly does).
    auto param = [&](float BoidType::*m) __attribute__((always_inline)) {
        if (oneType)
            return splat<F>(types[0]->*m);
        F r;
        for (int l = 0; l < kLanes; ++l)
            r[l] = types[l]->*m;
        return r;
    };
    const F wSep = param(&BoidType::wSeparation), wPur = param(&BoidType::wPursuit),
            wAli = param(&BoidType::wAlignment), wCoh = param(&BoidType::wCohesion),
            wWan = param(&BoidType::wWander), maxForce = param(&BoidType::maxForce), mass = param(&BoidType::mass),
            gPur = param(&BoidType::gainPursuit), gAli = param(&BoidType::gainAlignment),
            gCoh = param(&BoidType::gainCohesion), gWan = param(&BoidType::gainWander),
            cap = param(&BoidType::predictionCapS), slowing = param(&BoidType::slowingM),
            wanderR = param(&BoidType::wanderRadiusM), wanderD = param(&BoidType::wanderDistanceM),
            minSpeedType = param(&BoidType::minSpeed), bankGain = param(&BoidType::bankGain),
            bankBlend = param(&BoidType::bankBlend), wContain = param(&BoidType::wContainment);
    const V3 P = lanes<F>(p), V = lanes<F>(v), Fwd = lanes<F>(fwd);
    const F speedNow = length(V);
    // Containment, as steerBoid: only near the bounds, where the probe reaches them (the
    // nearest of the six faces found as std::min of a list finds it), and there for each
    // lane alone.
    M contained;
    {
        const F probe = probeMin + probeAhead * speedNow + radius;
        const V3 lo = P - V3{splat<F>(m_set.bounds.min.x), splat<F>(m_set.bounds.min.y), splat<F>(m_set.bounds.min.z)};
        const V3 hi = V3{splat<F>(m_set.bounds.max.x), splat<F>(m_set.bounds.max.y), splat<F>(m_set.bounds.max.z)} - P;
        F nearest = lo.x;
        for (const F face : {lo.y, lo.z, hi.x, hi.y, hi.z})
            nearest = select(face < nearest, face, nearest);
        contained = (wContain > 0.0f) & (nearest < probe);
        for (unsigned bits = bitsOf(contained); bits != 0; bits &= bits - 1) {
            const int l = std::countr_zero(bits);
            const std::size_t i = boid[l];
            contain[l] = stayInside(steeringAgent(m_agents, m_types, i), m_set.bounds,
                                    m_types.steering[m_agents.info[i].typeIndex].containment);
        }
    }

    // Steer, in steer's (Steer.h) order: containment, separation, pursuit, alignment,
    // cohesion, wander, each behaviour's formula from BehaviourMath.h.
    const V3 heading = select(speedNow > kTiny, V * (1.0f / speedNow), Fwd);
    // The blend (WeightedBlend.h, blendWeighted's sum), each behaviour in the lanes that run it.
    WeightedBlendOf<F> blend;
    blend.add(lanes<F>(contain), wContain, contained);
    blend.add(lanes<F>(push), wSep, wSep > 0.0f);
    {
        const V3 desired = behave::pursuitVelocity(P, lanes<F>(quarry), lanes<F>(quarryVel), maxSpeed, cap);
        blend.add(behave::towards(V, desired, gPur, maxForce), wPur, pursues);
    }
    const M some = n > 0.0f;
    {
        const behave::Alignment<F> a =
            behave::alignmentVelocity(lanes<F>(headings), lanes<F>(velocities), n, speedNow, maxSpeed, matchSpeed);
        blend.add(behave::towards(V, a.desired, gAli, maxForce), wAli, some & (wAli > 0.0f) & a.aligned);
    }
    {
        const V3 desired = behave::cohesionVelocity(P, lanes<F>(centre), n, maxSpeed, slowing);
        blend.add(behave::towards(V, desired, gCoh, maxForce), wCoh, some & (wCoh > 0.0f));
    }
    V3 target = lanes<F>(prevTarget);
    if (any(wanders)) {
        // Up made square to the heading; heading x up is then unit already (both unit and
        // square), so it is normalised only where up had to fall back.
        const V3 prev = target;
        target = select(wanders, behave::wanderTarget(prev, wanderR, lanes<F>(jitter)), prev);
        const V3 upNow = lanes<F>(up0);
        const V3 upRaw = upNow - heading * dot(upNow, heading);
        const F upLen = length(upRaw);
        V3 up = upRaw * (1.0f / upLen);
        V3 right = cross(heading, up);
        if (const M fallback = ~((upLen > 0.5f) & (upLen < kLaneInfinity)); any(fallback & wanders)) {
            for (int l = 0; l < kLanes; ++l) {
                if (!fallback[l])
                    continue;
                const glm::vec3 h = lane(heading, l), u = normalizeOr(lane(upRaw, l), kWorldUp);
                setLane(up, l, u);
                setLane(right, l, normalizeOr(glm::cross(h, u), rightOfForward(h)));
            }
        }
        const V3 aim = behave::wanderAim(heading, right, up, target, wanderR, wanderD);
        blend.add(behave::towards(V, behave::seekVelocity(aim, maxSpeed), gWan, maxForce), wWan, wanders);
    }
    const V3 force = blend.total(maxForce);

    // Integrate: integrateVehicle's flier step (VehicleModel.cpp), its velocity, banking and
    // square frame the same functions.
    V3 vel =
        behave::flierVelocity(V, force, splat<F>(m_clock.dt) / mass, maxSpeed, minOf(minSpeedType, maxSpeed), Fwd);
    const F speed = length(vel);
    vel = select(finite(vel), vel, V3{});
    V3 pos = P + vel * splat<F>(m_clock.dt);
    pos = select(finite(pos), pos, V3{});
    const V3 nextFwd = select(speed > kStoppedSpeed, vel / speed, Fwd);
    const V3 acceleration = (vel - V) / splat<F>(m_clock.dt);
    const V3 up = behave::bankedUp(lanes<F>(up0), nextFwd, acceleration, bankGain, bankBlend);
    behave::SquareFrame<F> frame = behave::squareFrame<F>(nextFwd, up);
    if (const M fallback = ~frame.square; any(fallback)) {
        for (int l = 0; l < kLanes; ++l) {
            if (!fallback[l])
                continue;
            const behave::SquareFrame<float> one =
                behave::squareFrameAlong(lane(nextFwd, l), lane(up, l), m_agents.side[boid[l]]);
            setLane(frame.side, l, one.side);
            setLane(frame.up, l, one.up);
        }
    }

    // Scatter, lane by lane (finishBoid's work): the ground, where a lane lies below its
    // floor or over a height field; whether the collide pass may skip it; the next state.
    const bool flat = m_set.terrain.heights.empty();
    for (int l = 0; l < kLanes; ++l) {
        const std::size_t i = boid[l];
        WanderState wanderNext = m_agents.wander[i];
        if (wanders[l])
            wanderNext.target = lane(target, l);
        glm::vec3 at = lane(pos, l), velocity = lane(vel, l);
        if (!flat || at.y < radius[l])
            groundBoid(i, at, velocity, lane(nextFwd, l));
        const BoidSense& in = sensed[l];
        const bool free = collideFree<F>(at, in.driftX, in.driftY, in.driftZ, in.keepOut, in.count, m_boidSlackM);
        storeBoid(i, free, at, velocity, lane(nextFwd, l), lane(frame.side, l), lane(frame.up, l), wanderNext);
    }
}

bool BoidKernel::canSteerEight()
{
#if defined(__x86_64__)
    static const bool avx2 = __builtin_cpu_supports("avx2");  // and the OS keeps its registers
    return avx2;
#else
    return false;
#endif
}

void BoidPass::steerBoids(const std::uint32_t* boid, const BoidSense* sensed, std::size_t count)
{
    std::size_t first = 0;
#if defined(__x86_64__)
    if (m_steerEight)
        for (; first + 8 <= count; first += 8)
            steerEightBoids(boid + first, sensed + first);
#endif
    for (; first + 4 <= count; first += 4)
        steerFourBoids(boid + first, sensed + first);
    for (; first < count; ++first)
        steerBoid(boid[first], sensed[first]);
}

void BoidPass::steerFourBoids(const std::uint32_t* boid, const BoidSense* sensed) { steerLanes<F4>(boid, sensed); }

void BoidPass::steerBoid(std::size_t i, const BoidSense& in)
{
    const auto boid = std::uint32_t(i);
    steerLanes<F1>(&boid, &in);
}

#if defined(__x86_64__)
// The same kernel, inlined here and so built with AVX2's eight-float registers (without
// fused multiply-add, which would change the bits); called only where the CPU has AVX2.
__attribute__((target("avx2"))) void BoidPass::steerEightBoids(const std::uint32_t* boid, const BoidSense* sensed)
{
    steerLanes<F8>(boid, sensed);
}
#endif

}  // namespace throng::sim
