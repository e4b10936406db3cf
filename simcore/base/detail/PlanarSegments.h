#pragma once
// Planar helpers on the ground plane (x, z): a point's ground coordinates, and segment
// tests. Shared by the step's phases (world/detail/StepGeometry.h) and the steering
// behaviours that meet walls (WallFollowing.cpp). Inline, no state.
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>

namespace throng::sim::detail {

inline glm::vec2 xz(glm::vec3 v) { return {v.x, v.z}; }

inline float cross(glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; }

// True when segment p0-p1 properly crosses segment a-b.
inline bool segmentsCross(glm::vec2 p0, glm::vec2 p1, glm::vec2 a, glm::vec2 b)
{
    const float d1 = cross(b - a, p0 - a), d2 = cross(b - a, p1 - a);
    const float d3 = cross(p1 - p0, a - p0), d4 = cross(p1 - p0, b - p0);
    return ((d1 > 0.0f && d2 < 0.0f) || (d1 < 0.0f && d2 > 0.0f)) &&
           ((d3 > 0.0f && d4 < 0.0f) || (d3 < 0.0f && d4 > 0.0f));
}

inline glm::vec2 closestOnSegment(glm::vec2 p, glm::vec2 a, glm::vec2 b)
{
    const glm::vec2 ab = b - a;
    const float len2 = glm::dot(ab, ab);
    const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
    return a + ab * t;
}

}  // namespace throng::sim::detail
