// Path following (Reynolds 1999, "Path Following"): predict, project onto the spine, and
// correct only when the prediction leaves the path.
#include "simcore/steering/PathFollowing.h"

#include "simcore/steering/TargetBehaviours.h"
#include "simcore/steering/detail/SteeringMath.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::sim {

using namespace detail;

namespace {

std::size_t segmentCount(const SteeringPath& path)
{
    const std::size_t n = path.points.size();
    if (n < 2)
        return 0;
    return path.closed ? n : n - 1;
}

glm::vec3 pointAt(const SteeringPath& path, std::size_t i)
{
    return finiteOrZero(path.points[i % path.points.size()]);
}

}  // namespace

float pathLength(const SteeringPath& path)
{
    float total = 0.0f;
    for (std::size_t i = 0; i < segmentCount(path); ++i)
        total += glm::length(pointAt(path, i + 1) - pointAt(path, i));
    return total;
}

PathProjection projectOntoPath(const SteeringPath& path, glm::vec3 p)
{
    PathProjection best;
    if (path.points.empty())
        return best;
    best.point = pointAt(path, 0);
    float bestDist2 = glm::dot(p - best.point, p - best.point);
    float along = 0.0f;
    for (std::size_t i = 0; i < segmentCount(path); ++i) {
        const glm::vec3 a = pointAt(path, i), b = pointAt(path, i + 1);
        const glm::vec3 ab = b - a;
        const float len = glm::length(ab);
        if (len <= kTiny)
            continue;
        const glm::vec3 dir = ab / len;
        const float t = std::clamp(glm::dot(p - a, dir), 0.0f, len);
        const glm::vec3 q = a + dir * t;
        const float d2 = glm::dot(p - q, p - q);
        // Strictly nearer only: on a tie the earlier segment wins, so the answer is deterministic.
        if (best.tangent == glm::vec3(0.0f) || d2 < bestDist2) {
            bestDist2 = d2;
            best.point = q;
            best.distanceAlongM = along + t;
            best.tangent = dir;
        }
        along += len;
    }
    return best;
}

glm::vec3 pointAlongPath(const SteeringPath& path, float distanceAlongM)
{
    if (path.points.empty())
        return glm::vec3(0.0f);
    const float total = pathLength(path);
    if (!(total > kTiny))
        return pointAt(path, 0);
    float s = finiteOr(distanceAlongM, 0.0f);
    s = path.closed ? s - total * std::floor(s / total) : std::clamp(s, 0.0f, total);
    for (std::size_t i = 0; i < segmentCount(path); ++i) {
        const glm::vec3 a = pointAt(path, i), b = pointAt(path, i + 1);
        const float len = glm::length(b - a);
        if (s <= len && len > kTiny)
            return a + (b - a) * (s / len);
        s -= len;
    }
    return pointAt(path, path.closed ? 0 : path.points.size() - 1);
}

glm::vec3 followPath(const SteeringAgent& agent, const SteeringPath& path, const PathFollowParams& params)
{
    if (path.points.empty())
        return glm::vec3(0.0f);
    const glm::vec3 position = finiteOrZero(agent.position);
    const glm::vec3 velocity = finiteOrZero(agent.velocity);
    const glm::vec3 future = position + velocity * nonNegative(params.predictionS);
    const PathProjection predicted = projectOntoPath(path, future);
    const float total = pathLength(path);
    const float direction = params.reverse ? -1.0f : 1.0f;

    // Reynolds 1999: no correction while the predicted position is on the path and the agent makes
    // progress along it.
    const bool inside = glm::length(future - predicted.point) <= nonNegative(path.radius);
    const float cruise = std::clamp(finiteOr(params.cruiseFraction, 0.0f), 0.0f, 1.0f) * nonNegative(agent.maxSpeed);
    const float speedAlong = glm::dot(velocity, predicted.tangent) * direction;
    const bool progressing = speedAlong > 0.0f && speedAlong >= cruise;
    const bool atEnd = !path.closed && (params.reverse ? predicted.distanceAlongM <= kTiny
                                                       : predicted.distanceAlongM >= total - kTiny);
    if (inside && progressing && !atEnd)
        return glm::vec3(0.0f);

    // The target is measured from the agent's own projection, not the prediction's: past a corner the
    // prediction already lies on the next leg, and a target ahead of it made the agent cut the corner
    // by more than the radius.
    const float targetAlong = projectOntoPath(path, position).distanceAlongM + direction * nonNegative(params.aheadM);
    const glm::vec3 target = pointAlongPath(path, targetAlong);
    if (!path.closed && (targetAlong >= total || targetAlong <= 0.0f)) {
        // The end of an open path: arrive there rather than orbit it.
        const float slowing = std::max(nonNegative(params.aheadM), nonNegative(agent.maxSpeed));
        return arrive(agent, target, ArrivalParams{slowing, 0.02f, params.responseTimeS});
    }
    return seek(agent, target, SeekParams{params.responseTimeS});
}

}  // namespace throng::sim
