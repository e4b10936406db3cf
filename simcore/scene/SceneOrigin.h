#pragma once
// Where a scene far from (0, 0) is simulated from. The World runs relative to this origin
// so that a set placed at map coordinates (1e6 m and more) moves exactly as the same set
// at (0, 0); what leaves simcore (frames, exports) adds the origin back once. Never
// rounds a coordinate that the shift can keep exact.

#include "simcore/scene/Scene.h"

#include <glm/vec2.hpp>

namespace throng::sim {

// Scenes whose bounds reach further than this from (0, 0) are simulated relative to their
// centre: beyond it a 32-bit float's spacing exceeds 1 mm, and a slow walker's step of
// a few centimetres starts to round.
constexpr double kFarSceneM = 8192.0;

// (0, 0) for a scene within kFarSceneM of the origin; else the centre of its bounds,
// rounded to whole metres (so that the shift of every float coordinate is exact).
glm::dvec2 simulationOrigin(const Scene& scene);

// The scene with every ground coordinate (x, z) less `origin`: bounds, agents, groups,
// paths, walls, obstacles, goals, terrain, flow strokes, lanes, crosswalks, lights,
// hero keyframes and sound sources. Heights, sizes and radii are unchanged.
Scene shiftedScene(const Scene& scene, glm::dvec2 origin);

// The spacing of 32-bit floats (m) at the scene's farthest ground coordinate: how finely
// the scene file's positions are held. 0 for an empty scene at the origin.
double coordinateSpacingM(const Scene& scene);

}  // namespace throng::sim
