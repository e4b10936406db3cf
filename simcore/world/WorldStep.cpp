// World::step: one fixed time step as a column of phases. Every agent reads the previous
// state and writes only its own next state (RVO2's doStep computes all new velocities
// before committing any), so the result is the same for any thread count.
#include "simcore/world/World.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::sim {

namespace {

glm::vec2 xz(glm::vec3 v) { return {v.x, v.z}; }

glm::vec3 truncate(glm::vec3 v, float maxLength)
{
    const float l2 = glm::dot(v, v);
    return l2 > maxLength * maxLength && l2 > 0.0f ? v * (maxLength / std::sqrt(l2)) : v;
}

glm::vec2 closestOnSegment(glm::vec2 p, glm::vec2 a, glm::vec2 b)
{
    const glm::vec2 ab = b - a;
    const float len2 = glm::dot(ab, ab);
    const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
    return a + ab * t;
}

float cross(glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; }

// True when segment p0-p1 properly crosses segment a-b.
bool segmentsCross(glm::vec2 p0, glm::vec2 p1, glm::vec2 a, glm::vec2 b)
{
    const float d1 = cross(b - a, p0 - a), d2 = cross(b - a, p1 - a);
    const float d3 = cross(p1 - p0, a - p0), d4 = cross(p1 - p0, b - p0);
    return ((d1 > 0.0f && d2 < 0.0f) || (d1 < 0.0f && d2 > 0.0f)) &&
           ((d3 > 0.0f && d4 < 0.0f) || (d3 < 0.0f && d4 > 0.0f));
}

bool isFinite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Overlap tolerance: touching within 1 cm is contact, not overlap.
constexpr float kOverlapToleranceM = 0.01f;

}  // namespace

glm::vec3 World::desiredVelocity(std::size_t i) const
{
    const TypeParams& t = m_types[m_info[i].typeIndex];
    const float speed = t.maxSpeed * m_speedFactor[i];
    const glm::vec2 p = xz(m_pos[i]);
    glm::vec2 target;
    float slowingM = 0.0f;  // 0 = no arrival: pass through at full speed
    if (m_path[i] >= 0) {
        const Path& path = m_paths[std::size_t(m_path[i])];
        const std::size_t w = std::size_t(m_waypoint[i]);
        target = path.points[std::min(w, path.points.size() - 1)];
        if (!path.closed && w + 1 >= path.points.size())
            slowingM = std::max(1.0f, speed);
    } else if (m_goal[i] >= 0) {
        target = m_goals[std::size_t(m_goal[i])].position;
        slowingM = std::max(1.0f, speed);
    } else {
        return glm::vec3(0.0f);
    }
    if (m_arrived[i])
        return glm::vec3(0.0f);
    const glm::vec2 d = target - p;
    const float dist = glm::length(d);
    if (dist < 1e-4f)
        return glm::vec3(0.0f);
    // Arrival (Reynolds 1999): ramp the speed down inside the slowing distance.
    const float s = slowingM > 0.0f ? speed * std::min(1.0f, dist / slowingM) : speed;
    const glm::vec2 v = d * (s / dist);
    return {v.x, 0.0f, v.y};
}

void World::constrain(std::size_t i, glm::vec3 from, glm::vec3& to) const
{
    const float r = m_radius[i];
    glm::vec2 p = xz(to);
    const glm::vec2 p0 = xz(from);
    // A move that would cross a wall stops where it started (no tunnelling at any speed).
    const glm::vec2 mid = (p0 + p) * 0.5f;
    const float reach = 0.5f * glm::length(p - p0) + r + 0.01f;
    bool crossed = false;
    m_walls.forEachNear(mid, reach, [&](std::uint32_t k) {
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
                n = glm::normalize(glm::vec2(-along.y, along.x));
                if (glm::dot(n, p0 - s.a) < 0.0f)
                    n = -n;
            }
            const glm::vec2 candidate = c + n * r;
            if (!segmentsCross(p0, candidate, s.a, s.b))
                p = candidate;
        });
        for (const CircleObstacle& o : m_circles) {
            const glm::vec2 d = p - o.c;
            const float dist = glm::length(d);
            const float minDist = o.r + r;
            if (dist >= minDist)
                continue;
            const glm::vec2 n = dist > 1e-6f ? d / dist : glm::vec2(1.0f, 0.0f);
            p = o.c + n * minDist;
        }
    }
    to.x = p.x;
    to.z = p.y;
}

void World::step()
{
    const std::size_t n = m_pos.size();
    const float dt = m_dt;

    // Grid: index agents by cell for neighbour queries.
    m_grid.rebuild(m_pos);

#pragma omp parallel for schedule(static) num_threads(m_threads)
    for (std::size_t i = 0; i < n; ++i) {
        const TypeParams& t = m_types[m_info[i].typeIndex];
        // Steer: arrival toward the goal or the current waypoint, plus separation.
        glm::vec3 desired = desiredVelocity(i);
        glm::vec3 force = (desired - m_vel[i]) * (t.mass / std::max(dt, 1e-6f));
        if (t.separation > 0.0f) {
            const glm::vec2 p = xz(m_pos[i]);
            const float reach = 2.0f * t.radius + 0.5f;
            glm::vec2 push(0.0f);
            m_grid.forEachNear(p, reach, [&](std::uint32_t j) {
                if (j == i)
                    return;
                const glm::vec2 d = p - xz(m_pos[j]);
                const float dist = glm::length(d);
                const float contact = t.radius + m_radius[j];
                if (dist >= reach || dist >= contact + 0.5f)
                    return;
                // Coincident agents separate along a direction fixed by their ids.
                const glm::vec2 dir = dist > 1e-5f ? d / dist
                                                   : glm::vec2(std::cos(float(m_info[i].id)), std::sin(float(m_info[i].id)));
                push += dir * ((contact + 0.5f - dist) / 0.5f);
            });
            force += glm::vec3(push.x, 0.0f, push.y) * (t.separation * t.maxForce);
        }
        // Integrate: the simple vehicle model (truncate force, a = F/m, truncate velocity).
        force = truncate(force, t.maxForce);
        glm::vec3 vel = m_vel[i] + force * (dt / t.mass);
        vel.y = 0.0f;
        vel = truncate(vel, t.maxSpeed * m_speedFactor[i]);
        glm::vec3 next = m_pos[i] + vel * dt;
        // Constrain: no agent ends a step inside a wall or obstacle.
        constrain(i, m_pos[i], next);
        m_nextVel[i] = (next - m_pos[i]) / dt;
        m_nextPos[i] = next;
    }

    // Commit: swap in the new state, then advance per-agent bookkeeping.
    std::uint64_t crossings = 0;
#pragma omp parallel for schedule(static) num_threads(m_threads) reduction(+ : crossings)
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec2 from = xz(m_pos[i]), to = xz(m_nextPos[i]);
        m_walls.forEachNear((from + to) * 0.5f, 0.5f * glm::length(to - from) + 0.01f, [&](std::uint32_t k) {
            const Segment& s = m_walls.segment(k);
            if (segmentsCross(from, to, s.a, s.b))
                ++crossings;
        });
        const float moved = glm::length(xz(m_nextPos[i]) - xz(m_pos[i]));
        // Animate: the gait advances by distance over stride length, so feet don't slide.
        m_phase[i] = std::fmod(m_phase[i] + moved / m_stride[i], 1.0f);
        m_pos[i] = m_nextPos[i];
        m_vel[i] = m_nextVel[i];
        const float speed = glm::length(m_vel[i]);
        if (speed > 1e-3f)
            m_fwd[i] = m_vel[i] / speed;
        const glm::vec2 p = xz(m_pos[i]);
        if (m_path[i] >= 0) {
            const Path& path = m_paths[std::size_t(m_path[i])];
            const std::size_t w = std::size_t(m_waypoint[i]);
            const bool last = !path.closed && w + 1 >= path.points.size();
            if (glm::distance(p, path.points[w]) < (last ? 0.05f : path.radiusM)) {
                if (last)
                    m_arrived[i] = 1;
                else
                    m_waypoint[i] = int((w + 1) % path.points.size());
            }
        } else if (m_goal[i] >= 0) {
            const Goal& g = m_goals[std::size_t(m_goal[i])];
            if (glm::distance(p, g.position) < g.radiusM)
                m_arrived[i] = 1;
        }
        if (m_arrived[i])
            m_vel[i] = glm::vec3(0.0f);
    }
    m_counters.wallPenetrations += crossings;
    ++m_step;
    countStep();
}

void World::countStep()
{
    const std::size_t n = m_pos.size();
    std::uint64_t overlaps = 0, nonFinite = 0, inObstacle = 0, red = 0;
    m_grid.rebuild(m_pos);
#pragma omp parallel for schedule(static) num_threads(m_threads) reduction(+ : overlaps, nonFinite, inObstacle, red)
    for (std::size_t i = 0; i < n; ++i) {
        if (!isFinite(m_pos[i]) || !isFinite(m_vel[i]))
            ++nonFinite;
        const glm::vec2 p = xz(m_pos[i]);
        const float r = m_radius[i];
        m_grid.forEachNear(p, 2.0f * r + 1.0f, [&](std::uint32_t j) {
            if (j <= i)
                return;
            const float contact = r + m_radius[j] - kOverlapToleranceM;
            const glm::vec2 d = p - xz(m_pos[j]);
            if (glm::dot(d, d) < contact * contact)
                ++overlaps;
        });
        for (const CircleObstacle& o : m_circles)
            if (glm::distance(p, o.c) < o.r + r - kOverlapToleranceM)
                ++inObstacle;
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
