// Path following (Reynolds 1999, "Path Following"): predict, project onto the spine, and
// correct only when the prediction leaves the path.
#include "simcore/steering/PathFollowing.h"

#include "simcore/steering/TargetBehaviours.h"
#include "simcore/steering/detail/SteeringMath.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

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

PathProjection projectOntoPathWithin(const SteeringPath& path, glm::vec3 p, float fromM, float toM)
{
    PathProjection best;
    const std::size_t segments = segmentCount(path);
    const float total = pathLength(path);
    if (segments == 0 || !(total > kTiny) || !(fromM <= toM))
        return projectOntoPath(path, p);
    if (path.closed) {
        // Two laps of segments cover any window up to a lap long that starts in the first.
        const float shift = total * std::floor(fromM / total);
        fromM -= shift;
        toM = std::min(toM - shift, fromM + total);
    } else {
        fromM = std::clamp(fromM, 0.0f, total);
        toM = std::clamp(toM, fromM, total);
    }
    float bestDist2 = INFINITY, along = 0.0f;
    bool found = false;
    const std::size_t laps = path.closed ? 2 : 1;
    for (std::size_t k = 0; k < laps * segments; ++k) {
        const glm::vec3 a = pointAt(path, k % segments), b = pointAt(path, k % segments + 1);
        const float len = glm::length(b - a);
        const float lo = std::max(fromM, along), hi = std::min(toM, along + len);
        if (len > kTiny && lo <= hi) {
            const glm::vec3 dir = (b - a) / len;
            const float t = std::clamp(glm::dot(p - a, dir), lo - along, hi - along);
            const glm::vec3 q = a + dir * t;
            const float d2 = glm::dot(p - q, p - q);
            if (!found || d2 < bestDist2) {
                found = true;
                bestDist2 = d2;
                best.point = q;
                best.distanceAlongM = along + t;
                best.tangent = dir;
            }
        }
        along += len;
        if (along > toM)
            break;
    }
    if (!found)
        return projectOntoPath(path, p);
    if (path.closed && best.distanceAlongM >= total)
        best.distanceAlongM -= total;
    return best;
}

// A follower pushed back this far along its path (a crowd at a red light) still aims from
// where it stands; a leg walked before lies further back than this once its turn is passed.
constexpr float kBackM = 1.0f;

// Whether a distance along lies behind the progress made by more than kBackM (on a
// closed path: within half a lap behind it), so it belongs to a stretch already walked.
static bool behindProgress(const SteeringPath& path, float alongM, float progressM, bool reverse)
{
    float back = reverse ? alongM - progressM : progressM - alongM;
    if (path.closed) {
        const float total = pathLength(path);
        if (!(total > kTiny))
            return false;
        back -= total * std::floor(back / total);
        return back > kBackM && back < 0.5f * total;
    }
    return back > kBackM;
}

float pathReachM(const SteeringPath& path, const PathFollowParams& params, float maxSpeed, float dtS)
{
    return nonNegative(maxSpeed) * nonNegative(dtS) + 2.0f * nonNegative(path.radius) + nonNegative(params.aheadM) +
           0.5f;
}

float startPathProgress(const SteeringPath& path, glm::vec3 p)
{
    return projectOntoPath(path, finiteOrZero(p)).distanceAlongM;
}

float advancePathProgress(const SteeringPath& path, glm::vec3 p, float progressM, float reachM, bool reverse)
{
    if (!std::isfinite(progressM))
        return startPathProgress(path, p);
    const float reach = nonNegative(reachM);
    const float from = reverse ? progressM - reach : progressM, to = reverse ? progressM : progressM + reach;
    const float nearest = projectOntoPath(path, finiteOrZero(p)).distanceAlongM;
    const float along = !behindProgress(path, nearest, progressM, reverse)
                            ? nearest
                            : projectOntoPathWithin(path, finiteOrZero(p), from, to).distanceAlongM;
    if (path.closed)
        return along;
    // Never back: on an open path the window already starts at the progress made.
    return reverse ? std::min(along, progressM) : std::max(along, progressM);
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
    return followPath(agent, path, params, NAN);
}

glm::vec3 followPath(const SteeringAgent& agent, const SteeringPath& path, const PathFollowParams& params,
                     float progressM)
{
    if (path.points.empty())
        return glm::vec3(0.0f);
    const glm::vec3 position = finiteOrZero(agent.position);
    const glm::vec3 velocity = finiteOrZero(agent.velocity);
    const glm::vec3 future = position + velocity * nonNegative(params.predictionS);
    // With a remembered progress, projections look only ahead of it (behind it when
    // reversed): the prediction as far as it can reach, the agent itself one step's reach.
    const bool remembered = std::isfinite(progressM);
    const float reach = remembered ? pathReachM(path, params, agent.maxSpeed, 0.0f) : 0.0f;
    auto window = [&](float extraM) {
        const float r = reach + extraM;
        return params.reverse ? std::pair{progressM - r, progressM + kBackM}
                              : std::pair{progressM - kBackM, progressM + r};
    };
    // The nearest point of the whole spine, as Reynolds has it, unless it lies on a stretch
    // already walked: then the nearest point from the progress made on.
    auto project = [&](glm::vec3 p, float extraM) {
        const PathProjection nearest = projectOntoPath(path, p);
        if (!remembered)
            return nearest;
        const auto [from, to] = window(extraM);
        if (!behindProgress(path, nearest.distanceAlongM, progressM, params.reverse))
            return nearest;
        return projectOntoPathWithin(path, p, from, to);
    };
    const PathProjection predicted = project(future, glm::length(velocity) * nonNegative(params.predictionS));
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
    const float targetAlong = project(position, 0.0f).distanceAlongM + direction * nonNegative(params.aheadM);
    const glm::vec3 target = pointAlongPath(path, targetAlong);
    if (!path.closed && (targetAlong >= total || targetAlong <= 0.0f)) {
        // The end of an open path: arrive there rather than orbit it.
        const float slowing = std::max(nonNegative(params.aheadM), nonNegative(agent.maxSpeed));
        return arrive(agent, target, ArrivalParams{slowing, 0.02f, params.responseTimeS});
    }
    return seek(agent, target, SeekParams{params.responseTimeS});
}

}  // namespace throng::sim
