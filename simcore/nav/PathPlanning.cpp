// Load-time route planning for paths marked `plan: astar` (the cavalry leader's route
// through the cone field): one grid per clearance, A* leg by leg, string pulling within
// each leg. The waypoints themselves are kept exactly, so the author still decides where
// the route must pass.
#include "simcore/nav/PathPlanning.h"

#include "simcore/nav/NavGrid.h"
#include "simcore/nav/NavShapes.h"

#include <glm/geometric.hpp>

#include <map>

namespace throng::sim {

namespace {

float polylineLength(const std::vector<glm::vec2>& points)
{
    float length = 0.0f;
    for (std::size_t k = 1; k < points.size(); ++k)
        length += glm::distance(points[k - 1], points[k]);
    return length;
}

PlannedPath planOnGrid(const NavGrid& grid, const Path& path)
{
    PlannedPath out;
    if (path.points.empty())
        return out;
    AStar astar;
    out.points.push_back(path.points.front());
    for (std::size_t k = 0; k + 1 < path.points.size(); ++k) {
        const glm::vec2 from = path.points[k], to = path.points[k + 1];
        const NavPlan plan =
            astar.plan(grid, grid.nearestWalkable(grid.cellOf(from)), grid.nearestWalkable(grid.cellOf(to)));
        if (!plan.found()) {
            out.error += (out.error.empty() ? "" : "; ") + std::string("no way from waypoint ") + std::to_string(k) +
                         " to " + std::to_string(k + 1) + " (" + toString(plan.status) + ")";
            out.points.push_back(to);
            continue;
        }
        out.gridLengthM += plan.lengthM;
        // The plan's last waypoint is the goal cell's centre: the waypoint itself stands for it.
        for (std::size_t w = 0; w + 1 < plan.waypoints.size(); ++w)
            out.points.push_back(plan.waypoints[w]);
        out.points.push_back(to);
    }
    out.lengthM = polylineLength(out.points);
    return out;
}

NavGrid gridFor(const Scene& scene, const NavShapes& shapes, float clearanceM)
{
    // The grid blocks a cell by its centre; a planned path keeps its clearance from every
    // point of the cells it crosses, so the shapes are inflated by half a cell's diagonal more.
    NavGrid grid;
    const float cellM = scene.settings.navCellM;
    grid.build(shapes, scene.settings.boundsMin, scene.settings.boundsMax,
               NavGridParams{cellM, clearanceM + 0.70711f * cellM});
    return grid;
}

}  // namespace

PlannedPath planPath(const Scene& scene, const Path& path)
{
    return planOnGrid(gridFor(scene, navShapes(scene), path.clearanceM), path);
}

std::vector<Path> plannedPaths(const Scene& scene, std::vector<std::string>* errors)
{
    std::vector<Path> paths = scene.paths;
    const NavShapes shapes = navShapes(scene);
    std::map<float, NavGrid> grids;  // paths with the same clearance share one grid
    for (Path& p : paths) {
        if (!p.planned)
            continue;
        auto it = grids.find(p.clearanceM);
        if (it == grids.end())
            it = grids.emplace(p.clearanceM, gridFor(scene, shapes, p.clearanceM)).first;
        PlannedPath planned = planOnGrid(it->second, p);
        if (!planned.ok() && errors)
            errors->push_back("path '" + p.name + "': " + planned.error);
        p.points = std::move(planned.points);
    }
    return paths;
}

}  // namespace throng::sim
