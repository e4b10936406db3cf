// The boids kernel: one agent step (sense, steer, integrate) for a flier type whose
// behaviours are only separation, alignment, cohesion, pursuit, containment and wander
// (Reynolds 1987), fused. It computes what steer (Steer.h) and integrateVehicle compute for
// such a type, in the same order, but in one pass over the neighbours: their positions,
// velocities and headings are read by index (no Neighbour copies, no request list), the
// three flocking sums accumulate together, and the vehicle step skips the re-normalising
// of a frame that is already orthonormal. Each behaviour's formula is the general path's
// (steering/detail/BehaviourMath.h); only the order of the sums and the skipped
// re-normalising make the last bits differ (TestBoidKernel compares the two on the
// quality figures). A step has two halves, senseBoid here and steerBoid, which
// BoidKernelLanes.cpp writes once for one, four or eight boids at once.
#include "simcore/world/BoidKernel.h"

#include "simcore/world/Collide.h"
#include "simcore/world/Sense.h"
#include "simcore/world/NearestList.h"

#include "simcore/steering/detail/SteeringConstants.h"
#include "simcore/steering/detail/BehaviourMath.h"
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

bool fitsBoidKernel(const TypeSteering& s)
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

void BoidKernel::build(const AgentTypes& types, float dt, std::size_t agents, bool enabled, bool plain,
                       bool collideShortcut, bool steerEight)
{
    // Brains change weights and speeds per agent, layers or priorities change whom an
    // agent perceives, and signals hold agents back: those worlds keep the general path.
    plain = plain && enabled;
    m_steerEight = steerEight && canSteerEight();
    m_runs.assign(types.steering.size(), 0);
    m_collideFree.assign(agents, 0);
    // How far a flier's next position may lie from where its old velocity takes it: the
    // force changes the velocity by at most maxForce / mass * dt, and lifting it back to
    // its min speed by as much again. The collide pass checks it holds for every agent.
    float accelMax = 0.0f;
    bool anyKernel = false;
    m_boidTypes.assign(types.steering.size(), BoidType{});
    for (std::size_t t = 0; t < types.steering.size(); ++t) {
        const TypeSteering& s = types.steering[t];
        // A walker that keeps a time gap (Headway.h) takes the general path, which applies it.
        m_runs[t] = plain && fitsBoidKernel(s) && types.timeGapS[t] <= 0.0f ? 1 : 0;
        anyKernel = anyKernel || m_runs[t];
        accelMax = std::max(accelMax, nonNegative(types.params[t].maxForce) / effectiveMass(types.params[t].mass));
        // As steerTowards, separate and integrateVehicle make each parameter usable.
        const float mass = effectiveMass(types.params[t].mass);
        BoidType& b = m_boidTypes[t];
        b.wContainment = s.weightIfOn(Behaviour::Containment);
        b.wSeparation = s.weightIfOn(Behaviour::Separation);
        b.wPursuit = s.weightIfOn(Behaviour::Pursuit);
        b.wAlignment = s.weightIfOn(Behaviour::Alignment);
        b.wCohesion = s.weightIfOn(Behaviour::Cohesion);
        b.wWander = s.weightIfOn(Behaviour::Wander);
        b.mass = mass;
        b.maxForce = nonNegative(types.params[t].maxForce);
        const behave::SeparationGains separation = behave::separationGains(s.separation, mass);
        b.range = separation.range;
        b.damping = separation.damping;
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
        b.bankBlend = behave::bankingBlend(s.vehicle.bankingResponseS, dt);
    }
    const float slack = 2.0f * accelMax * dt * dt;
    m_slackM = collideShortcut && anyKernel && std::isfinite(slack) ? slack : 0.0f;
}

BoidPass::BoidPass(BoidKernel& kernel, const StepView& v, AgentColumns& agents)
    : m_types(v.types), m_set(v.set), m_clock(v.clock), m_grid(v.grid), m_ties(v.ties), m_agents(agents),
      m_boidTypes(kernel.m_boidTypes), m_collideFree(kernel.m_collideFree.data()), m_boidSlackM(kernel.m_slackM),
      m_steerEight(kernel.m_steerEight), m_neighbourSweep(v.warmSearch), m_seed(v.seed)
{
}

void BoidPass::stepBoid(std::size_t i, NeighbourGrid::Sweep* sweep)
{
    BoidSense sense;
    senseBoid(i, sweep, sense);
    steerBoid(i, sense);
}

void BoidPass::senseBoid(std::size_t i, NeighbourGrid::Sweep* sweep, BoidSense& out)
{
    const float perception = m_types.params[m_agents.info[i].typeIndex].perception,
                perception2 = perception * perception;
    // Searching within last step's k nearest (lastNearestBound) visits far fewer cells and
    // candidates; when k are found in it they are exactly the k nearest within the
    // perception radius (everyone nearer lies inside the bound, and the grid offers all of
    // them), and when fewer are found the search runs again in full. So the result never
    // depends on the guess.
    const float guess2 = m_neighbourSweep ? lastNearestBound(m_agents, i, m_agents.pos[i], perception2) : perception2;
    BoidNearest best;
    searchBoid(i, sweep, guess2, best, false);
    finishSearch(i, sweep, guess2, perception2, best);
    sumBoid(i, best, out);
}

void BoidPass::finishSearch(std::size_t i, NeighbourGrid::Sweep* sweep, float guess2, float perception2,
                            BoidNearest& best) const
{
    finishNearest(best, guess2, perception2, !m_ties.byIndex(),
                  [&](float startBound, bool byRank) { searchBoid(i, sweep, startBound, best, byRank); });
}

void BoidPass::searchBoid(std::size_t i, NeighbourGrid::Sweep* sweep, float startBound, BoidNearest& best,
                          bool byRank) const
{
    const TypeParams& t = m_types.params[m_agents.info[i].typeIndex];
    const glm::vec3 p = m_agents.pos[i], fwd = m_agents.fwd[i];
    const float radius = m_agents.radius[i];
    // Sense: the k nearest in the perception radius and view cone, nearest first, ties by
    // id (as gatherNeighbours, without the layers and priorities a boid world lacks).
    best.clear();
    best.byRank = byRank;
    const bool watch = !m_ties.byIndex();
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
        const std::uint64_t key = nearestKey(d2, byRank ? m_ties.rank(j) : j);
        if ((watch ? best.insertWatchingTies(key) : best.insert(key)) && best.full())
            bound = best.worstDistance2();
    };
    if (sweep)
        m_grid.forEachNearestSweep(p, t.perception, [&] { return bound; }, consider, *sweep);
    else
        m_grid.forEachNearest(p, t.perception, [&] { return bound; }, consider);
}

void BoidPass::sumBoid(std::size_t i, const BoidNearest& best, BoidSense& out)
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
    // collide pass: see collideFree in BoidKernelLanes.cpp).
    float* keepOut = out.keepOut;
    behave::SeparationFloor floor;
    for (std::size_t n = 0; n < count; ++n) {
        const auto j = best.index(n, m_ties);
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
        push += behave::separationPush(p - q, d, contact, range, maxForce, damping, v - vj, [&] {
            return separationAxis(m_agents.info[i].id, m_agents.info[j].id);
        }, floor);
    }
    m_agents.nearCount[i] = std::uint8_t(count);
    out.push = push;
    out.headings = headings;
    out.velocities = velocities;
    out.centre = centre;
    out.count = std::uint32_t(count);
}

void BoidPass::groundBoid(std::size_t i, glm::vec3& pos, glm::vec3& vel, glm::vec3 nextFwd) const
{
    // Fliers may skim the ground but never pass through it (as in the general path, MovePhase.cpp).
    // (terrainHeight is 0 without a height field: no call for the common flat ground.)
    const float ground = m_set.terrain.heights.empty() ? 0.0f : m_set.groundHeight(pos.x, pos.z);
    if (const float floor = ground + m_agents.radius[i]; pos.y < floor) {
        pos.y = floor;
        vel.y = std::max(vel.y, 0.0f);
        const float stall =
            std::min(m_types.steering[m_agents.info[i].typeIndex].vehicle.minSpeed, m_agents.maxSpeed[i]);
        const float now = glm::length(vel);
        if (now < stall)
            vel = now > 1e-6f ? vel * (stall / now) : nextFwd * stall;
    }
}

void BoidPass::storeBoid(std::size_t i, bool collideFree, glm::vec3 pos, glm::vec3 vel, glm::vec3 nextFwd,
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
