#pragma once
// Small planar geometry shared by the step's phases (WorldStep.cpp, WorldSteer.cpp), and
// their constants (StepConstants.h). Internal to simcore/world; inline, no state.

#include "simcore/world/detail/StepConstants.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

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

inline bool isFinite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace throng::sim::detail
