#include "export/detail/SetNodes.h"

#include "export/set/SetSolids.h"
#include "export/set/SetSurfaces.h"
#include "simcore/scene/SceneOrigin.h"
#include "simcore/scene/TerrainHeight.h"
#include "simcore/traffic/LightPhase.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstring>
#include <map>
#include <tuple>
#include <vector>

namespace throng::exporting::detail {

namespace {

// A material per colour (and lamp glow): matte, seen from both sides (the set's solids are
// wound either way).
class SetMaterials {
public:
    explicit SetMaterials(tinygltf::Model& model) : m_model(model) {}

    int of(glm::vec4 colour, bool glow)
    {
        const auto key = std::make_tuple(colour.r, colour.g, colour.b, colour.a, glow);
        if (const auto it = m_made.find(key); it != m_made.end())
            return it->second;
        tinygltf::Material m;
        m.name = glow ? "set_lamp" : "set_" + std::to_string(m_made.size());
        m.pbrMetallicRoughness.baseColorFactor = {colour.r, colour.g, colour.b, colour.a};
        m.pbrMetallicRoughness.metallicFactor = 0.0;
        m.pbrMetallicRoughness.roughnessFactor = 0.85;
        m.doubleSided = true;
        if (glow)
            m.emissiveFactor = {colour.r, colour.g, colour.b};
        m_model.materials.push_back(std::move(m));
        const int index = static_cast<int>(m_model.materials.size()) - 1;
        m_made.emplace(key, index);
        return index;
    }

private:
    tinygltf::Model& m_model;
    std::map<std::tuple<float, float, float, float, bool>, int> m_made;
};

// The mesh `name` of `solids`: a primitive per colour, POSITION and NORMAL interleaved.
// -1 for no triangles.
int addMesh(GltfBuilder& b, SetMaterials& materials, const SolidMesh& solids, const std::string& name)
{
    std::map<std::tuple<float, float, float, float, bool>, std::vector<const SolidVertex*>> byColour;
    for (const SolidVertex& v : solids.vertices())
        byColour[std::make_tuple(v.colour.r, v.colour.g, v.colour.b, v.colour.a, v.glow > 0.0f)].push_back(&v);
    if (byColour.empty())
        return -1;
    tinygltf::Mesh mesh;
    mesh.name = name;
    for (const auto& [key, vertices] : byColour) {
        constexpr std::size_t kStride = 24;
        std::vector<unsigned char> bytes(vertices.size() * kStride);
        glm::vec3 lo(1e30f), hi(-1e30f);
        for (std::size_t k = 0; k < vertices.size(); ++k) {
            std::memcpy(&bytes[k * kStride], glm::value_ptr(vertices[k]->position), 12);
            std::memcpy(&bytes[k * kStride + 12], glm::value_ptr(vertices[k]->normal), 12);
            lo = glm::min(lo, vertices[k]->position);
            hi = glm::max(hi, vertices[k]->position);
        }
        const int view = b.addView(b.append(bytes.data(), bytes.size()), bytes.size(), kStride,
                                   TINYGLTF_TARGET_ARRAY_BUFFER);
        tinygltf::Primitive p;
        p.mode = TINYGLTF_MODE_TRIANGLES;
        p.attributes["POSITION"] =
            b.addAccessor(view, 0, TINYGLTF_COMPONENT_TYPE_FLOAT, vertices.size(), TINYGLTF_TYPE_VEC3);
        b.model().accessors[p.attributes["POSITION"]].minValues = {lo.x, lo.y, lo.z};
        b.model().accessors[p.attributes["POSITION"]].maxValues = {hi.x, hi.y, hi.z};
        p.attributes["NORMAL"] =
            b.addAccessor(view, 12, TINYGLTF_COMPONENT_TYPE_FLOAT, vertices.size(), TINYGLTF_TYPE_VEC3);
        const auto [r, g, bl, a, glow] = key;
        p.material = materials.of({r, g, bl, a}, glow);
        mesh.primitives.push_back(std::move(p));
    }
    b.model().meshes.push_back(std::move(mesh));
    return static_cast<int>(b.model().meshes.size()) - 1;
}

int addNode(tinygltf::Model& model, const std::string& name, int mesh)
{
    tinygltf::Node node;
    node.name = name;
    node.mesh = mesh;
    model.nodes.push_back(std::move(node));
    return static_cast<int>(model.nodes.size()) - 1;
}

}  // namespace

int addSetNodes(GltfBuilder& b, AnimationChannels& channels, const sim::Scene& original, glm::dvec2 origin,
                const Clock& frames, float fps, std::size_t firstFrame)
{
    const sim::Scene scene = sim::shiftedScene(original, origin);
    tinygltf::Model& model = b.model();
    SetMaterials materials(model);
    std::vector<int> children;
    auto part = [&](const char* name, auto build) {
        SolidMesh solids;
        build(solids);
        if (const int mesh = addMesh(b, materials, solids, name); mesh >= 0)
            children.push_back(addNode(model, name, mesh));
    };
    part("set_ground", [&](SolidMesh& m) { SetSurfaces::addGround(scene, m); });
    part("set_lanes", [&](SolidMesh& m) { SetSurfaces::addLanes(scene, m); });
    part("set_crosswalks", [&](SolidMesh& m) { SetSurfaces::addCrosswalks(scene, m); });
    part("set_walls", [&](SolidMesh& m) { SetSolids::addWalls(scene, m); });
    part("set_obstacles", [&](SolidMesh& m) { SetSolids::addObstacles(scene, m); });
    // The poles and heads with every lamp dark; each lamp lit on top of its dark self.
    part("set_lights", [&](SolidMesh& m) {
        SetSolids::addLightPoles(scene, m);
        SetSolids::addLamps(scene.trafficLights, scene.terrain, std::nullopt, m);
    });
    if (!scene.trafficLights.empty()) {
        std::map<sim::LightPhase, int> litMesh;  // one lit lamp about its own middle, shared
        for (const sim::LightPhase lamp : SetSolids::kLamps) {
            SolidMesh lit;
            SetSolids::addLitLamp(lamp, lit);
            litMesh[lamp] = addMesh(b, materials, lit, "set_lamp_lit");
        }
        for (const sim::TrafficLight& light : scene.trafficLights) {
            const float ground = sim::terrainHeight(scene.terrain, light.position.x, light.position.y);
            for (const sim::LightPhase lamp : SetSolids::kLamps) {
                const int node =
                    addNode(model, "set_lamp_" + light.name + "_" + SetSolids::lampName(lamp), litMesh[lamp]);
                model.nodes[node].translation = {light.position.x, ground + SetSolids::lampHeightM(lamp),
                                                 light.position.y};
                // Lit (scale 1) on the frames its phase shows it, else nothing (scale 0).
                std::vector<float> times;
                std::vector<glm::vec3> scales;
                for (std::size_t f = 0; f < frames.times.size(); ++f) {
                    const bool lit = sim::lightPhaseAt(light, double(firstFrame + f) / double(fps)) == lamp;
                    if (!scales.empty() && (scales.back().x > 0.0f) == lit)
                        continue;
                    times.push_back(frames.times[f]);
                    scales.push_back(glm::vec3(lit ? 1.0f : 0.0f));
                }
                if (times.size() == 1)
                    model.nodes[node].scale = {scales[0].x, scales[0].y, scales[0].z};
                else
                    channels.addSampler(node, "scale", b.addTimes(times), b.addVec3Keys(scales), "STEP");
                children.push_back(node);
            }
        }
    }
    if (children.empty())
        return -1;
    const int set = addNode(model, "set", -1);
    model.nodes[set].children = children;
    model.scenes[0].nodes.push_back(set);
    return set;
}

}  // namespace throng::exporting::detail
