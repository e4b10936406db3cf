// Ground-plane casts and closest points for the avoidance behaviours.
#include "simcore/steering/detail/PlanarGeometry.h"

#include "simcore/steering/detail/SteeringMath.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::sim::detail {

PlanarBox planarBox(const BoxObstacle& box)
{
    PlanarBox b;
    b.centre = isFinite(xz(box.centre)) ? xz(box.centre) : glm::vec2(0.0f);
    b.axisU = normalizeOr(xz(box.axis), glm::vec2(1.0f, 0.0f));
    b.axisW = {-b.axisU.y, b.axisU.x};
    b.half = {nonNegative(box.halfSize.x), nonNegative(box.halfSize.y)};
    return b;
}

float sweepCircle(glm::vec2 p, glm::vec2 dir, float length, glm::vec2 centre, float radius)
{
    const glm::vec2 m = p - centre;
    const float b = glm::dot(m, dir);
    const float c = glm::dot(m, m) - radius * radius;
    if (c <= 0.0f)
        return b < 0.0f ? 0.0f : -1.0f;
    const float disc = b * b - c;
    if (!(disc >= 0.0f))
        return -1.0f;
    const float t = -b - std::sqrt(disc);
    return t >= 0.0f && t <= length ? t : -1.0f;
}

float sweepBox(glm::vec2 p, glm::vec2 dir, float length, const PlanarBox& box, float inflate)
{
    const glm::vec2 rel = p - box.centre;
    const float pos[2] = {glm::dot(rel, box.axisU), glm::dot(rel, box.axisW)};
    const float d[2] = {glm::dot(dir, box.axisU), glm::dot(dir, box.axisW)};
    const float h[2] = {box.half.x + inflate, box.half.y + inflate};
    if (std::abs(pos[0]) <= h[0] && std::abs(pos[1]) <= h[1]) {
        // Inside: a hit only while moving toward the nearest face's interior side.
        const int axis = h[0] - std::abs(pos[0]) < h[1] - std::abs(pos[1]) ? 0 : 1;
        const float outward = pos[axis] >= 0.0f ? 1.0f : -1.0f;
        return d[axis] * outward < 0.0f ? 0.0f : -1.0f;
    }
    float tMin = 0.0f, tMax = length;
    for (int i = 0; i < 2; ++i) {
        if (std::abs(d[i]) < kTiny) {
            if (std::abs(pos[i]) > h[i])
                return -1.0f;
            continue;
        }
        float t1 = (-h[i] - pos[i]) / d[i];
        float t2 = (h[i] - pos[i]) / d[i];
        if (t1 > t2)
            std::swap(t1, t2);
        tMin = std::max(tMin, t1);
        tMax = std::min(tMax, t2);
        if (tMin > tMax)
            return -1.0f;
    }
    return tMin;
}

float raySegment(glm::vec2 p, glm::vec2 dir, float length, glm::vec2 a, glm::vec2 b)
{
    const glm::vec2 e = b - a;
    const float denom = cross2(dir, e);
    if (std::abs(denom) < kTiny * std::max(1.0f, glm::length(e)))
        return -1.0f;
    const float t = cross2(a - p, e) / denom;
    const float u = cross2(a - p, dir) / denom;
    return t >= 0.0f && t <= length && u >= 0.0f && u <= 1.0f ? t : -1.0f;
}

SurfaceDistance boxSurfaceDistance(glm::vec2 p, const PlanarBox& box)
{
    const glm::vec2 rel = p - box.centre;
    const glm::vec2 local{glm::dot(rel, box.axisU), glm::dot(rel, box.axisW)};
    const glm::vec2 clamped = glm::clamp(local, -box.half, box.half);
    SurfaceDistance s;
    if (clamped != local) {
        const glm::vec2 out = local - clamped;
        s.distance = glm::length(out);
        const glm::vec2 n = out / std::max(s.distance, kTiny);
        s.normal = box.axisU * n.x + box.axisW * n.y;
        return s;
    }
    // Inside: the nearest face decides (ties go to the u faces).
    const float du = box.half.x - std::abs(local.x), dw = box.half.y - std::abs(local.y);
    if (du <= dw) {
        s.distance = -du;
        s.normal = box.axisU * (local.x >= 0.0f ? 1.0f : -1.0f);
    } else {
        s.distance = -dw;
        s.normal = box.axisW * (local.y >= 0.0f ? 1.0f : -1.0f);
    }
    return s;
}

}  // namespace throng::sim::detail
