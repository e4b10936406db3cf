// Agents that start inside a wall or obstacle (a crowd brush stroke over a crate, a spawn
// rectangle across a pillar): the World walks each one out along the shortest way, at
// its own pace, before it steers again. Before, one in a box stayed trapped for the whole
// shot (its sides held it in) and one in a circle popped out metres in one frame (issue 23).
#include "simcore/world/World.h"

#include "simcore/world/detail/StepGeometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::sim {

using detail::closestOnSegment;
using detail::xz;

namespace {

constexpr float kInsideM = 0.01f;      // an overlap deeper than this is "inside"
constexpr float kClearM = 0.02f;       // the escape ends this far clear of the surface
constexpr float kMinEscapeSpeed = 0.5f; // m/s: even an agent with no speed of its own gets out
constexpr int kRounds = 8;              // moves out of one shape may lead into the next

}  // namespace

bool World::escapeTarget(glm::vec2 p, float r, glm::vec2& out) const
{
    const glm::vec2 start = p;
    for (int round = 0; round < kRounds; ++round) {
        // The deepest overlap here, and the shortest way out of it.
        float deepest = kInsideM;
        glm::vec2 exit = p;
        m_set.obstacleGrid.forEachNear(p, r, [&](std::uint32_t k) {
            if (k < m_set.circles.size()) {
                const CircleObstacle& o = m_set.circles[k];
                const glm::vec2 d = p - xz(o.centre);
                const float dist = glm::length(d), depth = o.radius + r - dist;
                if (depth > deepest) {
                    deepest = depth;
                    const glm::vec2 n = dist > 1e-6f ? d / dist : glm::vec2(1.0f, 0.0f);
                    exit = xz(o.centre) + n * (o.radius + r + kClearM);
                }
                return;
            }
            const BoxObstacle& b = m_set.boxes[k - m_set.circles.size()];
            const glm::vec2 ax = xz(b.axis), az(-ax.y, ax.x);
            const glm::vec2 d = p - xz(b.centre);
            const float lx = glm::dot(d, ax), lz = glm::dot(d, az);
            // Inside the box grown by the body: out through the nearer pair of faces.
            const float px = b.halfSize.x + r - std::fabs(lx), pz = b.halfSize.y + r - std::fabs(lz);
            const float depth = std::min(px, pz);
            if (px > 0.0f && pz > 0.0f && depth > deepest) {
                deepest = depth;
                const float sx = lx < 0.0f ? -1.0f : 1.0f, sz = lz < 0.0f ? -1.0f : 1.0f;
                exit = px < pz ? p + ax * (sx * (px + kClearM)) : p + az * (sz * (pz + kClearM));
            }
        });
        m_set.walls.forEachNear(p, r, [&](std::uint32_t k) {
            const Segment& s = m_set.walls.segment(k);
            const glm::vec2 c = closestOnSegment(p, s.a, s.b);
            const glm::vec2 d = p - c;
            const float dist = glm::length(d), depth = r - dist;
            if (depth > deepest) {
                deepest = depth;
                glm::vec2 n;
                if (dist > 1e-6f) {
                    n = d / dist;
                } else {
                    const glm::vec2 along = s.b - s.a;
                    n = glm::dot(along, along) > 0.0f ? glm::normalize(glm::vec2(-along.y, along.x)) : glm::vec2(1, 0);
                }
                exit = c + n * (r + kClearM);
            }
        });
        if (exit == p)
            break;
        p = exit;
    }
    out = p;
    // Inside = the way out is longer than the body's radius (its centre lies in an
    // obstacle): a body that only overlaps a wall or obstacle's edge is pushed clear by
    // constrain within a frame, by less than its radius, as it always was.
    return glm::distance(p, start) > r;
}

void World::findEscapes()
{
    const std::size_t n = m_agents.pos.size();
    m_agents.escaping.assign(n, 0);
    m_agents.escapeTo.assign(n, glm::vec2(0.0f));
    if (m_set.walls.segments().empty() && m_set.circles.empty())
        return;
    for (std::size_t i = 0; i < n; ++i) {
        if (m_types.params[m_agents.info[i].typeIndex].kind != AgentKind::Pedestrian || m_traffic.isDriven(i))
            continue;
        glm::vec2 to;
        if (escapeTarget(xz(m_agents.pos[i]), m_agents.radius[i], to)) {
            m_agents.escaping[i] = 1;
            m_agents.escapeTo[i] = to;
        }
    }
}

void World::escapeStep(std::size_t i, glm::vec3 from, glm::vec3& to) const
{
    const glm::vec2 p = xz(from), d = m_agents.escapeTo[i] - p;
    const float len = glm::length(d), most = std::max(m_agents.maxSpeed[i], kMinEscapeSpeed) * m_clock.dt;
    const glm::vec2 q = len > most ? p + d * (most / len) : m_agents.escapeTo[i];
    to.x = q.x;
    to.z = q.y;
}

}  // namespace throng::sim
