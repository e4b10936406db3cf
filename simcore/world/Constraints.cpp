// Hard constraints: no body ends a step inside a wall or obstacle. A move is held out of
// the set (holdOut); an agent that starts inside a wall or obstacle (a crowd brush stroke
// over a crate, a spawn rectangle across a pillar) instead walks out along the shortest
// way, at its own pace, before it steers again. Before, one in a box stayed trapped for
// the whole shot (its sides held it in) and one in a circle popped out metres in one
// frame (issue 23).
#include "simcore/world/Constraints.h"

#include "simcore/world/detail/StepGeometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::sim {

using namespace detail;

namespace {

constexpr float kInsideM = 0.01f;      // an overlap deeper than this is "inside"
constexpr float kClearM = 0.02f;       // the escape ends this far clear of the surface
constexpr float kMinEscapeSpeed = 0.5f; // m/s: even an agent with no speed of its own gets out
constexpr int kRounds = 8;              // moves out of one shape may lead into the next

}  // namespace

bool sideOfBoxAround(const StaticSet& set, const Segment& s, glm::vec2 p)
{
    constexpr float kOnSide = 1e-3f;  // relative: the side's midpoint lies on the box's outline
    for (const BoxObstacle& b : set.boxes) {
        const glm::vec2 ax = xz(b.axis), az(-ax.y, ax.x), c = xz(b.centre);
        const glm::vec2 d = p - c, m = 0.5f * (s.a + s.b) - c;
        if (std::fabs(glm::dot(d, ax)) >= b.halfSize.x || std::fabs(glm::dot(d, az)) >= b.halfSize.y)
            continue;  // p is not inside this box
        const float edge =
            std::max(std::fabs(glm::dot(m, ax)) / b.halfSize.x, std::fabs(glm::dot(m, az)) / b.halfSize.y);
        if (std::fabs(edge - 1.0f) < kOnSide)
            return true;
    }
    return false;
}

void holdOut(const StaticSet& set, glm::vec3 from, glm::vec3& to, float r)
{
    glm::vec2 p = xz(to);
    const glm::vec2 p0 = xz(from);
    // A move that would cross a wall stops where it started (no tunnelling at any speed).
    bool crossed = false;
    set.walls.forEachNear((p0 + p) * 0.5f, 0.5f * glm::length(p - p0) + r + 0.01f, [&](std::uint32_t k) {
        const Segment& s = set.walls.segment(k);
        crossed = crossed || segmentsCross(p0, p, s.a, s.b);
    });
    if (crossed)
        p = p0;
    // Then push the body out of walls and obstacles it overlaps; two passes settle corners.
    for (int pass = 0; pass < 2; ++pass) {
        set.walls.forEachNear(p, r, [&](std::uint32_t k) {
            const Segment& s = set.walls.segment(k);
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
        set.obstacleGrid.forEachNear(p, r, [&](std::uint32_t k) {
            if (k >= set.circles.size())
                return;  // boxes are walls too, handled above
            const CircleObstacle& o = set.circles[k];
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

bool escapeTarget(const StaticSet& set, glm::vec2 p, float r, glm::vec2& out)
{
    const glm::vec2 start = p;
    for (int round = 0; round < kRounds; ++round) {
        // The deepest overlap here, and the shortest way out of it.
        float deepest = kInsideM;
        glm::vec2 exit = p;
        set.obstacleGrid.forEachNear(p, r, [&](std::uint32_t k) {
            if (k < set.circles.size()) {
                const CircleObstacle& o = set.circles[k];
                const glm::vec2 d = p - xz(o.centre);
                const float dist = glm::length(d), depth = o.radius + r - dist;
                if (depth > deepest) {
                    deepest = depth;
                    const glm::vec2 n = dist > 1e-6f ? d / dist : glm::vec2(1.0f, 0.0f);
                    exit = xz(o.centre) + n * (o.radius + r + kClearM);
                }
                return;
            }
            const BoxObstacle& b = set.boxes[k - set.circles.size()];
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
        set.walls.forEachNear(p, r, [&](std::uint32_t k) {
            const Segment& s = set.walls.segment(k);
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

void constrain(const AgentColumns& agents, const StaticSet& set, float dt, std::size_t i, glm::vec3 from, glm::vec3& to)
{
    if (!agents.escaping[i]) {
        holdOut(set, from, to, agents.radius[i]);
        return;
    }
    // Started inside a wall or obstacle: on its way out, at its own pace.
    const glm::vec2 p = xz(from), d = agents.escapeTo[i] - p;
    const float len = glm::length(d), most = std::max(agents.maxSpeed[i], kMinEscapeSpeed) * dt;
    const glm::vec2 q = len > most ? p + d * (most / len) : agents.escapeTo[i];
    to.x = q.x;
    to.z = q.y;
}

}  // namespace throng::sim
