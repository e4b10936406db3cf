#include "simcore/scene/SpawnArea.h"

#include "simcore/scene/GroundPolygon.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace throng::sim {

double spawnAreaM2(const SpawnGroup& g)
{
    switch (g.shape) {
    case AreaShape::Circle: return 3.14159265358979 * double(g.radiusM) * double(g.radiusM);
    case AreaShape::Polygon: return polygonArea(g.points);
    case AreaShape::Rect: break;
    }
    return double(g.max.x - g.min.x) * double(g.max.y - g.min.y);
}

GroundBounds spawnAreaBounds(const SpawnGroup& g)
{
    switch (g.shape) {
    case AreaShape::Circle: return {g.center - glm::vec2(g.radiusM), g.center + glm::vec2(g.radiusM)};
    case AreaShape::Polygon: {
        if (g.points.empty())
            return {};
        GroundBounds b{g.points[0], g.points[0]};
        for (const glm::vec2 p : g.points) {
            b.min = glm::min(b.min, p);
            b.max = glm::max(b.max, p);
        }
        return b;
    }
    case AreaShape::Rect: break;
    }
    return {g.min, g.max};
}

bool spawnAreaContains(const SpawnGroup& g, glm::vec2 p)
{
    switch (g.shape) {
    case AreaShape::Circle: return glm::dot(p - g.center, p - g.center) <= g.radiusM * g.radiusM;
    case AreaShape::Polygon: return polygonContains(g.points, p);
    case AreaShape::Rect: break;
    }
    return p.x >= g.min.x && p.y >= g.min.y && p.x <= g.max.x && p.y <= g.max.y;
}

glm::vec2 clampToSpawnArea(const SpawnGroup& g, glm::vec2 p)
{
    switch (g.shape) {
    case AreaShape::Circle:
        if (const glm::vec2 d = p - g.center; glm::dot(d, d) > g.radiusM * g.radiusM)
            return g.center + d * (g.radiusM / glm::length(d));
        return p;
    case AreaShape::Polygon:
        return g.points.size() < 3 || polygonContains(g.points, p) ? p : nearestOnPolygonOutline(g.points, p);
    case AreaShape::Rect: break;
    }
    return glm::clamp(p, g.min, g.max);
}

}  // namespace throng::sim
