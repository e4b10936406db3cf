#pragma once
// Small planar geometry and tuning constants shared by the step's phases (WorldStep.cpp,
// WorldSteer.cpp). Internal to simcore/world; inline, no state.

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

// Most walls and obstacles one agent considers in a step.
constexpr std::size_t kMaxNearWalls = 16, kMaxNearObstacles = 8;
// How near its own spot in the goal area an agent stops for good.
constexpr float kSpotToleranceM = 0.1f;
// How quickly an agent with nowhere to go brakes to a stand, s.
constexpr float kStandStillResponseS = 0.5f;
// Inside its goal, an agent this near (body to body) a stopped agent settles too.
constexpr float kSettleGapM = 0.05f;
// Overlap tolerance: touching within 1 cm is contact, not overlap.
constexpr float kOverlapToleranceM = 0.01f;

}  // namespace throng::sim::detail
