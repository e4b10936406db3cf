#pragma once
// The largest sizes a scene may ask for: beyond these the World would exhaust memory or
// take hours to build, so loading reports them as errors before anything is allocated.
// Plain constants; docs/scene-format.md lists them.

#include <cstdint>

namespace throng::sim {

// Cells of the navigation grid: ceil(bounds width / nav_cell) x ceil(bounds depth / nav_cell),
// built when a type navigates, a path is planned or a flow stroke is drawn. About 30 bytes a
// cell with a sketched field, plus 12 per flow-field goal: a 2.2 km square at 0.5 m.
constexpr std::uint64_t kMaxNavCells = 20'000'000;
// Agents of one scene: placed agents, group counts, vehicles and heroes together
// (about 300 bytes each while stepping, more when frames are recorded).
constexpr std::uint64_t kMaxSceneAgents = 10'000'000;
// A group may start this many times as dense as its bodies pack (overlaps part in the
// first steps), or hold up to kDenseGroupFloor agents whatever its area.
constexpr double kDenseGroupFactor = 4.0;
constexpr std::uint32_t kDenseGroupFloor = 100;
// Metres of flow strokes: the sketched field takes a sample a metre (200 km of strokes).
constexpr double kMaxFlowStrokeLengthM = 200'000.0;
// Static geometry farther than this from the scene bounds draws a warning: no agent comes
// near it, and it only stretches the grids that index walls and obstacles.
constexpr float kFarGeometryM = 100'000.0f;

// Any coordinate or pair of numbers: past this, lengths and their squares lose all
// precision or overflow a float (1e30 m is a typo, not a place).
constexpr float kMaxCoordinateM = 1e9f;
// An obstacle's radius or side: larger swallows any set (and everyone in it).
constexpr float kMaxObstacleM = 10'000.0f;

}  // namespace throng::sim
