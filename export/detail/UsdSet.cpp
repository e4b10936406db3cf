#include "export/detail/UsdSet.h"

#include "export/detail/UsdMesh.h"
#include "export/detail/UsdText.h"
#include "export/set/SetSolids.h"
#include "export/set/SetSurfaces.h"
#include "simcore/scene/SceneOrigin.h"
#include "simcore/scene/TerrainHeight.h"
#include "simcore/traffic/LightPhase.h"

#include <map>
#include <tuple>
#include <vector>

namespace throng::exporting::detail {

namespace {

using ColourKey = std::tuple<float, float, float, bool>;

// One Mesh of the triangles `vertices` (a triangle list), named `name`, bound to `material`.
void writeTriangles(std::string& out, int depth, const std::string& name,
                    const std::vector<const SolidVertex*>& vertices, const std::string& material,
                    const std::string& specifier = "def Mesh")
{
    UsdMeshData data;
    for (const SolidVertex* v : vertices) {
        data.indices.push_back(static_cast<unsigned>(data.points.size()));
        data.points.push_back(v->position);
        data.normals.push_back(v->normal);
    }
    data.material = material;
    data.displayColour = glm::vec3(vertices.front()->colour);
    data.doubleSided = true;  // the solids are wound either way
    writeUsdMesh(out, depth, specifier, name, data);
}

// The part `name` of `solids`: an Xform with a Mesh per colour. Nothing for no triangles.
void writeSetPart(std::string& out, int depth, const std::string& name, const SolidMesh& solids,
                  UsdMaterials& materials)
{
    std::map<ColourKey, std::vector<const SolidVertex*>> byColour;
    for (const SolidVertex& v : solids.vertices())
        byColour[std::make_tuple(v.colour.r, v.colour.g, v.colour.b, v.glow > 0.0f)].push_back(&v);
    if (byColour.empty())
        return;
    indent(out, depth);
    out += "def Xform " + usdQuoted(name) + "\n";
    indent(out, depth);
    out += "{\n";
    int k = 0;
    for (const auto& [key, vertices] : byColour) {
        const auto [r, g, b, glow] = key;
        std::string colourName = "set_";
        appendUsdRounded(colourName, r, 3);
        colourName += "_";
        appendUsdRounded(colourName, g, 3);
        colourName += "_";
        appendUsdRounded(colourName, b, 3);
        const std::string material = materials.path(colourName + (glow ? "_lit" : ""), {r, g, b}, 0.85f, glow);
        writeTriangles(out, depth + 1, "colour" + std::to_string(k++), vertices, material);
    }
    indent(out, depth);
    out += "}\n";
}


}  // namespace

bool writeUsdSet(std::string& out, int depth, const std::string& path, const sim::Scene& original, glm::dvec2 origin,
                 std::size_t frames, float fps, std::size_t firstFrame, UsdMaterials& materials)
{
    const sim::Scene scene = sim::shiftedScene(original, origin);
    std::string body;
    auto part = [&](const char* name, auto build) {
        SolidMesh solids;
        build(solids);
        writeSetPart(body, depth + 1, name, solids, materials);
    };
    part("Ground", [&](SolidMesh& m) { SetSurfaces::addGround(scene, m); });
    part("Lanes", [&](SolidMesh& m) { SetSurfaces::addLanes(scene, m); });
    part("Crosswalks", [&](SolidMesh& m) { SetSurfaces::addCrosswalks(scene, m); });
    part("Walls", [&](SolidMesh& m) { SetSolids::addWalls(scene, m); });
    part("Obstacles", [&](SolidMesh& m) { SetSolids::addObstacles(scene, m); });
    // The poles and heads with every lamp dark; each lamp lit on top of its dark self.
    part("Lights", [&](SolidMesh& m) {
        SetSolids::addLightPoles(scene, m);
        SetSolids::addLamps(scene.trafficLights, scene.terrain, std::nullopt, m);
    });
    if (!scene.trafficLights.empty()) {
        // One lit lamp of each colour about its own middle, as classes the lamps reference.
        indent(body, depth + 1);
        body += "class Scope \"LitLamps\"\n";
        indent(body, depth + 1);
        body += "{\n";
        std::vector<SolidMesh> lit(SetSolids::kLamps.size());
        for (std::size_t l = 0; l < SetSolids::kLamps.size(); ++l) {
            const sim::LightPhase lamp = SetSolids::kLamps[l];
            SetSolids::addLitLamp(lamp, lit[l]);
            std::vector<const SolidVertex*> vertices;
            for (const SolidVertex& v : lit[l].vertices())
                vertices.push_back(&v);
            const glm::vec3 rgb(SetSolids::lampColour(lamp));
            const std::string name = SetSolids::lampName(lamp);
            writeTriangles(body, depth + 2, name, vertices, materials.path("set_lamp_" + name, rgb, 0.85f, true),
                           "class Mesh");
        }
        indent(body, depth + 1);
        body += "}\n";
        for (const sim::TrafficLight& light : scene.trafficLights) {
            const float ground = sim::terrainHeight(scene.terrain, light.position.x, light.position.y);
            for (const sim::LightPhase lamp : SetSolids::kLamps) {
                indent(body, depth + 1);
                const std::string name = SetSolids::lampName(lamp);
                body += "def Mesh " + usdQuoted("lamp_" + usdIdentifier(light.name) + "_" + name) + " (\n";
                indent(body, depth + 2);
                body += "prepend references = <" + path + "/LitLamps/" + name + ">\n";
                indent(body, depth + 1);
                body += ")\n";
                indent(body, depth + 1);
                body += "{\n";
                indent(body, depth + 2);
                body += "double3 xformOp:translate = ";
                appendUsdVec3(body, {light.position.x, ground + SetSolids::lampHeightM(lamp), light.position.y});
                body += "\n";
                indent(body, depth + 2);
                body += "uniform token[] xformOpOrder = [\"xformOp:translate\"]\n";
                // Shown on the frames its phase lights it, else invisible.
                indent(body, depth + 2);
                body += "token visibility.timeSamples = {\n";
                int shown = -1;
                for (std::size_t f = 0; f < frames; ++f) {
                    const bool on = sim::lightPhaseAt(light, double(firstFrame + f) / double(fps)) == lamp;
                    if (shown == int(on))
                        continue;
                    shown = int(on);
                    indent(body, depth + 3);
                    body += std::to_string(f) + (on ? ": \"inherited\",\n" : ": \"invisible\",\n");
                }
                indent(body, depth + 2);
                body += "}\n";
                indent(body, depth + 1);
                body += "}\n";
            }
        }
    }
    if (body.empty())
        return false;
    indent(out, depth);
    out += "def Xform \"Set\"\n";
    indent(out, depth);
    out += "{\n";
    out += body;
    indent(out, depth);
    out += "}\n";
    return true;
}

}  // namespace throng::exporting::detail
