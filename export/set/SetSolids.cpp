#include "export/set/SetSolids.h"

#include "export/set/SetColours.h"
#include "simcore/scene/TerrainHeight.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace throng::exporting {

namespace {

constexpr int kPostSegments = 8;
constexpr float kHeadRadiusM = 0.13f;
constexpr float kVisorRadiusM = 0.22f, kVisorThicknessM = 0.03f;

float ground(const sim::Scene& scene, glm::vec2 p)
{
    return sim::terrainHeight(scene.terrain, p.x, p.y);
}

int cylinderSegments(float radiusM)
{
    return std::clamp(int(radiusM * 16.0f), 16, 64);
}

}  // namespace

// A dark lamp keeps a trace of its colour (kDarkLampShade), so the head reads red-yellow-
// green unlit too.
const char* SetSolids::lampName(sim::LightPhase lamp)
{
    return lamp == sim::LightPhase::Red ? "red" : lamp == sim::LightPhase::Yellow ? "yellow" : "green";
}

void SetSolids::addLitLamp(sim::LightPhase lamp, SolidMesh& mesh)
{
    constexpr float kOver = 1.03f;  // just over the dark lamp
    mesh.addCylinder({0.0f, 0.0f}, kLampRadiusM * kOver, kHeadSegments, -kLampHalfHeightM * kOver,
                     kLampHalfHeightM * kOver, lampColour(lamp), true, 1.0f);
}

glm::vec4 SetSolids::lampColour(sim::LightPhase lamp)
{
    switch (lamp) {
    case sim::LightPhase::Green: return setcolours::kLightGreen;
    case sim::LightPhase::Yellow: return setcolours::kLightYellow;
    case sim::LightPhase::Red: return setcolours::kLightRed;
    }
    return setcolours::kLightUnknown;
}

float SetSolids::lampHeightM(sim::LightPhase lamp)
{
    // Red on top, as on every signal head; the lamps fill the head from its top down.
    const float pitch = (kHeadTopM - kHeadBottomM) / 3.0f;
    const int fromTop = lamp == sim::LightPhase::Red ? 0 : (lamp == sim::LightPhase::Yellow ? 1 : 2);
    return kHeadTopM - pitch * (0.5f + float(fromTop));
}

void SetSolids::addSet(const sim::Scene& scene, SolidMesh& mesh)
{
    addWalls(scene, mesh);
    addObstacles(scene, mesh);
    addLightPoles(scene, mesh);
}

void SetSolids::addWalls(const sim::Scene& scene, SolidMesh& mesh)
{
    const float half = 0.5f * kWallThicknessM;
    for (const sim::Wall& w : scene.walls) {
        for (std::size_t i = 0; i + 1 < w.points.size(); ++i) {
            const glm::vec2 a = w.points[i], b = w.points[i + 1];
            const float len = glm::length(b - a);
            if (!(len > 0.0f))
                continue;
            const glm::vec2 side = half * glm::vec2(-(b - a).y, (b - a).x) / len;
            const std::array<glm::vec2, 4> outline{a - side, b - side, b + side, a + side};
            // On sloping terrain a segment stands from its lower end's ground to its
            // height above the higher end's: never floating, never shorter than asked.
            const float ya = ground(scene, a), yb = ground(scene, b);
            mesh.addPrism(outline, std::min(ya, yb), std::max(ya, yb) + w.heightM, setcolours::kWall);
        }
        // A post at each corner fills the gap the two segments leave outside it.
        for (std::size_t i = 1; i + 1 < w.points.size(); ++i) {
            const float y = ground(scene, w.points[i]);
            mesh.addCylinder(w.points[i], half, kPostSegments, y, y + w.heightM, setcolours::kWall);
        }
    }
}

void SetSolids::addObstacles(const sim::Scene& scene, SolidMesh& mesh)
{
    for (const sim::Obstacle& o : scene.obstacles) {
        const float y = ground(scene, o.center);
        if (o.shape == sim::ObstacleShape::Circle)
            mesh.addCylinder(o.center, o.radiusM, cylinderSegments(o.radiusM), y, y + kObstacleHeightM,
                             setcolours::kObstacle);
        else
            mesh.addBox(o.center, o.size, glm::radians(o.angleDeg), y, y + kObstacleHeightM, setcolours::kObstacle);
    }
}

void SetSolids::addLightPoles(const sim::Scene& scene, SolidMesh& mesh)
{
    for (const sim::TrafficLight& light : scene.trafficLights) {
        const glm::vec2 p = light.position;
        const float y = ground(scene, p);
        mesh.addCylinder(p, kPoleRadiusM, kPostSegments, y, y + kHeadBottomM, setcolours::kLightPole);
        mesh.addCylinder(p, kHeadRadiusM, kHeadSegments, y + kHeadBottomM, y + kHeadTopM, setcolours::kLightHousing,
                         true);
        // A visor over each lamp: the head reads as three lamps from any side.
        for (sim::LightPhase lamp : kLamps) {
            const float top = y + lampHeightM(lamp) + kLampHalfHeightM;
            mesh.addCylinder(p, kVisorRadiusM, kHeadSegments, top, top + kVisorThicknessM, setcolours::kLightHousing,
                             true);
        }
    }
}

void SetSolids::addLamps(std::span<const sim::TrafficLight> lights, const sim::Terrain& terrain,
                         std::optional<double> timeS, SolidMesh& mesh)
{
    for (const sim::TrafficLight& light : lights) {
        const sim::LightPhase shown = timeS ? sim::lightPhaseAt(light, *timeS) : sim::LightPhase::Green;
        const float y = sim::terrainHeight(terrain, light.position.x, light.position.y);
        for (sim::LightPhase lamp : kLamps) {
            const bool lit = timeS && shown == lamp;
            const glm::vec4 c = lampColour(lamp);
            const glm::vec4 colour = lit ? c : glm::vec4(glm::vec3(c) * kDarkLampShade, 1.0f);
            const float mid = y + lampHeightM(lamp);
            mesh.addCylinder(light.position, kLampRadiusM, kHeadSegments, mid - kLampHalfHeightM,
                             mid + kLampHalfHeightM, colour, true, lit ? 1.0f : 0.0f);
        }
    }
}

}  // namespace throng::exporting
