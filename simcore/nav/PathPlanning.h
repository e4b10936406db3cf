#pragma once
// Plans a scene's `plan: astar` paths: between each waypoint and the next, the shortest way
// round the scene's walls and obstacles on a NavGrid inflated by the path's clearance,
// smoothed by line of sight so only the corners remain. Pure: reads the scene, returns
// polylines; never changes the scene and never moves agents.

#include "simcore/nav/AStar.h"
#include "simcore/scene/Scene.h"

#include <glm/vec2.hpp>

#include <string>
#include <vector>

namespace throng::sim {

struct PlannedPath {
    std::vector<glm::vec2> points;  // the waypoints and the corners between them, in order
    float lengthM = 0.0f;           // along points, m
    float gridLengthM = 0.0f;       // the sum of the legs' A* lengths on the 8-connected grid, m
    std::string error;              // empty when every leg was planned; else the legs that were not
                                    // (those legs stay straight lines between their waypoints)
    bool ok() const { return error.empty(); }
};

// The planned way along path.points (path.planned need not be set). Cells of
// scene.settings.navCellM; every point of the result keeps more than path.clearanceM from
// every wall and obstacle, except where a waypoint itself lies closer.
PlannedPath planPath(const Scene& scene, const Path& path);

// scene.paths with every planned path's points replaced by its planned way (others as
// they are); `errors` gets one line per path that could not be planned in full.
std::vector<Path> plannedPaths(const Scene& scene, std::vector<std::string>* errors = nullptr);

}  // namespace throng::sim
