// The boids kernel: one agent step (sense, steer, integrate) for a flier type whose
// behaviours are only separation, alignment, cohesion, pursuit, containment and wander
// (Reynolds 1987), fused. It computes what World::steer and integrateVehicle compute for
// such a type, in the same order, but in one pass over the neighbours: their positions,
// velocities and headings are read by index (no Neighbour copies, no request list), the
// three flocking sums accumulate together, and the vehicle step skips the re-normalising
// of a frame that is already orthonormal. Only the last bits differ from the general path
// (TestBoidKernel compares the two on the quality figures). A step has two halves,
// senseBoid and steerBoid (World.h); WorldFlockLanes.cpp does the second for four boids
// at once.
#include "simcore/world/World.h"

#include "simcore/world/Sense.h"
#include "simcore/world/NearestList.h"

#include "simcore/steering/detail/SteeringConstants.h"
#include "simcore/steering/detail/SteeringMath.h"
#include "simcore/base/Rng.h"
#include "simcore/base/Lanes.h"
#include "simcore/world/detail/StepConstants.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>
#include <cmath>

namespace throng::sim {

using namespace detail;
using namespace simd;

namespace {

// steerTowards (SteeringMath.h) for finite inputs: the velocity change, as a force that
// reaches it in the response time (gain = mass / response time), truncated to maxForce.
glm::vec3 towardsVelocity(glm::vec3 velocity, glm::vec3 desired, float gain, float maxForce)
{
    const glm::vec3 f = (desired - velocity) * gain;
    const float f2 = glm::dot(f, f);
    return f2 > maxForce * maxForce ? f * (maxForce / std::sqrt(f2)) : f;
}

bool fusable(const TypeSteering& s)
{
    using B = Behaviour;
    if (!s.vehicle.flying || !s.wander.flying || s.priority)
        return false;
    for (std::size_t b = 0; b < kBehaviourCount; ++b) {
        const auto behaviour = Behaviour(b);
        const bool allowed = behaviour == B::Separation || behaviour == B::Alignment || behaviour == B::Cohesion ||
                             behaviour == B::Pursuit || behaviour == B::Containment || behaviour == B::Wander;
        if (s.weight[b] > 0.0f && !allowed)
            return false;
    }
    return true;
}

}  // namespace

void World::buildBoidKernel(bool enabled, bool collideShortcut)
{
    // Brains change weights and speeds per agent, layers or priorities change whom an
    // agent perceives, and signals hold agents back: those worlds keep the general path.
    const bool plain = enabled && !m_brains && !m_types.makingWay && m_traffic.signal.empty();
    m_boidKernel.assign(m_types.steering.size(), 0);
    m_collideFree.assign(m_agents.pos.size(), 0);
    // How far a flier's next position may lie from where its old velocity takes it: the
    // force changes the velocity by at most maxForce / mass * dt, and lifting it back to
    // its min speed by as much again. The collide pass checks it holds for every agent.
    float accelMax = 0.0f;
    bool anyKernel = false;
    m_boidTypes.assign(m_types.steering.size(), BoidType{});
    for (std::size_t t = 0; t < m_types.steering.size(); ++t) {
        const TypeSteering& s = m_types.steering[t];
        m_boidKernel[t] = plain && fusable(s) ? 1 : 0;
        anyKernel = anyKernel || m_boidKernel[t];
        accelMax = std::max(accelMax, nonNegative(m_types.params[t].maxForce) / effectiveMass(m_types.params[t].mass));
        // As steerTowards, separate and integrateVehicle make each parameter usable.
        const float mass = effectiveMass(m_types.params[t].mass);
        BoidType& b = m_boidTypes[t];
        b.wContainment = s.weightIfOn(Behaviour::Containment);
        b.wSeparation = s.weightIfOn(Behaviour::Separation);
        b.wPursuit = s.weightIfOn(Behaviour::Pursuit);
        b.wAlignment = s.weightIfOn(Behaviour::Alignment);
        b.wCohesion = s.weightIfOn(Behaviour::Cohesion);
        b.wWander = s.weightIfOn(Behaviour::Wander);
        b.mass = mass;
        b.maxForce = nonNegative(m_types.params[t].maxForce);
        b.range = nonNegative(s.separation.rangeM);
        b.damping = mass / std::max(nonNegative(s.separation.dampingTimeS), kMinResponseTimeS);
        b.gainPursuit = responseGain(mass, s.pursuit.responseTimeS);
        b.gainAlignment = responseGain(mass, s.alignment.responseTimeS);
        b.gainCohesion = responseGain(mass, s.cohesion.responseTimeS);
        b.gainWander = responseGain(mass, s.wander.responseTimeS);
        b.predictionCapS = nonNegative(s.pursuit.maxPredictionS);
        b.slowingM = std::max(nonNegative(s.cohesion.slowingDistanceM), kTiny);
        b.jitterM = nonNegative(s.wander.jitterM);
        b.wanderRadiusM = nonNegative(s.wander.radiusM);
        b.wanderDistanceM = nonNegative(s.wander.distanceM);
        b.minSpeed = nonNegative(s.vehicle.minSpeed);
        b.bankGain = nonNegative(s.vehicle.bankingGainS2PerM);
        const float response = std::max(nonNegative(s.vehicle.bankingResponseS), kMinResponseTimeS);
        b.bankBlend = 1.0f - std::exp(-m_clock.dt / response);
    }
    const float slack = 2.0f * accelMax * m_clock.dt * m_clock.dt;
    m_boidSlackM = collideShortcut && anyKernel && std::isfinite(slack) ? slack : 0.0f;
}

void World::stepBoid(std::size_t i, NeighbourGrid::Sweep* sweep)
{
    BoidSense sense;
    senseBoid(i, sweep, sense);
    steerBoid(i, sense);
}

void World::senseBoid(std::size_t i, NeighbourGrid::Sweep* sweep, BoidSense& out)
{
    const float perception = m_types.params[m_agents.info[i].typeIndex].perception, perception2 = perception * perception;
    // Searching within last step's k nearest (lastNearestBound) visits far fewer cells and
    // candidates; when k are found in it they are exactly the k nearest within the
    // perception radius (everyone nearer lies inside the bound, and the grid offers all of
    // them), and when fewer are found the search runs again in full. So the result never
    // depends on the guess.
    const float guess2 = m_neighbourSweep ? lastNearestBound(m_agents, i, m_agents.pos[i], perception2) : perception2;
    BoidNearest best;
    searchBoid(i, sweep, guess2, best);
    if (!best.full() && guess2 < perception2)
        searchBoid(i, sweep, perception2, best);
    sumBoid(i, best, out);
}

void World::searchBoid(std::size_t i, NeighbourGrid::Sweep* sweep, float startBound, BoidNearest& best) const
{
    const TypeParams& t = m_types.params[m_agents.info[i].typeIndex];
    const glm::vec3 p = m_agents.pos[i], fwd = m_agents.fwd[i];
    const float radius = m_agents.radius[i];
    // Sense: the k nearest in the perception radius and view cone, nearest first, ties by
    // index (as gatherNeighbours, without the layers and priorities a boid world lacks).
    best.clear();
    float bound = startBound;
    const float c = t.cosHalfView;
    const auto self = std::uint32_t(i);
    auto consider = [&](std::uint32_t j, const glm::vec3& q) {
        const glm::vec3 d = q - p;
        const float d2 = glm::dot(d, d);
        if (d2 > bound || j == self)
            return;
        if (outsideViewCone(d, d2, fwd, c)) {
            const float contact = radius + m_agents.radius[j];
            if (d2 > contact * contact)
                return;
        }
        if (best.insert(nearestKey(d2, j)) && best.full())
            bound = best.worstDistance2();
    };
    if (sweep)
        m_grid.forEachNearestSweep(p, t.perception, [&] { return bound; }, consider, *sweep);
    else
        m_grid.forEachNearest(p, t.perception, [&] { return bound; }, consider);
}

void World::sumBoid(std::size_t i, const BoidNearest& best, BoidSense& out)
{
    const BoidType& b = m_boidTypes[m_agents.info[i].typeIndex];
    const glm::vec3 p = m_agents.pos[i], v = m_agents.vel[i];
    const float radius = m_agents.radius[i];
    constexpr std::size_t k = kMaxNeighbours;
    const std::size_t count = best.count;

    // Separation, and the sums for alignment and cohesion, in one pass over the neighbours.
    const float range = b.range, damping = b.damping, maxForce = b.maxForce;
    glm::vec3 push(0.0f), headings(0.0f), velocities(0.0f), centre(0.0f);
    std::uint32_t* nearIndex = &m_agents.nearIndex[i * k];
    // Where each neighbour's old velocity takes it, and how close it may come (for the
    // collide pass: see collideFree in finishBoid).
    float* keepOut = out.keepOut;
    // The weight's floor, reference / kMaxSeparationWeight, is the same for neighbours of
    // the same contact distance (all of them, where the flock has one radius).
    float limitContact = NAN, limit = 0.0f;
    for (std::size_t n = 0; n < count; ++n) {
        const auto j = best.index(n);
        nearIndex[n] = j;
        const glm::vec3 q = m_agents.pos[j], vj = m_agents.vel[j];
        headings += m_agents.fwd[j];
        velocities += vj;
        centre += q;
        const glm::vec3 drift = q + vj * m_clock.dt;
        out.driftX[n] = drift.x;
        out.driftY[n] = drift.y;
        out.driftZ[n] = drift.z;
        // Separation (FlockingBehaviours.cpp): the squared distance is the search key's.
        const float contact = radius + m_agents.radius[j], reach = contact + range;
        keepOut[n] = contact + m_boidSlackM;
        const float d2 = std::bit_cast<float>(std::uint32_t(best.keys[n] >> 32));
        if (!(d2 < reach * reach))
            continue;
        const float d = std::sqrt(d2);
        const glm::vec3 rel = p - q;
        const float reference = contact > kTiny ? contact : range;
        if (!(contact == limitContact)) {
            limitContact = contact;
            limit = reference / kMaxSeparationWeight;
        }
        const float w = reference / std::max(d, limit);
        // rel / d and (reach - d) / range, the same divisions in one instruction.
        const F4 quotient = F4{rel.x, rel.y, rel.z, reach - d} / F4{d, d, d, range};
        const float fade = range > kTiny ? std::min(1.0f, quotient[3]) : 1.0f;
        const glm::vec3 away = d > kTiny ? glm::vec3(quotient[0], quotient[1], quotient[2])
                                         : separationAxis(m_agents.info[i].id, m_agents.info[j].id);
        const float opening = glm::dot(v - vj, away);
        push += away * (fade * (maxForce * w - damping * opening));
    }
    m_agents.nearCount[i] = std::uint8_t(count);
    out.push = push;
    out.headings = headings;
    out.velocities = velocities;
    out.centre = centre;
    out.count = std::uint32_t(count);
}

// steerLanes (WorldFlockLanes.cpp) repeats this, operation for operation, for four or
// eight boids at once: a change here needs the same change there. TestNeighbourSweep fails
// when they differ in a bit (the grid-order path steers by eights or fours, the index-order
// one here).
void World::steerBoid(std::size_t i, const BoidSense& in)
{
    const std::uint16_t type = m_agents.info[i].typeIndex;
    const TypeSteering& s = m_types.steering[type];
    const BoidType& b = m_boidTypes[type];
    const glm::vec3 p = m_agents.pos[i], v = m_agents.vel[i], fwd = m_agents.fwd[i];
    const float radius = m_agents.radius[i], maxSpeed = nonNegative(m_agents.maxSpeed[i]);
    const std::size_t count = in.count;
    const glm::vec3 push = in.push, headings = in.headings, velocities = in.velocities, centre = in.centre;
    const float maxForce = b.maxForce;

    // Blended in World::steer's order (containment, separation, pursuit, alignment,
    // cohesion, wander), each behaviour as its function in simcore/steering computes it
    // for a finite state.
    const float speedNow = glm::length(v);
    const glm::vec3 heading = speedNow > kTiny ? v * (1.0f / speedNow) : fwd;
    auto towards = [&](glm::vec3 desired, float gain) { return towardsVelocity(v, desired, gain, maxForce); };
    glm::vec3 sum(0.0f);
    if (b.wContainment > 0.0f) {
        const float probe = s.containment.probeMinM + s.containment.probeLookaheadS * speedNow + radius;
        const glm::vec3 lo = p - m_set.bounds.min, hi = m_set.bounds.max - p;
        if (std::min({lo.x, lo.y, lo.z, hi.x, hi.y, hi.z}) < probe)
            sum += stayInside(steeringAgent(m_agents, m_types, i), m_set.bounds, s.containment) * b.wContainment;
    }
    if (b.wSeparation > 0.0f)
        sum += push * b.wSeparation;
    if (const std::int32_t leader = m_agents.leader[i]; leader >= 0 && b.wPursuit > 0.0f) {
        // Pursuit: seek where the quarry will be after distance / max speed.
        const auto j = std::size_t(leader);
        const glm::vec3 q = m_agents.pos[j];
        const float cap = b.predictionCapS;
        const float ahead = maxSpeed > kTiny ? std::min(glm::length(q - p) / maxSpeed, cap) : cap;
        const glm::vec3 aim = q + m_agents.vel[j] * ahead - p;
        sum += towards(normalizeOr(aim, glm::vec3(0.0f)) * maxSpeed, b.gainPursuit) * b.wPursuit;
    }
    if (count > 0 && b.wAlignment > 0.0f) {
        // Alignment: the neighbours' mean heading at the current speed, or their mean velocity.
        glm::vec3 desired(0.0f);
        bool any = true;
        if (s.alignment.matchSpeed) {
            desired = truncate(velocities / float(count), maxSpeed);
        } else {
            const glm::vec3 dir = normalizeOr(headings, glm::vec3(0.0f));
            any = dir != glm::vec3(0.0f);
            desired = dir * std::min(speedNow, maxSpeed);
        }
        if (any)
            sum += towards(desired, b.gainAlignment) * b.wAlignment;
    }
    if (count > 0 && b.wCohesion > 0.0f) {
        // Cohesion: arrive at the neighbours' centre, slowing within slowingDistanceM.
        const glm::vec3 offset = centre / float(count) - p;
        const float dist = glm::length(offset);
        glm::vec3 desired(0.0f);
        if (dist > kTiny) {
            desired = offset * (maxSpeed * std::min(1.0f, dist / b.slowingM) / dist);
        }
        sum += towards(desired, b.gainCohesion) * b.wCohesion;
    }
    WanderState wanderNext = m_agents.wander[i];
    if (b.wWander > 0.0f) {
        // Wander (Wander.cpp, in 3D): jitter the target on the unit sphere (kept unit from
        // step to step), then aim at it on the sphere ahead, in the agent's own frame.
        const std::uint64_t key = rngKey(m_seed, m_agents.info[i].id, m_clock.step);
        const glm::vec3 jitter = glm::vec3(rngRangeOf(key, kWanderX, -1.0f, 1.0f), rngRangeOf(key, kWanderY, -1.0f, 1.0f),
                                           rngRangeOf(key, kWanderZ, -1.0f, 1.0f)) *
                                 b.jitterM;
        const float wanderRadius = b.wanderRadiusM;
        const glm::vec3 prev = wanderNext.target;
        const glm::vec3 target = normalizeOr(prev * wanderRadius + jitter, prev);
        wanderNext.target = target;
        // Up made square to the heading; heading x up is then unit already (both unit and
        // square), so it is normalised only where up had to fall back.
        const glm::vec3 upRaw = m_agents.up[i] - heading * glm::dot(m_agents.up[i], heading);
        const float upLen = glm::length(upRaw);
        glm::vec3 up, right;
        if (upLen > 0.5f && upLen < kInfinity) {
            up = upRaw * (1.0f / upLen);
            right = glm::cross(heading, up);
        } else {
            up = normalizeOr(upRaw, kWorldUp);
            right = normalizeOr(glm::cross(heading, up), rightOfForward(heading));
        }
        const glm::vec3 aim = heading * b.wanderDistanceM +
                              (right * target.x + up * target.y + heading * target.z) * wanderRadius;
        sum += towards(normalizeOr(aim, glm::vec3(0.0f)) * maxSpeed, b.gainWander) * b.wWander;
    }
    const glm::vec3 force = truncate(sum, maxForce);

    // Integrate: integrateVehicle's flier step (VehicleModel.cpp) on a state that is
    // already finite and orthonormal.
    glm::vec3 vel = truncate(v + force * (m_clock.dt / b.mass), maxSpeed);
    const float minSpeed = std::min(b.minSpeed, maxSpeed);
    float speed = glm::length(vel);
    if (speed < minSpeed) {
        vel = (speed > kStoppedSpeed ? vel / speed : fwd) * minSpeed;
        speed = glm::length(vel);
    }
    vel = finiteOrZero(vel);
    glm::vec3 pos = finiteOrZero(p + vel * m_clock.dt);
    glm::vec3 nextFwd = fwd;
    if (speed > kStoppedSpeed)
        nextFwd = vel / speed;
    // Bank: up leans toward the lateral acceleration, smoothed.
    const glm::vec3 acceleration = (vel - v) / m_clock.dt;
    const glm::vec3 lateral = acceleration - nextFwd * glm::dot(acceleration, nextFwd);
    const glm::vec3 bankedUp = normalizeOr(kWorldUp + lateral * b.bankGain, kWorldUp);
    const glm::vec3 up0 = m_agents.up[i];
    const glm::vec3 up = normalizeOr(up0 + (bankedUp - up0) * b.bankBlend, kWorldUp);
    // As for wander's frame: side x forward is unit once side is (both unit and square).
    const glm::vec3 sideRaw = glm::cross(nextFwd, up);
    const float sideLen = glm::length(sideRaw);
    glm::vec3 side, nextUp;
    if (sideLen > 0.5f && sideLen < kInfinity) {
        side = sideRaw * (1.0f / sideLen);
        nextUp = glm::cross(side, nextFwd);
    } else {
        side = normalizeOr(sideRaw, m_agents.side[i]);
        nextUp = normalizeOr(glm::cross(side, nextFwd), kWorldUp);
    }

    finishBoid(i, in, pos, vel, nextFwd, side, nextUp, wanderNext);
}

void World::finishBoid(std::size_t i, const BoidSense& in, glm::vec3 pos, glm::vec3 vel, glm::vec3 nextFwd,
                       glm::vec3 side, glm::vec3 nextUp, WanderState wanderNext)
{
    groundBoid(i, pos, vel, nextFwd);
    // Collide-free: none of the k nearest can end the step within contact distance, as
    // long as each lies within m_boidSlackM of where its old velocity takes it (what the
    // collide pass checks before it trusts this flag); the margin covers the rounding of
    // these sums and of the pass's own. (steerLanes repeats this, a vector of neighbours
    // at a time.)
    const float margin = 1e-4f + 4e-6f * (std::fabs(pos.x) + std::fabs(pos.y) + std::fabs(pos.z));
    bool collideFree = m_boidSlackM > 0.0f;
    for (std::size_t n = 0; n < in.count; ++n) {
        const glm::vec3 d = pos - glm::vec3(in.driftX[n], in.driftY[n], in.driftZ[n]);
        const float keep = in.keepOut[n] + margin;
        collideFree = collideFree && glm::dot(d, d) > keep * keep;
    }
    storeBoid(i, collideFree, pos, vel, nextFwd, side, nextUp, wanderNext);
}

void World::groundBoid(std::size_t i, glm::vec3& pos, glm::vec3& vel, glm::vec3 nextFwd) const
{
    // Fliers may skim the ground but never pass through it (as in World::step).
    // (terrainHeight is 0 without a height field: no call for the common flat ground.)
    const float ground = m_set.terrain.heights.empty() ? 0.0f : m_set.groundHeight(pos.x, pos.z);
    if (const float floor = ground + m_agents.radius[i]; pos.y < floor) {
        pos.y = floor;
        vel.y = std::max(vel.y, 0.0f);
        const float stall = std::min(m_types.steering[m_agents.info[i].typeIndex].vehicle.minSpeed, m_agents.maxSpeed[i]);
        const float now = glm::length(vel);
        if (now < stall)
            vel = now > 1e-6f ? vel * (stall / now) : nextFwd * stall;
    }
}

void World::storeBoid(std::size_t i, bool collideFree, glm::vec3 pos, glm::vec3 vel, glm::vec3 nextFwd,
                      glm::vec3 side, glm::vec3 nextUp, const WanderState& wanderNext)
{
    m_collideFree[i] = collideFree ? kCollideFree : 0;
    m_agents.nextPos[i] = pos;
    m_agents.nextVel[i] = vel;
    m_agents.nextFwd[i] = nextFwd;
    m_agents.nextSide[i] = side;
    m_agents.nextUp[i] = nextUp;
    m_agents.nextWander[i] = wanderNext;
}

}  // namespace throng::sim
