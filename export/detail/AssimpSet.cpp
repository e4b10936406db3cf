#include "export/detail/AssimpSet.h"

#include "export/set/SetSolids.h"
#include "export/set/SetSurfaces.h"
#include "simcore/scene/SceneOrigin.h"
#include "simcore/scene/TerrainHeight.h"
#include "simcore/traffic/LightPhase.h"

#include <glm/gtc/matrix_transform.hpp>

#include <map>
#include <tuple>

namespace throng::exporting::detail {

namespace {

// A rigid mesh per colour of `solids` under a node `name`; nothing for no triangles.
void addPart(AssimpScene& out, aiNode* parent, const std::string& name, const SolidMesh& solids)
{
    std::map<std::tuple<float, float, float, bool>, std::pair<std::vector<glm::vec3>, std::vector<glm::vec3>>> byColour;
    for (const SolidVertex& v : solids.vertices()) {
        auto& [positions, normals] = byColour[std::make_tuple(v.colour.r, v.colour.g, v.colour.b, v.glow > 0.0f)];
        positions.push_back(v.position);
        normals.push_back(v.normal);
    }
    if (byColour.empty())
        return;
    aiNode* node = out.addNode(parent, name);
    std::vector<unsigned> meshes;
    for (const auto& [key, vertices] : byColour) {
        const auto [r, g, b, glow] = key;
        const std::string material = "set_" + std::to_string(int(r * 255.0f + 0.5f)) + "_" +
                                     std::to_string(int(g * 255.0f + 0.5f)) + "_" +
                                     std::to_string(int(b * 255.0f + 0.5f)) + (glow ? "_lit" : "");
        meshes.push_back(out.addRigidMesh(name + "_" + std::to_string(meshes.size()), vertices.first, vertices.second,
                                          out.material(material, {r, g, b}, glow)));
    }
    out.setMeshes(node, meshes);
}


}  // namespace

std::vector<std::pair<double, glm::vec3>> stepKeys(const std::vector<std::uint8_t>& on, float fps, glm::vec3 off,
                                                   glm::vec3 onValue)
{
    constexpr double kJustBefore = 1e-3;  // s: the old value holds until then
    std::vector<std::pair<double, glm::vec3>> keys;
    for (std::size_t f = 0; f < on.size(); ++f) {
        if (f > 0 && on[f] == on[f - 1])
            continue;
        const double t = double(f) / double(fps);
        if (f > 0)
            keys.emplace_back(t - kJustBefore, on[f - 1] ? onValue : off);
        keys.emplace_back(t, on[f] ? onValue : off);
    }
    if (on.size() > 1)  // the curve spans the shot
        keys.emplace_back(double(on.size() - 1) / double(fps), on.back() ? onValue : off);
    return keys;
}

void addAssimpSet(AssimpScene& out, aiNode* parent, const sim::Scene& original, glm::dvec2 origin, std::size_t frames,
                  float fps, std::size_t firstFrame)
{
    const sim::Scene scene = sim::shiftedScene(original, origin);
    aiNode* set = out.addNode(parent, "set");
    auto part = [&](const char* name, auto build) {
        SolidMesh solids;
        build(solids);
        addPart(out, set, name, solids);
    };
    part("set_ground", [&](SolidMesh& m) { SetSurfaces::addGround(scene, m); });
    part("set_lanes", [&](SolidMesh& m) { SetSurfaces::addLanes(scene, m); });
    part("set_crosswalks", [&](SolidMesh& m) { SetSurfaces::addCrosswalks(scene, m); });
    part("set_walls", [&](SolidMesh& m) { SetSolids::addWalls(scene, m); });
    part("set_obstacles", [&](SolidMesh& m) { SetSolids::addObstacles(scene, m); });
    part("set_lights", [&](SolidMesh& m) {
        SetSolids::addLightPoles(scene, m);
        SetSolids::addLamps(scene.trafficLights, scene.terrain, std::nullopt, m);
    });
    for (const sim::TrafficLight& light : scene.trafficLights) {
        const float ground = sim::terrainHeight(scene.terrain, light.position.x, light.position.y);
        for (const sim::LightPhase lamp : SetSolids::kLamps) {
            SolidMesh lit;
            SetSolids::addLitLamp(lamp, lit);
            const std::string name = "set_lamp_" + light.name + "_" + SetSolids::lampName(lamp);
            const glm::vec3 at(light.position.x, ground + SetSolids::lampHeightM(lamp), light.position.y);
            aiNode* node = out.addNode(set, name, toAssimp(glm::translate(glm::mat4(1.0f), at)));
            std::vector<glm::vec3> positions, normals;
            for (const SolidVertex& v : lit.vertices()) {
                positions.push_back(v.position);
                normals.push_back(v.normal);
            }
            const glm::vec3 rgb(SetSolids::lampColour(lamp));
            const unsigned material = out.material(std::string("set_lamp_") + SetSolids::lampName(lamp), rgb, true);
            out.setMeshes(node, {out.addRigidMesh(name, positions, normals, material)});
            std::vector<std::uint8_t> on(frames);
            for (std::size_t f = 0; f < frames; ++f)
                on[f] = sim::lightPhaseAt(light, double(firstFrame + f) / double(fps)) == lamp ? 1 : 0;
            AssimpScene::Channel channel;
            channel.translation = {{0.0, at}};
            channel.rotation = {{0.0, glm::quat(1.0f, 0.0f, 0.0f, 0.0f)}};
            channel.scale = stepKeys(on, fps, glm::vec3(kHiddenScale), glm::vec3(1.0f));
            out.addChannel(name, std::move(channel));
        }
    }
}

}  // namespace throng::exporting::detail
