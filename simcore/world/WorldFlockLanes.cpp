// The boids kernel's steering (WorldFlock.cpp, steerBoid) for four boids at once, one per
// lane of a 4-wide float vector (detail/Lanes.h). What each boid's state and type decide
// (whether it pursues, aligns or wanders, which side of a threshold it lies on) becomes a
// lane mask, and both sides are computed and one is kept; the rare cases that need more
// (containment near the bounds, a frame whose up had to fall back, the ground) are done
// for their lane alone. Operation for operation what steerBoid does, so the result is the
// same to the bit (TestNeighbourSweep and the flock's state hash show it). The square
// roots and divisions of four boids go together: a step of 100,000 birds takes about
// 12 % less time than with steerBoid for each (1 thread).
#include "simcore/world/World.h"

#include "simcore/steering/detail/SteeringConstants.h"
#include "simcore/steering/detail/SteeringMath.h"
#include "simcore/world/Rng.h"
#include "simcore/world/detail/Lanes.h"
#include "simcore/world/detail/StepConstants.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::sim {

using namespace detail;

namespace {

constexpr int kLanes = 4;

V4 lanes(const glm::vec3 (&v)[kLanes])
{
    return {F4{v[0].x, v[1].x, v[2].x, v[3].x}, F4{v[0].y, v[1].y, v[2].y, v[3].y},
            F4{v[0].z, v[1].z, v[2].z, v[3].z}};
}

glm::vec3 lane(const V4& v, int l) { return {v.x[l], v.y[l], v.z[l]}; }

void setLane(V4& v, int l, glm::vec3 x)
{
    v.x[l] = x.x;
    v.y[l] = x.y;
    v.z[l] = x.z;
}

// towardsVelocity (WorldFlock.cpp): (desired - velocity) * gain, truncated to maxForce.
V4 towards(V4 velocity, V4 desired, F4 gain, F4 maxForce)
{
    const V4 f = (desired - velocity) * gain;
    const F4 f2 = dot(f, f);
    return select(f2 > maxForce * maxForce, f * (maxForce / sqrtOf(f2)), f);
}

const V4 kUp4{f4(0.0f), f4(1.0f), f4(0.0f)};
const V4 kZero4{f4(0.0f), f4(0.0f), f4(0.0f)};

}  // namespace

void World::steerBoids(const std::uint32_t* boid, const BoidSense* sensed, std::size_t count)
{
    std::size_t first = 0;
    for (; first + kLanes <= count; first += kLanes)
        steerFourBoids(boid + first, sensed + first);
    for (; first < count; ++first)
        steerBoid(boid[first], sensed[first]);
}

void World::steerFourBoids(const std::uint32_t* boid, const BoidSense* sensed)
{
    // Gather: each lane's state, its type's parameters and its neighbours' sums, and the
    // parts steerBoid computes with branches of its own (containment, pursuit's quarry,
    // wander's random jitter).
    glm::vec3 p[kLanes], v[kLanes], fwd[kLanes], up0[kLanes], contain[kLanes], quarry[kLanes], quarryVel[kLanes],
        jitter[kLanes], prevTarget[kLanes], push[kLanes], headings[kLanes], velocities[kLanes], centre[kLanes];
    F4 maxSpeed, n;
    M4 contained, pursues, matchSpeed, wanders;
    const BoidType* types[kLanes];
    bool oneType = true;
    for (int l = 0; l < kLanes; ++l) {
        const std::size_t i = boid[l];
        const std::uint16_t type = m_info[i].typeIndex;
        const TypeSteering& s = m_steering[type];
        const BoidType& b = m_boidTypes[type];
        types[l] = &b;
        oneType = oneType && types[l] == types[0];
        const BoidSense& in = sensed[l];
        p[l] = m_pos[i];
        v[l] = m_vel[i];
        fwd[l] = m_fwd[i];
        up0[l] = m_up[i];
        maxSpeed[l] = nonNegative(m_maxSpeed[i]);
        push[l] = in.push;
        headings[l] = in.headings;
        velocities[l] = in.velocities;
        centre[l] = in.centre;
        n[l] = float(in.count);
        matchSpeed[l] = s.alignment.matchSpeed ? -1 : 0;
        // Containment, as steerBoid: only near the bounds, where the probe reaches them.
        contained[l] = 0;
        contain[l] = glm::vec3(0.0f);
        if (b.wContainment > 0.0f) {
            const float speedNow = glm::length(v[l]);
            const float probe = s.containment.probeMinM + s.containment.probeLookaheadS * speedNow + m_radius[i];
            const glm::vec3 lo = p[l] - m_bounds.min, hi = m_bounds.max - p[l];
            if (std::min({lo.x, lo.y, lo.z, hi.x, hi.y, hi.z}) < probe) {
                contained[l] = -1;
                contain[l] = stayInside(steeringAgent(i), m_bounds, s.containment) * b.wContainment;
            }
        }
        const std::int32_t leader = m_leader[i];
        pursues[l] = leader >= 0 && b.wPursuit > 0.0f ? -1 : 0;
        quarry[l] = pursues[l] ? m_pos[std::size_t(leader)] : glm::vec3(0.0f);
        quarryVel[l] = pursues[l] ? m_vel[std::size_t(leader)] : glm::vec3(0.0f);
        wanders[l] = b.wWander > 0.0f ? -1 : 0;
        prevTarget[l] = m_wander[i].target;
        jitter[l] = glm::vec3(0.0f);
        if (wanders[l]) {
            const std::uint64_t key = rngKey(m_seed, m_info[i].id, m_step);
            jitter[l] = glm::vec3(rngRangeOf(key, kWanderX, -1.0f, 1.0f), rngRangeOf(key, kWanderY, -1.0f, 1.0f),
                                  rngRangeOf(key, kWanderZ, -1.0f, 1.0f)) *
                        b.jitterM;
        }
    }
    // A type's parameter in each lane (one load when the four share their type, as a
    // flock mostly does).
    auto param = [&](float BoidType::*m) {
        return oneType ? f4(types[0]->*m) : F4{types[0]->*m, types[1]->*m, types[2]->*m, types[3]->*m};
    };
    const F4 wSep = param(&BoidType::wSeparation), wPur = param(&BoidType::wPursuit),
             wAli = param(&BoidType::wAlignment), wCoh = param(&BoidType::wCohesion),
             wWan = param(&BoidType::wWander), maxForce = param(&BoidType::maxForce), mass = param(&BoidType::mass),
             gPur = param(&BoidType::gainPursuit), gAli = param(&BoidType::gainAlignment),
             gCoh = param(&BoidType::gainCohesion), gWan = param(&BoidType::gainWander),
             cap = param(&BoidType::predictionCapS), slowing = param(&BoidType::slowingM),
             wanderR = param(&BoidType::wanderRadiusM), wanderD = param(&BoidType::wanderDistanceM),
             minSpeedType = param(&BoidType::minSpeed), bankGain = param(&BoidType::bankGain),
             bankBlend = param(&BoidType::bankBlend);
    const V4 P = lanes(p), V = lanes(v), Fwd = lanes(fwd);

    // Steer, in steerBoid's order: containment, separation, pursuit, alignment, cohesion,
    // wander.
    const F4 speedNow = length(V);
    const V4 heading = select(speedNow > kTiny, V * (1.0f / speedNow), Fwd);
    V4 sum = select(contained, lanes(contain), kZero4);
    sum = select(wSep > 0.0f, sum + lanes(push) * wSep, sum);
    {
        const V4 q = lanes(quarry);
        const F4 ahead = select(maxSpeed > kTiny, minOf(length(q - P) / maxSpeed, cap), cap);
        const V4 aim = q + lanes(quarryVel) * ahead - P;
        const V4 force = towards(V, normalizeOr(aim, kZero4, kTiny) * maxSpeed, gPur, maxForce) * wPur;
        sum = select(pursues, sum + force, sum);
    }
    const M4 some = n > 0.0f;
    {
        const V4 matched = truncate(lanes(velocities) / n, maxSpeed);
        const V4 dir = normalizeOr(lanes(headings), kZero4, kTiny);
        const M4 anyDir = (dir.x != 0.0f) | (dir.y != 0.0f) | (dir.z != 0.0f);
        const V4 desired = select(matchSpeed, matched, dir * minOf(speedNow, maxSpeed));
        const V4 force = towards(V, desired, gAli, maxForce) * wAli;
        sum = select(some & (wAli > 0.0f) & (matchSpeed | anyDir), sum + force, sum);
    }
    {
        const V4 offset = lanes(centre) / n - P;
        const F4 dist = length(offset);
        const V4 desired = select(dist > kTiny, offset * (maxSpeed * minOf(f4(1.0f), dist / slowing) / dist), kZero4);
        const V4 force = towards(V, desired, gCoh, maxForce) * wCoh;
        sum = select(some & (wCoh > 0.0f), sum + force, sum);
    }
    V4 target = lanes(prevTarget);
    if (any(wanders)) {
        const V4 prev = target;
        target = select(wanders, normalizeOr(prev * wanderR + lanes(jitter), prev, kTiny), prev);
        const V4 upNow = lanes(up0);
        const V4 upRaw = upNow - heading * dot(upNow, heading);
        const F4 upLen = length(upRaw);
        V4 up = upRaw * (1.0f / upLen);
        V4 right = cross(heading, up);
        if (const M4 fallback = ~((upLen > 0.5f) & (upLen < kLaneInfinity)); any(fallback & wanders)) {
            for (int l = 0; l < kLanes; ++l) {
                if (!fallback[l])
                    continue;
                const glm::vec3 h = lane(heading, l), u = normalizeOr(lane(upRaw, l), kWorldUp);
                setLane(up, l, u);
                setLane(right, l, normalizeOr(glm::cross(h, u), rightOfForward(h)));
            }
        }
        const V4 aim = heading * wanderD + (right * target.x + up * target.y + heading * target.z) * wanderR;
        const V4 force = towards(V, normalizeOr(aim, kZero4, kTiny) * maxSpeed, gWan, maxForce) * wWan;
        sum = select(wanders, sum + force, sum);
    }
    const V4 force = truncate(sum, maxForce);

    // Integrate: steerBoid's flier step.
    V4 vel = truncate(V + force * (f4(m_dt) / mass), maxSpeed);
    const F4 minSpeed = minOf(minSpeedType, maxSpeed);
    F4 speed = length(vel);
    {
        const M4 slow = speed < minSpeed;
        const V4 lifted = select(speed > kStoppedSpeed, vel / speed, Fwd) * minSpeed;
        vel = select(slow, lifted, vel);
        speed = select(slow, length(vel), speed);
    }
    vel = select(finite(vel), vel, kZero4);
    V4 pos = P + vel * f4(m_dt);
    pos = select(finite(pos), pos, kZero4);
    const V4 nextFwd = select(speed > kStoppedSpeed, vel / speed, Fwd);
    const V4 acceleration = (vel - V) / f4(m_dt);
    const V4 lateral = acceleration - nextFwd * dot(acceleration, nextFwd);
    const V4 bankedUp = normalizeOr(kUp4 + lateral * bankGain, kUp4, kTiny);
    const V4 upNow = lanes(up0);
    const V4 up = normalizeOr(upNow + (bankedUp - upNow) * bankBlend, kUp4, kTiny);
    const V4 sideRaw = cross(nextFwd, up);
    const F4 sideLen = length(sideRaw);
    V4 side = sideRaw * (1.0f / sideLen);
    V4 nextUp = cross(side, nextFwd);
    if (const M4 fallback = ~((sideLen > 0.5f) & (sideLen < kLaneInfinity)); any(fallback)) {
        for (int l = 0; l < kLanes; ++l) {
            if (!fallback[l])
                continue;
            const glm::vec3 s = normalizeOr(lane(sideRaw, l), m_side[boid[l]]);
            setLane(side, l, s);
            setLane(nextUp, l, normalizeOr(glm::cross(s, lane(nextFwd, l)), kWorldUp));
        }
    }

    // Scatter: the ground, the collide pass's flags and the next state, lane by lane.
    for (int l = 0; l < kLanes; ++l) {
        const std::size_t i = boid[l];
        WanderState wanderNext = m_wander[i];
        if (wanders[l])
            wanderNext.target = lane(target, l);
        finishBoid(i, sensed[l], lane(pos, l), lane(vel, l), lane(nextFwd, l), lane(side, l), lane(nextUp, l),
                   wanderNext);
    }
}

}  // namespace throng::sim
