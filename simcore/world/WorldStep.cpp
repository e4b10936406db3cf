// World::step: one fixed time step as a column of phases (DetourCrowd's dtCrowd::update
// reads the same way). Every agent reads the previous state and writes only its own next
// state (RVO2's doStep computes all new velocities before committing any), so the result
// is the same for any thread count.
#include "simcore/world/World.h"

#include "simcore/world/Rng.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace throng::sim {

namespace {

enum StepStream : std::uint64_t { kWanderX = 101, kWanderY, kWanderZ };

glm::vec2 xz(glm::vec3 v) { return {v.x, v.z}; }

float cross(glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; }

// True when segment p0-p1 properly crosses segment a-b.
bool segmentsCross(glm::vec2 p0, glm::vec2 p1, glm::vec2 a, glm::vec2 b)
{
    const float d1 = cross(b - a, p0 - a), d2 = cross(b - a, p1 - a);
    const float d3 = cross(p1 - p0, a - p0), d4 = cross(p1 - p0, b - p0);
    return ((d1 > 0.0f && d2 < 0.0f) || (d1 < 0.0f && d2 > 0.0f)) &&
           ((d3 > 0.0f && d4 < 0.0f) || (d3 < 0.0f && d4 > 0.0f));
}

glm::vec2 closestOnSegment(glm::vec2 p, glm::vec2 a, glm::vec2 b)
{
    const glm::vec2 ab = b - a;
    const float len2 = glm::dot(ab, ab);
    const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
    return a + ab * t;
}

bool isFinite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Most walls and obstacles one agent considers in a step.
constexpr std::size_t kMaxNearWalls = 16, kMaxNearObstacles = 8;
// How near its own spot in the goal area an agent stops for good.
constexpr float kSpotToleranceM = 0.1f;
// How quickly an agent with nowhere to go brakes to a stand, s.
constexpr float kStandStillResponseS = 0.5f;
// Inside its goal, an agent this near (body to body) a stopped agent settles too.
constexpr float kSettleGapM = 0.05f;
// Overlap tolerance: touching within 1 cm is contact, not overlap.
constexpr float kOverlapToleranceM = 0.01f;

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
        if (std::fabs(side) < 0.2f)  // nearly head-on: go round the nearer end
            side = glm::distance(c, a) < glm::distance(c, b) ? -1.0f : 1.0f;
        tangent = side < 0.0f ? -t : t;
        nearest = d;
    }
    return glm::vec3(tangent.x, 0.0f, tangent.y) * self.maxForce;
}

}  // namespace

SteeringAgent World::steeringAgent(std::size_t i) const
{
    const TypeParams& t = m_types[m_info[i].typeIndex];
    SteeringAgent a;
    a.position = m_pos[i];
    a.velocity = m_vel[i];
    a.forward = m_fwd[i];
    a.side = m_side[i];
    a.up = m_up[i];
    a.radius = m_radius[i];
    a.maxSpeed = m_maxSpeed[i];
    a.maxForce = t.maxForce;
    a.mass = t.mass;
    a.id = m_info[i].id;
    return a;
}

// Sense: the nearest kMaxNeighbours agents within the perception radius and view cone
// (Reynolds 1987), nearest first, ties by id, so the choice never depends on grid order.
std::size_t World::gatherNeighbours(std::size_t i, Neighbour* out, std::uint32_t* indices) const
{
    const TypeParams& t = m_types[m_info[i].typeIndex];
    const glm::vec3 p = m_pos[i], fwd = m_fwd[i];
    const float r2 = t.perception * t.perception;
    struct Candidate {
        float d2;
        AgentId id;
        std::uint32_t index;
        bool operator<(const Candidate& o) const { return d2 != o.d2 ? d2 < o.d2 : id < o.id; }
    };
    std::array<Candidate, kMaxNeighbours> best;
    std::size_t count = 0;
    auto consider = [&](std::uint32_t j, const glm::vec3& q) {
        if (j == i)
            return;
        const glm::vec3 d = q - p;
        const float d2 = glm::dot(d, d);
        if (d2 > r2)
            return;
        // Outside the view cone (but a touching neighbour is always felt). The test
        // dot(d, fwd) < c |d| is done on squares to avoid a square root per candidate.
        if (t.cosHalfView > -1.0f) {
            const float c = t.cosHalfView, dot = glm::dot(d, fwd);
            const bool outside = c >= 0.0f ? (dot < 0.0f || dot * dot < c * c * d2) : (dot < 0.0f && dot * dot > c * c * d2);
            const float contact = m_radius[i] + m_radius[j];
            if (outside && d2 > contact * contact)
                return;
        }
        const Candidate c{d2, m_info[j].id, j};
        if (count == kMaxNeighbours && !(c < best[count - 1]))
            return;
        std::size_t k = count < kMaxNeighbours ? count++ : count - 1;
        for (; k > 0 && c < best[k - 1]; --k)
            best[k] = best[k - 1];
        best[k] = c;
    };
    if (m_grid.sortedByHeight())
        m_grid.forEachNear3D(p, t.perception, consider);
    else
        m_grid.forEachNear(xz(p), t.perception, consider);
    for (std::size_t k = 0; k < count; ++k) {
        const std::uint32_t j = best[k].index;
        out[k] = {m_pos[j], m_vel[j], m_fwd[j], m_radius[j], m_info[j].id};
        indices[k] = j;
    }
    return count;
}

glm::vec3 World::flowDirection(glm::vec3 p) const
{
    // The nearest stroke segment whose band holds p gives the direction.
    const glm::vec2 q = xz(p);
    float bestD = INFINITY;
    glm::vec2 dir(0.0f);
    for (const FlowSegment& s : m_flow) {
        const float d = glm::distance(q, closestOnSegment(q, s.a, s.b));
        if (d <= s.halfWidth && d < bestD && s.a != s.b) {
            bestD = d;
            dir = glm::normalize(s.b - s.a);
        }
    }
    return {dir.x, 0.0f, dir.y};
}

// Steer: every behaviour the type runs, in priority order, combined by blending or by
// prioritised allocation. Pure in the previous state; the new wander state goes out.
glm::vec3 World::steer(std::size_t i, const SteeringAgent& self, std::span<const Neighbour> near,
                       WanderState& wanderOut) const
{
    const TypeSteering& s = m_steering[m_info[i].typeIndex];
    using B = Behaviour;
    SteeringRequestList requests;
    auto request = [&](B b, auto&& force) {
        if (s.on(b))
            requests.add(force(), s.w(b));
    };
    const glm::vec3 p = self.position;
    const bool hasGoal = m_goal[i] >= 0;
    const glm::vec3 goal = hasGoal ? glm::vec3(m_goalSpot[i].x, p.y, m_goalSpot[i].y) : p + self.forward;
    const std::int32_t leaderIndex = m_leader[i];
    Neighbour leader;
    if (leaderIndex >= 0) {
        const auto j = std::size_t(leaderIndex);
        leader = {m_pos[j], m_vel[j], m_fwd[j], m_radius[j], m_info[j].id};
    }

    if (s.on(B::Containment)) {
        // Only agents whose probes can reach the bounds ask; the rest are far inside.
        const float probe = s.containment.probeMinM + s.containment.probeLookaheadS * self.speed() + self.radius;
        const glm::vec3 lo = p - m_bounds.min, hi = m_bounds.max - p;
        const float nearest = s.vehicle.flying ? std::min({lo.x, lo.y, lo.z, hi.x, hi.y, hi.z})
                                               : std::min({lo.x, lo.z, hi.x, hi.z});  // walkers ignore height
        if (nearest < probe)
            requests.add(stayInside(self, m_bounds, s.containment), s.w(B::Containment));
    }
    if (s.on(B::WallFollowing)) {
        std::array<WallSegment, kMaxNearWalls> walls;
        std::size_t n = 0;
        const float reach = s.walls.feelerMinM + s.walls.feelerLookaheadS * self.speed() + s.walls.standoffM +
                            self.radius;
        m_walls.forEachNear(xz(p), reach, [&](std::uint32_t k) {
            if (n < walls.size()) {
                const Segment& seg = m_walls.segment(k);
                walls[n++] = {glm::vec3(seg.a.x, 0.0f, seg.a.y), glm::vec3(seg.b.x, 0.0f, seg.b.y)};
            }
        });
        if (n > 0) {
            request(B::WallFollowing, [&] { return avoidWalls(self, {walls.data(), n}, s.walls); });
            request(B::WallFollowing, [&] { return slideAlongWall(self, {walls.data(), n}, goal, s.walls); });
        }
    }
    if (s.on(B::ObstacleAvoidance) && (!m_circles.empty() || !m_boxes.empty())) {
        std::array<CircleObstacle, kMaxNearObstacles> circles;
        std::array<BoxObstacle, kMaxNearObstacles> boxes;
        std::size_t nc = 0, nb = 0;
        const float reach = s.obstacles.minLengthM + s.obstacles.lookaheadS * self.speed() + self.radius +
                            s.obstacles.marginM;
        m_obstacleGrid.forEachNear(xz(p), reach, [&](std::uint32_t k) {
            if (k < m_circles.size()) {
                if (nc < circles.size())
                    circles[nc++] = m_circles[k];
            } else if (nb < boxes.size()) {
                boxes[nb++] = m_boxes[k - m_circles.size()];
            }
        });
        request(B::ObstacleAvoidance,
                [&] { return avoidObstacles(self, {circles.data(), nc}, {boxes.data(), nb}, goal, s.obstacles); });
    }
    request(B::Separation, [&] { return separate(self, near, s.separation); });
    request(B::UnalignedCollisionAvoidance, [&] { return avoidUnalignedCollisions(self, near, s.unaligned); });
    if (leaderIndex >= 0) {
        request(B::Evasion, [&] { return evade(self, leader, s.evasion); });
        request(B::Flee, [&] { return flee(self, leader.position, s.flee); });
        request(B::LeaderFollowing, [&] { return followLeader(self, leader, s.leader); });
        request(B::OffsetPursuit, [&] { return pursueOffset(self, leader, s.offsetPursuit); });
        request(B::Pursuit, [&] { return pursue(self, leader, s.pursuit); });
    } else if (hasGoal) {
        request(B::Flee, [&] { return flee(self, goal, s.flee); });
    }
    if (m_path[i] >= 0) {
        const auto k = std::size_t(m_path[i]);
        const SteeringPath path{m_pathPoints[k], m_paths[k].radiusM, m_paths[k].closed};
        request(B::PathFollowing, [&] { return followPath(self, path, s.path); });
    }
    if (!m_flow.empty())
        request(B::FlowFieldFollowing, [&] { return followFlow(self, flowDirection(flowSamplePoint(self, s.flow)), s.flow); });
    if (hasGoal && m_path[i] < 0) {
        request(B::Arrival, [&] { return arrive(self, goal, s.arrival); });
        request(B::Seek, [&] { return seek(self, goal, s.seek); });
    }
    request(B::Alignment, [&] { return align(self, near, s.alignment); });
    request(B::Cohesion, [&] { return cohere(self, near, s.cohesion); });
    wanderOut = m_wander[i];
    if (s.on(B::Wander)) {
        const AgentId id = m_info[i].id;
        const glm::vec3 random(rngRange(m_seed, id, m_step, kWanderX, -1.0f, 1.0f),
                               rngRange(m_seed, id, m_step, kWanderY, -1.0f, 1.0f),
                               rngRange(m_seed, id, m_step, kWanderZ, -1.0f, 1.0f));
        const WanderResult w = wander(self, m_wander[i], random, s.wander);
        wanderOut = w.state;
        requests.add(w.force, s.w(B::Wander));
    }
    // A walker or vehicle with nowhere to go comes to rest instead of coasting on what
    // separation or a collision gave it (the lowest priority: anything else comes first).
    const bool goesSomewhere = hasGoal || m_path[i] >= 0 || leaderIndex >= 0 || s.on(B::Wander) ||
                               (!m_flow.empty() && s.on(B::FlowFieldFollowing));
    if (!goesSomewhere && !s.vehicle.flying)
        requests.add(-self.velocity * (self.mass / kStandStillResponseS), 1.0f);
    return s.priority ? allocateByPriority(requests, self.maxForce) : blendWeighted(requests, self.maxForce);
}

void World::step()
{
    const std::size_t n = m_pos.size();

    // Grid: index agents by cell for neighbour queries (the last step's count left it
    // current for these positions).
    if (!m_gridCurrent)
        m_grid.rebuild(m_pos, m_hasFliers);
    m_gridCurrent = false;

#pragma omp parallel for schedule(static, 256) num_threads(m_threads)
    for (std::size_t i = 0; i < n; ++i) {
        const TypeSteering& s = m_steering[m_info[i].typeIndex];
        if (m_stopped[i]) {
            // An agent that has arrived stays put: no dodging, no yo-yo.
            m_nextPos[i] = m_pos[i];
            m_nextVel[i] = glm::vec3(0.0f);
            m_nextFwd[i] = m_fwd[i];
            m_nextSide[i] = m_side[i];
            m_nextUp[i] = m_up[i];
            m_nextWander[i] = m_wander[i];
            m_nearCount[i] = 0;
            continue;
        }
        const SteeringAgent self = steeringAgent(i);
        // Sense: nearby agents in the perception cone.
        std::array<Neighbour, kMaxNeighbours> near;
        const std::size_t count = gatherNeighbours(i, near.data(), &m_nearIndex[i * kMaxNeighbours]);
        m_nearCount[i] = std::uint8_t(count);
        // Steer: the type's behaviours, combined.
        WanderState wanderNext;
        const glm::vec3 force = steer(i, self, {near.data(), count}, wanderNext);
        // Integrate: the simple vehicle model (Reynolds 1999).
        SteeringAgent next = integrateVehicle(self, force, m_dt, s.vehicle);
        // Constrain: no agent ends a step inside a wall or obstacle; walkers stand on the ground.
        if (!s.vehicle.flying) {
            constrain(i, self.position, next.position);
            next.position.y = groundHeight(next.position.x, next.position.z);
            next.velocity = (next.position - self.position) / m_dt;
            next.velocity.y = 0.0f;
        } else if (const float floor = groundHeight(next.position.x, next.position.z) + self.radius;
                   next.position.y < floor) {
            // Fliers may skim the ground but never pass through it; the dive turns into
            // level flight at no less than the stall speed.
            next.position.y = floor;
            next.velocity.y = std::max(next.velocity.y, 0.0f);
            const float stall = std::min(s.vehicle.minSpeed, m_maxSpeed[i]), v = glm::length(next.velocity);
            if (v < stall)
                next.velocity = v > 1e-6f ? next.velocity * (stall / v) : next.forward * stall;
        }
        m_nextPos[i] = next.position;
        m_nextVel[i] = next.velocity;
        m_nextFwd[i] = next.forward;
        m_nextSide[i] = next.side;
        m_nextUp[i] = next.up;
        m_nextWander[i] = wanderNext;
    }

    // Collide: bodies still overlapping after steering move apart, each by its share of
    // the overlap (DetourCrowd's collision handling, done Jacobi-style: every agent reads
    // the others' proposed positions and moves only itself). Walls stay hard.
#pragma omp parallel for schedule(static, 256) num_threads(m_threads)
    for (std::size_t i = 0; i < n; ++i) {
        glm::vec3 p = m_nextPos[i] + separateBodies(i);
        const bool flying = m_steering[m_info[i].typeIndex].vehicle.flying;
        // Nobody moves faster than its max speed, nudges included, so what the viewer
        // sees and the gait it is animated with always agree.
        const glm::vec3 move = p - m_pos[i];
        const float maxMove = m_maxSpeed[i] * m_dt, moved = glm::length(move);
        if (moved > maxMove && moved > 0.0f)
            p = m_pos[i] + move * (maxMove / moved);
        if (!flying) {
            constrain(i, m_pos[i], p);
            p.y = m_nextPos[i].y;
        }
        m_resolvedPos[i] = p;
    }
#pragma omp parallel for schedule(static, 256) num_threads(m_threads)
    for (std::size_t i = 0; i < n; ++i) {
        if (m_stopped[i])
            continue;
        if (!m_steering[m_info[i].typeIndex].vehicle.flying) {
            m_nextVel[i] = (m_resolvedPos[i] - m_pos[i]) / m_dt;
            m_nextVel[i].y = 0.0f;
        }
        m_nextPos[i] = m_resolvedPos[i];
    }

    // Commit: swap in the new state, animate, and note arrivals.
    m_stoppedBefore = m_stopped;
    std::uint64_t crossings = 0;
#pragma omp parallel for schedule(static, 256) num_threads(m_threads) reduction(+ : crossings)
    for (std::size_t i = 0; i < n; ++i)
        commit(i, crossings);
    m_counters.wallPenetrations += crossings;
    ++m_step;
    countStep();
}

glm::vec3 World::separateBodies(std::size_t i) const
{
    if (m_stopped[i])
        return glm::vec3(0.0f);
    const bool flying = m_steering[m_info[i].typeIndex].vehicle.flying;
    glm::vec3 push(0.0f);
    const std::uint32_t* near = &m_nearIndex[i * kMaxNeighbours];
    for (std::size_t k = 0; k < m_nearCount[i]; ++k) {
        const std::uint32_t j = near[k];
        glm::vec3 d = m_nextPos[i] - m_nextPos[j];
        if (!flying)
            d.y = 0.0f;
        const float contact = m_radius[i] + m_radius[j];
        const float d2 = glm::dot(d, d);
        if (d2 >= contact * contact)
            continue;
        const float dist = std::sqrt(d2);
        // Coincident bodies part along a direction both derive from their ids, in
        // opposite senses, so the pair never moves together.
        glm::vec3 dir;
        if (dist > 1e-6f) {
            dir = d / dist;
        } else {
            const AgentId lo = std::min(m_info[i].id, m_info[j].id), hi = std::max(m_info[i].id, m_info[j].id);
            const float a = float(rngUniform(lo, hi, 0, 77)) * 6.2831853f;
            dir = glm::vec3(std::cos(a), 0.0f, std::sin(a)) * (m_info[i].id == lo ? 1.0f : -1.0f);
        }
        // A standing neighbour does not give way, so this agent takes the whole overlap.
        const float share = m_stopped[j] ? 1.0f : 0.5f;
        push += dir * ((contact - dist) * share);
    }
    // Cap the correction so a squeezed agent is nudged, never thrown: at most half its
    // body and half what it could walk in the step.
    const float cap = std::min(0.5f * m_radius[i], 0.5f * m_maxSpeed[i] * m_dt);
    const float len = glm::length(push);
    return len > cap ? push * (cap / len) : push;
}

void World::commit(std::size_t i, std::uint64_t& wallCrossings)
{
    const glm::vec2 from = xz(m_pos[i]), to = xz(m_nextPos[i]);
    // Fliers pass over walls; only walkers and vehicles can penetrate one.
    if (!m_steering[m_info[i].typeIndex].vehicle.flying)
        m_walls.forEachNear((from + to) * 0.5f, 0.5f * glm::length(to - from) + 0.01f, [&](std::uint32_t k) {
        const Segment& s = m_walls.segment(k);
        if (segmentsCross(from, to, s.a, s.b))
            ++wallCrossings;
    });
    // Animate: the gait advances by distance over stride length, so feet don't slide.
    m_phase[i] = std::fmod(m_phase[i] + glm::length(to - from) / m_stride[i], 1.0f);
    m_pos[i] = m_nextPos[i];
    m_vel[i] = m_nextVel[i];
    m_fwd[i] = m_nextFwd[i];
    m_side[i] = m_nextSide[i];
    m_up[i] = m_nextUp[i];
    m_wander[i] = m_nextWander[i];
    if (m_stopped[i])
        return;
    // Arrived (the stats' figure) = entered the goal's area, or joined the pile of those
    // who stopped at it; counted once. Stopped = frozen for good: at the end of an open
    // path, on its own spot in the goal, or against someone with the same goal who already
    // stopped between it and its spot, so a shared goal fills like sand from the inside
    // out and the last comers settle at the edge of the pile.
    bool stop = false;
    auto arrive = [&] {
        if (!m_arrived[i]) {
            m_arrived[i] = 1;
            m_arrivalTime[i] = float(double(m_step + 1) * double(m_dt));
        }
    };
    if (m_path[i] >= 0) {
        const Path& path = m_paths[std::size_t(m_path[i])];
        const float tolerance = std::max(0.1f, 0.25f * path.radiusM);
        stop = !path.closed && glm::distance(to, path.points.back()) < tolerance;
        if (stop)
            arrive();
    } else if (m_goal[i] >= 0) {
        const Goal& g = m_goals[std::size_t(m_goal[i])];
        if (glm::distance(to, g.position) < g.radiusM) {
            arrive();
            stop = glm::distance(to, m_goalSpot[i]) < kSpotToleranceM;
        }
        // Against the pile: a stopped agent with the same goal, between this one and its
        // spot. Flags as they were when this phase began, and j's next position (which a
        // stopped agent shares with its current one): nothing another thread writes in
        // this phase is read here.
        const std::uint32_t* near = &m_nearIndex[i * kMaxNeighbours];
        for (std::size_t k = 0; !stop && k < m_nearCount[i]; ++k) {
            const std::uint32_t j = near[k];
            const float contact = m_radius[i] + m_radius[j] + kSettleGapM;
            const glm::vec2 q = xz(m_nextPos[j]);
            stop = m_stoppedBefore[j] && m_goal[j] == m_goal[i] && glm::distance(to, q) < contact &&
                   glm::dot(q - to, m_goalSpot[i] - to) > 0.0f;
        }
        if (stop)
            arrive();
    }
    if (stop) {
        m_stopped[i] = 1;
        m_vel[i] = glm::vec3(0.0f);
    }
}

void World::constrain(std::size_t i, glm::vec3 from, glm::vec3& to) const
{
    const float r = m_radius[i];
    glm::vec2 p = xz(to);
    const glm::vec2 p0 = xz(from);
    // A move that would cross a wall stops where it started (no tunnelling at any speed).
    bool crossed = false;
    m_walls.forEachNear((p0 + p) * 0.5f, 0.5f * glm::length(p - p0) + r + 0.01f, [&](std::uint32_t k) {
        const Segment& s = m_walls.segment(k);
        crossed = crossed || segmentsCross(p0, p, s.a, s.b);
    });
    if (crossed)
        p = p0;
    // Then push the body out of walls and obstacles it overlaps; two passes settle corners.
    for (int pass = 0; pass < 2; ++pass) {
        m_walls.forEachNear(p, r, [&](std::uint32_t k) {
            const Segment& s = m_walls.segment(k);
            const glm::vec2 c = closestOnSegment(p, s.a, s.b);
            const glm::vec2 d = p - c;
            const float dist2 = glm::dot(d, d);
            if (dist2 >= r * r)
                return;
            glm::vec2 n;
            if (dist2 > 1e-12f) {
                n = d / std::sqrt(dist2);
            } else {
                const glm::vec2 along = s.b - s.a;
                n = glm::dot(along, along) > 0.0f ? glm::normalize(glm::vec2(-along.y, along.x)) : glm::vec2(1, 0);
                if (glm::dot(n, p0 - s.a) < 0.0f)
                    n = -n;
            }
            const glm::vec2 candidate = c + n * r;
            if (!segmentsCross(p0, candidate, s.a, s.b))
                p = candidate;
        });
        m_obstacleGrid.forEachNear(p, r, [&](std::uint32_t k) {
            if (k >= m_circles.size())
                return;  // boxes are walls too, handled above
            const CircleObstacle& o = m_circles[k];
            const glm::vec2 d = p - xz(o.centre);
            const float dist = glm::length(d);
            const float minDist = o.radius + r;
            if (dist >= minDist)
                return;
            const glm::vec2 n = dist > 1e-6f ? d / dist : glm::vec2(1.0f, 0.0f);
            p = xz(o.centre) + n * minDist;
        });
    }
    to.x = p.x;
    to.z = p.y;
}

void World::countStep()
{
    const std::size_t n = m_pos.size();
    std::uint64_t overlaps = 0, nonFinite = 0, inObstacle = 0, red = 0;
    m_grid.rebuild(m_pos, m_hasFliers);
    m_gridCurrent = true;
#pragma omp parallel for schedule(static, 256) num_threads(m_threads) reduction(+ : overlaps, nonFinite, inObstacle, red)
    for (std::size_t i = 0; i < n; ++i) {
        if (!isFinite(m_pos[i]) || !isFinite(m_vel[i]))
            ++nonFinite;
        const glm::vec2 p = xz(m_pos[i]);
        const float r = m_radius[i];
        auto overlap = [&](std::uint32_t j, const glm::vec3& q) {
            if (j <= i)
                return;
            const float contact = r + m_radius[j] - kOverlapToleranceM;
            const glm::vec3 d = m_pos[i] - q;
            if (glm::dot(d, d) < contact * contact)
                ++overlaps;
        };
        // Only a body within r + the largest radius can overlap this one.
        if (m_hasFliers)
            m_grid.forEachNear3D(m_pos[i], r + m_maxRadius, overlap);
        else
            m_grid.forEachNear(p, r + m_maxRadius, overlap);
        if (m_types[m_info[i].typeIndex].kind == AgentKind::Flier)
            continue;
        m_obstacleGrid.forEachNear(p, r, [&](std::uint32_t k) {
            if (k < m_circles.size() && glm::distance(p, xz(m_circles[k].centre)) < m_circles[k].radius + r - kOverlapToleranceM)
                ++inObstacle;
        });
        // A pedestrian stepping onto a crosswalk while its light is red violates it.
        std::uint8_t on = 0;
        int light = -1;
        for (const CrosswalkBox& c : m_crosswalks) {
            const glm::vec2 ab = c.b - c.a;
            const float len = glm::length(ab);
            const float along = glm::dot(p - c.a, ab) / len;
            const float across = std::fabs(cross(ab, p - c.a)) / len;
            if (along > 0.0f && along < len && across < c.halfWidth) {
                on = 1;
                light = c.light;
            }
        }
        if (on && !m_onCrosswalk[i] && light >= 0 && m_types[m_info[i].typeIndex].kind == AgentKind::Pedestrian &&
            lightState(std::size_t(light)) == 2)
            ++red;
        m_onCrosswalk[i] = on;
    }
    m_counters.overlappingPairs += overlaps;
    m_counters.nonFiniteValues += nonFinite;
    m_counters.obstaclePenetrations += inObstacle;
    m_counters.redLightViolations += red;
    m_counters.agentSteps += n;
}

}  // namespace throng::sim
