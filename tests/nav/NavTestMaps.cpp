#include "NavTestMaps.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace throng::test {

using namespace throng::sim;

NavGrid randomGrid(std::mt19937& gen, int cols, int rows, float density)
{
    NavGrid grid(cols, rows, {0.0f, 0.0f}, 1.0f);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int z = 0; z < rows; ++z)
        for (int x = 0; x < cols; ++x)
            if (u(gen) < density)
                grid.setWalkable({x, z}, false);
    return grid;
}

std::vector<double> bruteForceDistances(const NavGrid& grid, NavCell source)
{
    const int n = grid.cellCount();
    std::vector<double> d(std::size_t(n), -1.0);
    std::vector<bool> done(std::size_t(n), false);
    if (!grid.walkable(source))
        return d;
    d[std::size_t(grid.index(source))] = 0.0;
    for (;;) {
        int best = -1;
        for (int i = 0; i < n; ++i)
            if (!done[std::size_t(i)] && d[std::size_t(i)] >= 0.0 && (best < 0 || d[std::size_t(i)] < d[std::size_t(best)]))
                best = i;
        if (best < 0)
            return d;
        done[std::size_t(best)] = true;
        const NavCell c = grid.cellAt(best);
        for (int dz = -1; dz <= 1; ++dz)
            for (int dx = -1; dx <= 1; ++dx) {
                const NavCell nb{c.x + dx, c.z + dz};
                if ((dx == 0 && dz == 0) || !grid.walkable(nb))
                    continue;
                if (dx != 0 && dz != 0 && (!grid.walkable({c.x + dx, c.z}) || !grid.walkable({c.x, c.z + dz})))
                    continue;
                const double w = d[std::size_t(best)] + ((dx != 0 && dz != 0) ? std::sqrt(2.0) : 1.0);
                double& t = d[std::size_t(grid.index(nb))];
                if (t < 0.0 || w < t)
                    t = w;
            }
    }
}

bool legalWalk(const NavGrid& grid, const std::vector<NavCell>& cells)
{
    for (std::size_t k = 0; k < cells.size(); ++k) {
        if (!grid.walkable(cells[k]))
            return false;
        if (k == 0)
            continue;
        const int dx = cells[k].x - cells[k - 1].x, dz = cells[k].z - cells[k - 1].z;
        if (std::abs(dx) > 1 || std::abs(dz) > 1 || (dx == 0 && dz == 0))
            return false;
        if (dx != 0 && dz != 0
            && (!grid.walkable({cells[k - 1].x + dx, cells[k - 1].z}) || !grid.walkable({cells[k - 1].x, cells[k - 1].z + dz})))
            return false;
    }
    return true;
}

bool polylineStaysWalkable(const NavGrid& grid, const std::vector<NavCell>& corners, float stepM)
{
    for (std::size_t k = 1; k < corners.size(); ++k) {
        const glm::vec2 a = grid.centre(corners[k - 1]), b = grid.centre(corners[k]);
        const int steps = std::max(1, int(std::ceil(glm::distance(a, b) / stepM)));
        for (int i = 0; i <= steps; ++i) {
            const glm::vec2 p = a + (b - a) * (float(i) / float(steps));
            // A point exactly on a cell edge belongs to both cells; accept either walkable one.
            const NavCell c = grid.cellOf(p), lo = grid.cellOf(p - glm::vec2(1e-4f));
            if (!grid.walkable(c) && !grid.walkable(lo) && !grid.walkable({c.x, lo.z}) && !grid.walkable({lo.x, c.z}))
                return false;
        }
    }
    return true;
}

float pointSegmentDistance(glm::vec2 p, glm::vec2 a, glm::vec2 b)
{
    const glm::vec2 ab = b - a;
    const float len2 = glm::dot(ab, ab);
    const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
    return glm::distance(p, a + ab * t);
}

Scene fieldTestScene(int which)
{
    Scene s;
    s.settings.boundsMin = {0.0f, 0.0f};
    s.settings.boundsMax = {30.0f, 20.0f};
    if (which == 1) {  // a room with one door in its east wall, the goal outside
        s.walls.push_back({"room", {{5, 4}, {20, 4}, {20, 9}}});
        s.walls.push_back({"room2", {{20, 11}, {20, 16}, {5, 16}, {5, 4}}});
        s.obstacles.push_back({"pillar", ObstacleShape::Circle, {12, 10}, 1.5f, {1, 1}, 0.0f});
    } else if (which == 2) {  // a maze of walls and boxes
        s.walls.push_back({"a", {{6, 0}, {6, 14}}});
        s.walls.push_back({"b", {{12, 20}, {12, 6}}});
        s.walls.push_back({"c", {{18, 0}, {18, 12}, {24, 12}}});
        s.obstacles.push_back({"crate", ObstacleShape::Box, {24, 5}, 0.5f, {3, 2}, 30.0f});
        s.obstacles.push_back({"cone", ObstacleShape::Circle, {3, 16}, 1.0f, {1, 1}, 0.0f});
    } else {  // open ground with a few cones
        for (int k = 0; k < 6; ++k)
            s.obstacles.push_back({"cone", ObstacleShape::Circle, {4.0f + 4.0f * float(k), 6.0f + 3.0f * float(k % 3)}, 0.8f, {1, 1}, 0.0f});
    }
    return s;
}

float angleDeg(glm::vec2 a, glm::vec2 b)
{
    const float la = glm::length(a), lb = glm::length(b);
    if (la <= 0.0f || lb <= 0.0f)
        return 180.0f;
    return glm::degrees(std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0f, 1.0f)));
}

}  // namespace throng::test
