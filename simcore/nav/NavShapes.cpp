#include "simcore/nav/NavShapes.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

namespace throng::sim {

bool NavBox::contains(glm::vec2 p) const
{
    const glm::vec2 d = p - centre;
    return std::abs(glm::dot(d, axisX)) <= halfSize.x && std::abs(glm::dot(d, axisZ)) <= halfSize.y;
}

NavShapes navShapes(const Scene& scene)
{
    NavShapes shapes;
    for (const Wall& w : scene.walls)
        for (std::size_t k = 0; k + 1 < w.points.size(); ++k)
            shapes.walls.push_back({w.points[k], w.points[k + 1]});
    for (const Obstacle& o : scene.obstacles) {
        if (o.shape == ObstacleShape::Circle) {
            shapes.circles.push_back({o.center, o.radiusM});
            continue;
        }
        // The same axes as World::buildStatics, so navigation and collision agree.
        const float a = glm::radians(o.angleDeg);
        shapes.boxes.push_back({o.center, {std::cos(a), -std::sin(a)}, {std::sin(a), std::cos(a)}, o.size * 0.5f});
    }
    return shapes;
}

void boxSides(const NavBox& box, Segment out[4])
{
    const glm::vec2 x = box.axisX * box.halfSize.x, z = box.axisZ * box.halfSize.y;
    const glm::vec2 c[4] = {box.centre - x - z, box.centre + x - z, box.centre + x + z, box.centre - x + z};
    for (int k = 0; k < 4; ++k)
        out[k] = {c[k], c[(k + 1) % 4]};
}

}  // namespace throng::sim
