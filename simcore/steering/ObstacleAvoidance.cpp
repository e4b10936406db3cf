// Obstacle avoidance (Reynolds 1999, "Obstacle Avoidance"): a swept cylinder ahead, two
// half-length side feelers, and an inside test, answered laterally or repulsively.
#include "simcore/steering/ObstacleAvoidance.h"

#include "simcore/steering/detail/PlanarGeometry.h"
#include "simcore/steering/detail/SteeringMath.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::sim {

using namespace detail;

namespace {

// Below this sine the obstacle counts as on the line agent-target and the heading decides;
// below it again the agent passes on its right. Float noise on exactly collinear input is far smaller.
constexpr float kCollinearSine = 1e-3f;
// How strongly the repulsive answer leans sideways when the obstacle is dead ahead, so a
// head-on approach turns instead of stalling in front of the obstacle.
constexpr float kRepulsiveSideLean = 1.0f;

struct Threat {
    float urgency = -1.0f;  // [0, 1]; < 0 = none
    glm::vec2 centre{0.0f};
};

struct Feeler {
    glm::vec2 dir;
    float length;
};

glm::vec2 rotateRight(glm::vec2 d, float angleRad)
{
    return d * std::cos(angleRad) + rightOf(d) * std::sin(angleRad);
}

// The deepest overlap of the agent's body with any obstacle, as the direction straight out.
bool overlapPush(glm::vec2 p, float r, glm::vec2 h, std::span<const CircleObstacle> circles,
                 std::span<const BoxObstacle> boxes, glm::vec2& out)
{
    float deepest = 0.0f;
    for (const CircleObstacle& c : circles) {
        const glm::vec2 rel = p - xz(c.centre);
        const float depth = nonNegative(c.radius) + r - glm::length(rel);
        if (depth > deepest) {
            deepest = depth;
            out = normalizeOr(rel, -h);
        }
    }
    for (const BoxObstacle& b : boxes) {
        const SurfaceDistance s = boxSurfaceDistance(p, planarBox(b));
        const float depth = r - s.distance;
        if (depth > deepest) {
            deepest = depth;
            out = s.normal;
        }
    }
    return deepest > 0.0f;
}

void consider(Threat& threat, float t, float length, glm::vec2 centre)
{
    if (t < 0.0f)
        return;
    const float urgency = length > kTiny ? 1.0f - t / length : 1.0f;
    if (urgency > threat.urgency) {
        threat.urgency = urgency;
        threat.centre = centre;
    }
}

// The unit lateral direction (perpendicular to h) on which to pass the obstacle at c: toward the
// blend of the preferred side (away from the obstacle as seen from the line agent-target) and
// straight away from the obstacle. The second term takes over when the agent already moves
// sideways along the preferred side, where the first alone would flip with every small turn.
glm::vec2 passingSide(glm::vec2 p, glm::vec2 h, glm::vec2 c, glm::vec2 target)
{
    const glm::vec2 toObstacle = normalizeOr(c - p, h);
    const glm::vec2 toTarget = normalizeOr(target - p, h);
    const float offTargetLine = glm::dot(toObstacle, rightOf(toTarget));
    glm::vec2 preferred(0.0f);
    if (std::abs(offTargetLine) >= kCollinearSine) {
        preferred = rightOf(toTarget) * (offTargetLine > 0.0f ? -1.0f : 1.0f);
    } else {
        const float offHeading = glm::dot(toObstacle, rightOf(h));
        preferred = rightOf(h) * (offHeading > kCollinearSine ? -1.0f : 1.0f);
    }
    return rightOf(h) * (glm::dot(preferred - toObstacle, rightOf(h)) < 0.0f ? -1.0f : 1.0f);
}

}  // namespace

glm::vec3 avoidObstacles(const SteeringAgent& agent, std::span<const CircleObstacle> circles,
                         std::span<const BoxObstacle> boxes, glm::vec3 target, const ObstacleAvoidanceParams& params)
{
    const glm::vec2 p = xz(finiteOrZero(agent.position));
    const float r = nonNegative(agent.radius);
    const float maxForce = nonNegative(agent.maxForce);
    const glm::vec2 h = planarHeading(agent);

    glm::vec2 out(0.0f);
    if (overlapPush(p, r, h, circles, boxes, out))
        return fromXz(normalizeOr(out, glm::vec2(1.0f, 0.0f))) * maxForce;
    if (h == glm::vec2(0.0f))
        return glm::vec3(0.0f);

    const float speed = isFinite(xz(agent.velocity)) ? glm::length(xz(agent.velocity)) : 0.0f;
    const float length = nonNegative(params.minLengthM) + speed * nonNegative(params.lookaheadS);
    if (!(length > kTiny))
        return glm::vec3(0.0f);
    const float sweep = r + nonNegative(params.marginM);
    const float whisker = finiteOr(params.whiskerAngleRad, 0.0f);
    const Feeler feelers[3] = {
        {h, length}, {rotateRight(h, whisker), 0.5f * length}, {rotateRight(h, -whisker), 0.5f * length}};

    Threat threat;
    for (const Feeler& f : feelers) {
        for (const CircleObstacle& c : circles)
            consider(threat, sweepCircle(p, f.dir, f.length, xz(c.centre), nonNegative(c.radius) + sweep), f.length,
                     xz(c.centre));
        for (const BoxObstacle& b : boxes) {
            const PlanarBox box = planarBox(b);
            consider(threat, sweepBox(p, f.dir, f.length, box, sweep), f.length, box.centre);
        }
    }
    if (threat.urgency <= 0.0f)
        return glm::vec3(0.0f);

    const glm::vec2 goal = isFinite(xz(target)) ? xz(target) : p + h;
    const glm::vec2 side = passingSide(p, h, threat.centre, goal);
    glm::vec2 dir = side;
    if (params.response == AvoidanceResponse::Repulsive) {
        const glm::vec2 away = normalizeOr(p - threat.centre, -h);
        const float headOn = std::max(0.0f, -glm::dot(away, h));
        dir = normalizeOr(away + side * (headOn * kRepulsiveSideLean), side);
    }
    return fromXz(dir) * (maxForce * threat.urgency);
}

}  // namespace throng::sim
