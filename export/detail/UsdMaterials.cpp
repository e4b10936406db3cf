#include "export/detail/UsdMaterials.h"

#include "export/detail/UsdText.h"

namespace throng::exporting::detail {

std::string UsdMaterials::path(const std::string& name, glm::vec3 rgb, float roughness, bool glow)
{
    const std::string id = usdIdentifier(name);
    m_made.try_emplace(id, Made{rgb, roughness, glow});
    return m_scope + "/" + id;
}

void UsdMaterials::write(std::string& out, int depth) const
{
    indent(out, depth);
    out += "def Scope " + usdQuoted(m_scope.substr(m_scope.rfind('/') + 1)) + "\n";
    indent(out, depth);
    out += "{\n";
    for (const auto& [name, made] : m_made) {
        const std::string path = m_scope + "/" + name;
        indent(out, depth + 1);
        out += "def Material " + usdQuoted(name) + "\n";
        indent(out, depth + 1);
        out += "{\n";
        indent(out, depth + 2);
        out += "token outputs:surface.connect = <" + path + "/Surface.outputs:surface>\n";
        indent(out, depth + 2);
        out += "def Shader \"Surface\"\n";
        indent(out, depth + 2);
        out += "{\n";
        indent(out, depth + 3);
        out += "uniform token info:id = \"UsdPreviewSurface\"\n";
        indent(out, depth + 3);
        out += "color3f inputs:diffuseColor = ";
        appendUsdColour(out, made.rgb);
        out += '\n';
        if (made.glow) {
            indent(out, depth + 3);
            out += "color3f inputs:emissiveColor = ";
            appendUsdColour(out, made.rgb);
            out += '\n';
        }
        indent(out, depth + 3);
        out += "float inputs:metallic = 0\n";
        indent(out, depth + 3);
        out += "float inputs:roughness = ";
        appendUsdRounded(out, made.roughness, 3);
        out += '\n';
        indent(out, depth + 3);
        out += "token outputs:surface\n";
        indent(out, depth + 2);
        out += "}\n";
        indent(out, depth + 1);
        out += "}\n";
    }
    indent(out, depth);
    out += "}\n";
}

}  // namespace throng::exporting::detail
