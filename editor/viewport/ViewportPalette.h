#pragma once
// The viewport's colours in one place (linear 0..1 RGBA, drawn without lighting in the
// top view), so renderers, the screenshot and the tests agree. Holds no GL state.

#include "export/set/SetColours.h"

#include <glm/vec4.hpp>

#include <cstddef>

namespace throng::editor::palette {

inline constexpr glm::vec4 kBackground{0.145f, 0.153f, 0.165f, 1.0f};   // outside the world bounds
inline constexpr glm::vec4 kGround = exporting::setcolours::kGround;       // inside the world bounds
inline constexpr glm::vec4 kGridMinor{0.290f, 0.302f, 0.322f, 1.0f};
inline constexpr glm::vec4 kGridMajor{0.345f, 0.357f, 0.380f, 1.0f};
inline constexpr glm::vec4 kBounds{0.560f, 0.580f, 0.610f, 1.0f};
inline constexpr glm::vec4 kWall = exporting::setcolours::kWall;
inline constexpr glm::vec4 kPathBand{0.224f, 0.290f, 0.380f, 1.0f};     // the radius band, opaque over the ground
inline constexpr glm::vec4 kPathLine{0.420f, 0.650f, 1.000f, 1.0f};
inline constexpr glm::vec4 kObstacleFill{0.455f, 0.404f, 0.349f, 1.0f};
inline constexpr glm::vec4 kObstacleEdge{0.690f, 0.620f, 0.545f, 1.0f};
inline constexpr glm::vec4 kObstacleSolid = exporting::setcolours::kObstacle;  // 3D view, lit
inline constexpr glm::vec4 kGoal{0.380f, 0.850f, 0.560f, 1.0f};
inline constexpr glm::vec4 kActionPoint{0.960f, 0.480f, 0.800f, 1.0f};
inline constexpr glm::vec4 kSource{0.250f, 0.820f, 0.800f, 1.0f};
inline constexpr glm::vec4 kMeasurement{0.330f, 0.560f, 1.000f, 1.0f};
inline constexpr glm::vec4 kLane = exporting::setcolours::kLane;
inline constexpr glm::vec4 kLaneEdge{0.420f, 0.435f, 0.455f, 1.0f};
inline constexpr glm::vec4 kLaneCentre = exporting::setcolours::kLaneCentre;
inline constexpr glm::vec4 kCrosswalkStripe = exporting::setcolours::kCrosswalkStripe;
inline constexpr glm::vec4 kLightHousing = exporting::setcolours::kLightHousing;
inline constexpr glm::vec4 kLightPole = exporting::setcolours::kLightPole;  // 3D view, lit
inline constexpr glm::vec4 kLightGreen = exporting::setcolours::kLightGreen;
inline constexpr glm::vec4 kLightYellow = exporting::setcolours::kLightYellow;
inline constexpr glm::vec4 kLightRed = exporting::setcolours::kLightRed;
inline constexpr glm::vec4 kLightUnknown = exporting::setcolours::kLightUnknown;
inline constexpr glm::vec4 kSpawnArea{0.700f, 0.700f, 0.720f, 1.0f};
inline constexpr glm::vec4 kFlowStroke{0.560f, 0.470f, 0.800f, 1.0f};
inline constexpr glm::vec4 kAgentNose{0.090f, 0.095f, 0.105f, 1.0f};
inline constexpr glm::vec4 kHeroWay{1.000f, 0.550f, 0.250f, 1.0f};
inline constexpr glm::vec4 kSelection{1.000f, 0.850f, 0.100f, 1.0f};
inline constexpr glm::vec4 kLayoutClash{1.000f, 0.250f, 0.250f, 1.0f};  // an agent the layout edits made clash
inline constexpr glm::vec4 kFlowArrow{0.700f, 0.620f, 0.950f, 0.75f};
inline constexpr glm::vec4 kTrail{1.000f, 0.780f, 0.300f, 0.90f};         // the newest part of a trail
// Steering annotations (SteeringOverlay).
inline constexpr glm::vec4 kViewCone{0.450f, 0.700f, 1.000f, 0.12f};
inline constexpr glm::vec4 kViewConeEdge{0.450f, 0.700f, 1.000f, 0.55f};
inline constexpr glm::vec4 kNeighbourLink{0.550f, 0.900f, 1.000f, 0.80f};
inline constexpr glm::vec4 kFeeler{1.000f, 0.600f, 0.200f, 0.95f};
inline constexpr glm::vec4 kVelocity{0.400f, 1.000f, 0.500f, 0.95f};
inline constexpr glm::vec4 kSteeringForce{1.000f, 1.000f, 1.000f, 0.95f};
inline constexpr glm::vec4 kPlannedPath{0.300f, 0.900f, 0.900f, 0.90f};
inline constexpr glm::vec4 kSteerTarget{1.000f, 0.350f, 0.850f, 0.95f};

// Colour of agents of type `typeIndex` (Scene::agentTypes order); repeats after 8 types.
glm::vec4 agentColour(std::size_t typeIndex);

}  // namespace throng::editor::palette
