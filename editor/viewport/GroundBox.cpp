#include "editor/viewport/GroundBox.h"

#include "simcore/scene/SpawnArea.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace throng::editor {

void GroundBox::include(glm::vec2 point, float radiusM)
{
    const glm::vec2 lo = point - glm::vec2(radiusM), hi = point + glm::vec2(radiusM);
    if (empty) {
        min = lo;
        max = hi;
        empty = false;
        return;
    }
    min = glm::min(min, lo);
    max = glm::max(max, hi);
}

void GroundBox::include(const GroundBox& other)
{
    if (other.empty)
        return;
    include(other.min);
    include(other.max);
}

GroundBox setExtent(const sim::Scene& scene)
{
    GroundBox box;
    auto polyline = [&](const std::vector<glm::vec2>& points, float radiusM) {
        for (glm::vec2 p : points)
            box.include(p, radiusM);
    };
    for (const sim::Wall& w : scene.walls)
        polyline(w.points, 0.0f);
    for (const sim::Path& p : scene.paths)
        polyline(p.points, p.radiusM);
    for (const sim::Lane& l : scene.lanes)
        polyline(l.points, 0.5f * l.widthM);
    for (const sim::FlowStroke& f : scene.flowStrokes)
        polyline(f.points, 0.5f * f.widthM);
    for (const sim::Obstacle& o : scene.obstacles) {
        const float r = o.shape == sim::ObstacleShape::Circle ? o.radiusM : 0.5f * glm::length(o.size);
        box.include(o.center, r);
    }
    for (const sim::Goal& g : scene.goals)
        box.include(g.position, g.radiusM);
    for (const sim::Crosswalk& c : scene.crosswalks) {
        box.include(c.from, 0.5f * c.widthM);
        box.include(c.to, 0.5f * c.widthM);
    }
    for (const sim::TrafficLight& t : scene.trafficLights)
        box.include(t.position, 1.0f);
    for (const sim::SpawnGroup& g : scene.groups) {
        const sim::GroundBounds area = sim::spawnAreaBounds(g);
        box.include(area.min);
        box.include(area.max);
    }
    for (const sim::Agent& a : scene.agents) {
        const sim::AgentType* type = scene.findAgentType(a.type);
        box.include({a.position.x, a.position.z}, type ? type->radiusM : 0.0f);
    }
    return box;
}

}  // namespace throng::editor
