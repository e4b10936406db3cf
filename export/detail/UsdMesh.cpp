#include "export/detail/UsdMesh.h"

#include "export/detail/UsdText.h"

namespace throng::exporting::detail {

namespace {

void line(std::string& out, int depth, const std::string& text)
{
    indent(out, depth);
    out += text;
    out += '\n';
}

// `declaration = [values]` and, when given, its metadata on the lines after.
template <typename Values, typename Append>
void array(std::string& out, int depth, const char* declaration, const Values& values, Append append,
           const std::vector<std::string>& metadata = {})
{
    indent(out, depth);
    out += declaration;
    out += " = [";
    bool first = true;
    for (const auto& v : values) {
        if (!first)
            out += ", ";
        first = false;
        append(v);
    }
    out += ']';
    if (metadata.empty()) {
        out += '\n';
        return;
    }
    out += " (\n";
    for (const std::string& m : metadata)
        line(out, depth + 1, m);
    line(out, depth, ")");
}

}  // namespace

void writeUsdMesh(std::string& out, int depth, const std::string& specifier, const std::string& name,
                  const UsdMeshData& mesh)
{
    const bool skinned = !mesh.skeleton.empty();
    const bool bound = !mesh.material.empty();
    line(out, depth, specifier + " " + usdQuoted(name) + " (");
    const std::string schemas = std::string(skinned ? "\"SkelBindingAPI\"" : "") + (skinned && bound ? ", " : "") +
                                (bound ? "\"MaterialBindingAPI\"" : "");
    line(out, depth + 1, "prepend apiSchemas = [" + schemas + "]");
    line(out, depth, ")");
    line(out, depth, "{");
    line(out, depth + 1, "uniform token subdivisionScheme = \"none\"");
    if (mesh.doubleSided)
        line(out, depth + 1, "uniform bool doubleSided = 1");
    const std::vector<int> counts(mesh.indices.size() / 3, 3);
    array(out, depth + 1, "int[] faceVertexCounts", counts, [&](int n) { out += std::to_string(n); });
    array(out, depth + 1, "int[] faceVertexIndices", mesh.indices, [&](unsigned i) { out += std::to_string(i); });
    array(out, depth + 1, "point3f[] points", mesh.points, [&](glm::vec3 p) { appendUsdVec3(out, p); });
    array(out, depth + 1, "normal3f[] normals", mesh.normals, [&](glm::vec3 n) { appendUsdVec3(out, n); },
          {"interpolation = \"vertex\""});
    if (mesh.displayColour) {
        const std::vector<glm::vec3> colour{*mesh.displayColour};
        array(out, depth + 1, "color3f[] primvars:displayColor", colour, [&](glm::vec3 c) { appendUsdColour(out, c); },
              {"interpolation = \"constant\""});
    }
    if (skinned) {
        const std::vector<std::string> influences{"elementSize = 4", "interpolation = \"vertex\""};
        array(out, depth + 1, "int[] primvars:skel:jointIndices", mesh.jointIndices,
              [&](int j) { out += std::to_string(j); }, influences);
        array(out, depth + 1, "float[] primvars:skel:jointWeights", mesh.jointWeights,
              [&](float w) { appendUsdFloat(out, w); }, influences);
        line(out, depth + 1,
             "matrix4d primvars:skel:geomBindTransform = ((1, 0, 0, 0), (0, 1, 0, 0), (0, 0, 1, 0), (0, 0, 0, 1))");
        line(out, depth + 1, "rel skel:skeleton = <" + mesh.skeleton + ">");
    }
    if (bound)
        line(out, depth + 1, "rel material:binding = <" + mesh.material + ">");
    line(out, depth, "}");
}

}  // namespace throng::exporting::detail
