#include "export/detail/UsdCharacter.h"

#include "export/detail/UsdMesh.h"
#include "export/detail/UsdText.h"

#include <glm/gtc/matrix_transform.hpp>

#include <map>
#include <set>

namespace throng::exporting::detail {

namespace {

// `base`, or base_1, base_2, … : the first that `taken` lacks (then taken).
std::string unique(std::set<std::string>& taken, const std::string& base)
{
    std::string name = base;
    for (int k = 1; taken.count(name); ++k)
        name = base + "_" + std::to_string(k);
    taken.insert(name);
    return name;
}

glm::mat4 restLocal(const Joint& joint)
{
    return glm::translate(glm::mat4(1.0f), joint.restTranslation) * glm::mat4_cast(joint.restRotation) *
           glm::scale(glm::mat4(1.0f), joint.restScale);
}

void writeMatrices(std::string& out, const std::vector<glm::mat4>& matrices)
{
    out += '[';
    for (std::size_t j = 0; j < matrices.size(); ++j) {
        if (j)
            out += ", ";
        appendUsdMatrix(out, matrices[j]);
    }
    out += ']';
}

void writePart(std::string& out, int depth, const Character& c, const MeshPart& part, const std::string& name,
               const std::string& skeleton, const std::string& material)
{
    const CharacterMesh& mesh = c.mesh;
    // The part's own vertices, in the order its triangles first use them.
    std::map<std::uint32_t, std::uint32_t> local;
    UsdMeshData data;
    for (std::uint32_t k = part.firstIndex; k < part.firstIndex + part.indexCount; ++k) {
        const std::uint32_t v = mesh.indices[k];
        const auto [it, added] = local.emplace(v, static_cast<std::uint32_t>(data.points.size()));
        if (added) {
            data.points.push_back(mesh.positions[v]);
            data.normals.push_back(mesh.normals[v]);
            for (std::size_t i = 0; i < 4; ++i) {
                data.jointIndices.push_back(mesh.joints[v][i]);
                data.jointWeights.push_back(mesh.weights[v][static_cast<int>(i)]);
            }
        }
        data.indices.push_back(it->second);
    }
    data.skeleton = skeleton;
    data.material = material;
    writeUsdMesh(out, depth, "def Mesh", name, data);
}

}  // namespace

UsdLook usdLookOf(const Character& c, const std::string& prim)
{
    UsdLook look;
    look.prim = prim;
    std::vector<std::set<std::string>> children(c.joints.size() + 1);  // the last: the roots
    for (const Joint& joint : c.joints) {
        const std::size_t parent = joint.parent >= 0 ? static_cast<std::size_t>(joint.parent) : c.joints.size();
        const std::string name = unique(children[parent], usdIdentifier(joint.name));
        look.jointPaths.push_back(joint.parent >= 0 ? look.jointPaths[parent] + "/" + name : name);
    }
    std::set<std::string> parts{"Skel"};
    for (const MeshPart& part : partsOf(c.mesh))
        look.partNames.push_back(unique(parts, toString(part.slot)));
    return look;
}

void appendUsdJointTokens(std::string& out, const UsdLook& look)
{
    out += '[';
    for (std::size_t j = 0; j < look.jointPaths.size(); ++j) {
        if (j)
            out += ", ";
        out += usdQuoted(look.jointPaths[j]);
    }
    out += ']';
}

void writeUsdCharacter(std::string& out, int depth, const Character& c, const UsdLook& look, const std::string& path,
                       const std::vector<std::string>& partMaterials)
{
    indent(out, depth);
    out += "class Xform " + usdQuoted(look.prim) + " (\n";
    indent(out, depth + 1);
    out += "customData = {\n";
    indent(out, depth + 2);
    out += "string character = " + usdQuoted(c.name) + "\n";
    indent(out, depth + 1);
    out += "}\n";
    indent(out, depth);
    out += ")\n";
    indent(out, depth);
    out += "{\n";
    indent(out, depth + 1);
    out += "def Skeleton \"Skel\"\n";
    indent(out, depth + 1);
    out += "{\n";
    indent(out, depth + 2);
    out += "uniform token[] joints = ";
    appendUsdJointTokens(out, look);
    out += '\n';
    std::vector<glm::mat4> bind, rest;
    for (std::size_t j = 0; j < c.joints.size(); ++j) {
        bind.push_back(j < c.mesh.inverseBindMatrices.size() ? glm::inverse(c.mesh.inverseBindMatrices[j])
                                                              : glm::mat4(1.0f));
        rest.push_back(restLocal(c.joints[j]));
    }
    indent(out, depth + 2);
    out += "uniform matrix4d[] bindTransforms = ";
    writeMatrices(out, bind);
    out += '\n';
    indent(out, depth + 2);
    out += "uniform matrix4d[] restTransforms = ";
    writeMatrices(out, rest);
    out += '\n';
    indent(out, depth + 1);
    out += "}\n";
    const std::vector<MeshPart> parts = partsOf(c.mesh);
    for (std::size_t p = 0; p < parts.size(); ++p)
        writePart(out, depth + 1, c, parts[p], look.partNames[p], path + "/Skel",
                  p < partMaterials.size() ? partMaterials[p] : std::string());
    indent(out, depth);
    out += "}\n";
}

}  // namespace throng::exporting::detail
