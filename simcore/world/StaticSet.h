#pragma once
// The set a World's agents move in, static during a run, in the World's coordinates:
// walls, obstacles, goals, paths, traffic lights, crosswalks, the sketched flow, the
// terrain, the walkable bounds and the action points. Built once with the World (World.cpp); the step's
// phases read it and never change it.

#include "simcore/base/SegmentGrid.h"
#include "simcore/scene/Scene.h"
#include "simcore/scene/TerrainHeight.h"
#include "simcore/steering/Steering.h"
#include "simcore/world/ActionPoints.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace throng::sim {

// A crosswalk's strip: centre line a to b and half its width, m; light -1 = uncontrolled.
struct CrosswalkBox {
    glm::vec2 a, b;
    float halfWidth;
    int light;
};

// One segment of a sketched flow stroke and half its width, m.
struct FlowSegment {
    glm::vec2 a, b;
    float halfWidth;
};

struct StaticSet {
    SegmentGrid walls;  // walls and the 4 sides of box obstacles
    std::vector<CircleObstacle> circles;
    std::vector<BoxObstacle> boxes;
    SegmentGrid obstacleGrid;  // circles and boxes by their bounding boxes; index < circles = circle
    std::vector<Goal> goals;
    std::vector<std::vector<glm::vec3>> pathPoints;
    std::vector<Path> paths;
    std::vector<TrafficLight> lights;
    std::vector<CrosswalkBox> crosswalks;
    std::vector<FlowSegment> flow;
    Terrain terrain;
    WalkableBox bounds;
    std::vector<ActionPlace> actionPoints;

    // Anything to hold walkers out of: walls, box sides or circles (not in an open field).
    bool hasStatics() const { return !walls.segments().empty() || !circles.empty(); }
    // The ground's height under (x, z), m: the terrain's, 0 without one.
    float groundHeight(float x, float z) const { return terrainHeight(terrain, x, z); }
};

}  // namespace throng::sim
