#pragma once
// The static geometry behaviours steer around or along: obstacles, walls, path spines and
// walkable regions, as plain structs over caller-owned data. Never owns or copies points.
// Obstacles and walls are vertical prisms of unlimited height: only (x, z) counts.

#include <glm/vec3.hpp>
#include <glm/vec2.hpp>

#include <span>

namespace throng::sim {

// A vertical cylinder.
struct CircleObstacle {
    glm::vec3 centre{0.0f};  // m; y ignored
    float radius = 0.5f;     // m, >= 0
};

// A vertical box at any rotation about y.
struct BoxObstacle {
    glm::vec3 centre{0.0f};                // m; y ignored
    glm::vec3 axis{1.0f, 0.0f, 0.0f};      // unit, horizontal: the box's own x axis
    glm::vec2 halfSize{0.5f, 0.5f};        // m, >= 0: half extents along axis and across it
};

// A wall segment from a to b; thickness zero, both faces solid.
struct WallSegment {
    glm::vec3 a{0.0f};  // m; y ignored
    glm::vec3 b{0.0f};  // m; y ignored
};

// A path: the polyline spine through points plus a radius. Points are used in 3D.
struct SteeringPath {
    std::span<const glm::vec3> points;  // >= 1 point; repeated points (zero-length segments) are fine
    float radius = 1.0f;                // m, >= 0: half width of the path
    bool closed = false;                // true: the last point joins the first
};

// An axis-aligned walkable region. Ground agents give a y range that contains them.
struct WalkableBox {
    glm::vec3 min{-1.0f};  // m
    glm::vec3 max{1.0f};   // m, >= min on every axis
};

// A walkable simple polygon in the ground plane, either winding, inside by the even-odd rule.
struct WalkablePolygon {
    std::span<const glm::vec3> vertices;  // >= 3 vertices, (x, z) used, closed implicitly
};

}  // namespace throng::sim
