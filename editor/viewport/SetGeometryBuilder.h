#pragma once
// Turns the set of a scene (bounds, lanes, crosswalks, paths, goals, action points, sources,
// obstacles, walls, spawn areas, flow strokes and their field, hero ways, traffic lights)
// into ShapeMesh triangles in draw order.
// Reads plain scene data only; never touches GL or the simulation.

#include "editor/viewport/ShapeMesh.h"
#include "simcore/scene/Scene.h"

#include <optional>
#include <span>

namespace throng::editor {

class SetGeometryBuilder {
public:
    // The static set, back to front. Traffic lights are not included (see addLights).
    static void addSet(const sim::Scene& scene, ShapeMesh& mesh);
    // Signal heads and their stop lines coloured by the phase at `timeS`; grey when the
    // time is unknown.
    static void addLights(const sim::Scene& scene, std::optional<double> timeS, ShapeMesh& mesh);

private:
    static void addBounds(const sim::Settings& settings, ShapeMesh& mesh);
    static void addLanes(std::span<const sim::Lane> lanes, ShapeMesh& mesh);
    static void addCrosswalks(std::span<const sim::Crosswalk> crosswalks, ShapeMesh& mesh);
    static void addSpawnAreas(std::span<const sim::SpawnGroup> groups, ShapeMesh& mesh);
    static void addFlowStrokes(std::span<const sim::FlowStroke> strokes, ShapeMesh& mesh);
    // Arrows on a coarse grid where the strokes steer the crowd (World::flowDirection's
    // rule: the nearest stroke segment whose band holds the point).
    static void addFlowField(const sim::Scene& scene, ShapeMesh& mesh);
    static void addHeroes(std::span<const sim::Hero> heroes, ShapeMesh& mesh);
    static void addPaths(std::span<const sim::Path> paths, ShapeMesh& mesh);
    static void addGoals(std::span<const sim::Goal> goals, ShapeMesh& mesh);
    // A ring, a dot at the centre, and an arrow to the facing where the point sets one.
    static void addActionPoints(std::span<const sim::ActionPoint> points, ShapeMesh& mesh);
    // A source's line or rectangle, with an arrow from its middle the way its agents head
    // off: its heading, else toward its goal or its path's first point, else square to the line.
    static void addSources(const sim::Scene& scene, ShapeMesh& mesh);
    // A measurement line with an arrow from its middle to its forward side (the way a
    // crossing counts as forward), or an area's outline dashed.
    static void addMeasurements(std::span<const sim::Measurement> measurements, ShapeMesh& mesh);
    static void addObstacles(std::span<const sim::Obstacle> obstacles, ShapeMesh& mesh);
    static void addWalls(std::span<const sim::Wall> walls, ShapeMesh& mesh);
    static void addChevrons(std::span<const glm::vec2> points, bool closed, float sizeM, glm::vec4 colour,
                            ShapeMesh& mesh);
};

}  // namespace throng::editor
