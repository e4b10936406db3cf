// Containment (Reynolds 1999, "Containment"): probes outside the region steer back along
// the surface normal.
#include "simcore/steering/Containment.h"

#include "simcore/steering/detail/PlanarGeometry.h"
#include "simcore/steering/detail/SteeringMath.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace throng::sim {

using namespace detail;

namespace {

std::array<glm::vec3, 4> probes(const SteeringAgent& agent, const ContainmentParams& params)
{
    const glm::vec3 p = finiteOrZero(agent.position);
    const glm::vec3 h = heading(agent);
    const glm::vec3 right = normalizeOr(glm::cross(h, normalizeOr(agent.up, kWorldUp)), rightOfForward(h));
    const float speed = glm::length(finiteOrZero(agent.velocity));
    const float length = nonNegative(params.probeMinM) + speed * nonNegative(params.probeLookaheadS);
    const float sideLength = length * std::clamp(finiteOr(params.sideProbeFraction, 0.0f), 0.0f, 1.0f);
    const float angle = finiteOr(params.sideProbeAngleRad, 0.0f);
    const glm::vec3 ahead = h * std::cos(angle), across = right * std::sin(angle);
    return {p, p + h * length, p + (ahead + across) * sideLength, p + (ahead - across) * sideLength};
}

bool insidePolygon(glm::vec2 q, std::span<const glm::vec3> v)
{
    // Even-odd rule: count edge crossings of a ray toward +x.
    bool inside = false;
    for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
        const glm::vec2 a = xz(v[i]), b = xz(v[j]);
        if ((a.y > q.y) != (b.y > q.y) && q.x < a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y))
            inside = !inside;
    }
    return inside;
}

glm::vec2 nearestOnPolygon(glm::vec2 q, std::span<const glm::vec3> v)
{
    glm::vec2 best = xz(v[0]);
    float bestDist2 = glm::dot(q - best, q - best);
    for (std::size_t i = 0, j = v.size() - 1; i < v.size(); j = i++) {
        const glm::vec2 c = closestOnSegment(q, xz(v[j]), xz(v[i]));
        const float d2 = glm::dot(q - c, q - c);
        if (d2 < bestDist2) {
            bestDist2 = d2;
            best = c;
        }
    }
    return best;
}

glm::vec3 pushBack(const SteeringAgent& agent, glm::vec3 inward)
{
    return normalizeOr(inward, glm::vec3(0.0f)) * nonNegative(agent.maxForce);
}

}  // namespace

glm::vec3 stayInside(const SteeringAgent& agent, const WalkableBox& region, const ContainmentParams& params)
{
    if (!isFinite(region.min) || !isFinite(region.max))
        return glm::vec3(0.0f);
    const glm::vec3 lo = glm::min(region.min, region.max), hi = glm::max(region.min, region.max);
    glm::vec3 inward(0.0f);
    for (const glm::vec3& q : probes(agent, params)) {
        const glm::vec3 back = glm::clamp(q, lo, hi) - q;
        inward += normalizeOr(back, glm::vec3(0.0f));
    }
    return pushBack(agent, inward);
}

glm::vec3 stayInside(const SteeringAgent& agent, const WalkablePolygon& region, const ContainmentParams& params)
{
    if (region.vertices.size() < 3)
        return glm::vec3(0.0f);
    for (const glm::vec3& v : region.vertices)
        if (!isFinite(v))
            return glm::vec3(0.0f);
    glm::vec2 inward(0.0f);
    for (const glm::vec3& q : probes(agent, params)) {
        const glm::vec2 p = xz(q);
        if (!insidePolygon(p, region.vertices))
            inward += normalizeOr(nearestOnPolygon(p, region.vertices) - p, glm::vec2(0.0f));
    }
    return pushBack(agent, fromXz(inward));
}

}  // namespace throng::sim
