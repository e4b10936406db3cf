#pragma once
// Small planar geometry shared by the step's phases (WorldStep.cpp, Steer.cpp), and
// their constants (StepConstants.h). Internal to simcore/world; inline, no state.
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

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

// An agent's own spot in its goal's disk (centre, radius) from two uniform draws u, v in
// [0, 1): uniform over 80 % of the disk, so a crowd sharing a goal spreads over it instead
// of converging on one point. For an exit, over 80 % of the disk less the body's radius:
// a disk placed across a door as wide as itself has its rim on the door posts, and a walker
// aiming at a spot near the rim pressed into the wall beside the door, just outside the
// disk, for good (issue 23).
inline glm::vec2 goalSpot(glm::vec2 centre, float radiusM, bool exit, float bodyRadiusM, float u, float v)
{
    const float reach = exit ? std::max(0.0f, radiusM - bodyRadiusM) : radiusM;
    const float r = 0.8f * reach * std::sqrt(u);
    const float a = 6.28318531f * v;
    return centre + r * glm::vec2(std::cos(a), std::sin(a));
}

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
