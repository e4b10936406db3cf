#pragma once
// The solid shapes of a scene as navigation sees them: wall segments, circles and
// rotated boxes in the ground plane (x, z). Plain data read from the Scene; never
// inflated here and never changed by a simulation step.

#include "simcore/scene/Scene.h"
#include "simcore/base/SegmentGrid.h"

#include <glm/vec2.hpp>

#include <vector>

namespace throng::sim {

struct NavCircle {
    glm::vec2 centre{0.0f};
    float radiusM = 0.5f;  // m, >= 0
};

struct NavBox {
    glm::vec2 centre{0.0f};
    glm::vec2 axisX{1.0f, 0.0f};  // unit: the box's own x axis in (x, z)
    glm::vec2 axisZ{0.0f, 1.0f};  // unit, perpendicular to axisX
    glm::vec2 halfSize{0.5f};     // m, >= 0, along axisX and axisZ
    bool contains(glm::vec2 p) const;
};

struct NavShapes {
    std::vector<Segment> walls;  // wall polylines, one segment each (box sides are in boxes)
    std::vector<NavCircle> circles;
    std::vector<NavBox> boxes;
};

// Scene walls and obstacles, with box angles turned as World turns them
// (counter-clockwise seen from above, +y up, z south).
NavShapes navShapes(const Scene& scene);

// The four sides of a box, in order around it.
void boxSides(const NavBox& box, Segment out[4]);

}  // namespace throng::sim
