#pragma once
// Ground-plane (x, z) queries the avoidance behaviours share: swept-circle casts against
// circles, boxes and segments, and closest points. Internal to simcore/steering; pure,
// allocation-free, and finite for degenerate shapes (zero radius, zero-length segments).
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include "simcore/base/detail/PlanarSegments.h"
#include "simcore/steering/SteeringGeometry.h"

#include <glm/vec2.hpp>

namespace throng::sim::detail {

// A BoxObstacle in its own planar frame: u along axis, w across it.
struct PlanarBox {
    glm::vec2 centre{0.0f};
    glm::vec2 axisU{1.0f, 0.0f};  // unit
    glm::vec2 axisW{0.0f, 1.0f};  // unit, perpendicular to axisU
    glm::vec2 half{0.0f};         // m, >= 0
};
PlanarBox planarBox(const BoxObstacle& box);

// Where a point moving from p along unit dir first comes within `radius` of the circle's
// centre, as a distance in [0, length]; -1 when it does not. A point already within counts as a
// hit at 0 only while it is moving closer.
float sweepCircle(glm::vec2 p, glm::vec2 dir, float length, glm::vec2 centre, float radius);

// The same against the box grown by `inflate` on every side (corners left square: conservative).
float sweepBox(glm::vec2 p, glm::vec2 dir, float length, const PlanarBox& box, float inflate);

// Where the ray p + dir * t (t in [0, length]) meets segment a-b; -1 when it does not or when they
// are parallel.
float raySegment(glm::vec2 p, glm::vec2 dir, float length, glm::vec2 a, glm::vec2 b);

// Signed distance from p to the box's surface (negative inside) and the outward normal there.
struct SurfaceDistance {
    float distance = 0.0f;   // m
    glm::vec2 normal{0.0f};  // unit, pointing out of the shape toward p
};
SurfaceDistance boxSurfaceDistance(glm::vec2 p, const PlanarBox& box);

}  // namespace throng::sim::detail
