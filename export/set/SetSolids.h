#pragma once
// The set as the 3D view stands it up: walls extruded to their height, obstacles as
// cylinders and boxes, traffic lights as poles with a head of three lamps, the lit one
// following the phase. Builds SolidMesh triangles from plain scene data; never touches
// GL or the simulation, and adds nothing flat (SetGeometryBuilder draws the ground).

#include "export/set/SolidMesh.h"
#include "simcore/scene/Scene.h"
#include "simcore/traffic/LightPhase.h"

#include <array>
#include <optional>
#include <span>

namespace throng::exporting {

class SetSolids {
public:
    static constexpr float kWallThicknessM = 0.2f;
    // Obstacles have no height in the scene (agents only go round them): the 3D view
    // stands every one this high, about a bollard, a bench or a kiosk's counter.
    static constexpr float kObstacleHeightM = 1.0f;
    // A signal head of three lamps, red on top, on a pole (heights above the ground).
    static constexpr float kPoleRadiusM = 0.07f;
    static constexpr float kHeadBottomM = 2.4f;
    static constexpr float kHeadTopM = 3.35f;
    static constexpr float kLampRadiusM = 0.17f;
    static constexpr float kLampHalfHeightM = 0.12f;

    // Walls, obstacles and the lights' poles and heads, standing on the scene's terrain.
    // The lamps are not included (see addLamps).
    static void addSet(const sim::Scene& scene, SolidMesh& mesh);
    // Each light's three lamps: the one its phase at `timeS` shows lit, the others dark;
    // all dark when the time is unknown.
    static void addLamps(std::span<const sim::TrafficLight> lights, const sim::Terrain& terrain,
                         std::optional<double> timeS, SolidMesh& mesh);
    // The height of a lamp's middle above the light's ground, m.
    static float lampHeightM(sim::LightPhase lamp);
    // A lamp's colour when lit (dark lamps keep a trace of it).
    static glm::vec4 lampColour(sim::LightPhase lamp);
    // "red", "yellow" or "green": how the exports name a lamp.
    static const char* lampName(sim::LightPhase lamp);
    // One lamp lit, about its own middle, a little larger than its dark self so that it
    // covers it where an export stands it over the head (glowing in its colour).
    static void addLitLamp(sim::LightPhase lamp, SolidMesh& mesh);
    // The three lamps of a head, red on top.
    static constexpr std::array<sim::LightPhase, 3> kLamps{sim::LightPhase::Red, sim::LightPhase::Yellow,
                                                           sim::LightPhase::Green};
    static constexpr float kDarkLampShade = 0.22f;
    static constexpr int kHeadSegments = 16;

    // The parts addSet adds, one at a time (the glTF export names a node for each).
    static void addWalls(const sim::Scene& scene, SolidMesh& mesh);
    static void addObstacles(const sim::Scene& scene, SolidMesh& mesh);
    static void addLightPoles(const sim::Scene& scene, SolidMesh& mesh);
};

}  // namespace throng::exporting
