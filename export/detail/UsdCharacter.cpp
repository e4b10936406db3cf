#include "export/detail/UsdCharacter.h"

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
    std::vector<std::uint32_t> used, indices;
    for (std::uint32_t k = part.firstIndex; k < part.firstIndex + part.indexCount; ++k) {
        const std::uint32_t v = mesh.indices[k];
        const auto [it, added] = local.emplace(v, static_cast<std::uint32_t>(used.size()));
        if (added)
            used.push_back(v);
        indices.push_back(it->second);
    }
    indent(out, depth);
    out += "def Mesh " + usdQuoted(name) + " (\n";
    indent(out, depth + 1);
    out += material.empty() ? "prepend apiSchemas = [\"SkelBindingAPI\"]\n"
                            : "prepend apiSchemas = [\"SkelBindingAPI\", \"MaterialBindingAPI\"]\n";
    indent(out, depth);
    out += ")\n";
    indent(out, depth);
    out += "{\n";
    indent(out, depth + 1);
    out += "uniform token subdivisionScheme = \"none\"\n";
    indent(out, depth + 1);
    out += "int[] faceVertexCounts = [";
    for (std::size_t t = 0; t < indices.size() / 3; ++t)
        out += t ? ", 3" : "3";
    out += "]\n";
    indent(out, depth + 1);
    out += "int[] faceVertexIndices = [";
    for (std::size_t k = 0; k < indices.size(); ++k) {
        if (k)
            out += ", ";
        out += std::to_string(indices[k]);
    }
    out += "]\n";
    auto vec3s = [&](const char* declaration, const std::vector<glm::vec3>& values, const std::string& after) {
        indent(out, depth + 1);
        out += declaration;
        out += " = [";
        for (std::size_t k = 0; k < used.size(); ++k) {
            if (k)
                out += ", ";
            appendUsdVec3(out, values[used[k]]);
        }
        out += ']';
        out += after;
        out += '\n';
    };
    vec3s("point3f[] points", mesh.positions, "");
    vec3s("normal3f[] normals", mesh.normals, " (\n" + std::string(4 * (depth + 2), ' ') +
                                                  "interpolation = \"vertex\"\n" + std::string(4 * (depth + 1), ' ') +
                                                  ")");
    indent(out, depth + 1);
    out += "int[] primvars:skel:jointIndices = [";
    for (std::size_t k = 0; k < used.size(); ++k)
        for (int i = 0; i < 4; ++i) {
            if (k || i)
                out += ", ";
            out += std::to_string(mesh.joints[used[k]][static_cast<std::size_t>(i)]);
        }
    out += "] (\n";
    indent(out, depth + 2);
    out += "elementSize = 4\n";
    indent(out, depth + 2);
    out += "interpolation = \"vertex\"\n";
    indent(out, depth + 1);
    out += ")\n";
    indent(out, depth + 1);
    out += "float[] primvars:skel:jointWeights = [";
    for (std::size_t k = 0; k < used.size(); ++k)
        for (int i = 0; i < 4; ++i) {
            if (k || i)
                out += ", ";
            appendUsdFloat(out, mesh.weights[used[k]][i]);
        }
    out += "] (\n";
    indent(out, depth + 2);
    out += "elementSize = 4\n";
    indent(out, depth + 2);
    out += "interpolation = \"vertex\"\n";
    indent(out, depth + 1);
    out += ")\n";
    indent(out, depth + 1);
    out += "matrix4d primvars:skel:geomBindTransform = ((1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (0, 0, 0, 1))\n";
    indent(out, depth + 1);
    out += "rel skel:skeleton = <" + skeleton + ">\n";
    if (!material.empty()) {
        indent(out, depth + 1);
        out += "rel material:binding = <" + material + ">\n";
    }
    indent(out, depth);
    out += "}\n";
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
