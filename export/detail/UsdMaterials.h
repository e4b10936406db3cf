#pragma once
// The USD export's materials: each a UsdPreviewSurface of one colour (matte, or glowing
// for a lit lamp), made once under the materials' scope however many prims bind it.
#ifndef THRONG_EXPORT_BUILD
#error "a detail/ header, private to throng::export: include the module's public headers instead"
#endif

#include <glm/vec3.hpp>

#include <map>
#include <string>

namespace throng::exporting::detail {

class UsdMaterials {
public:
    explicit UsdMaterials(std::string scopePath) : m_scope(std::move(scopePath)) {}

    // The path of the material `name` (made a valid prim name); the first call for a name
    // decides its colour.
    std::string path(const std::string& name, glm::vec3 rgb, float roughness = 0.8f, bool glow = false);
    // `def Scope "<last element of the scope path>"` with every material made so far.
    void write(std::string& out, int depth) const;
    bool empty() const { return m_made.empty(); }

private:
    struct Made {
        glm::vec3 rgb{0.5f};
        float roughness = 0.8f;
        bool glow = false;
    };
    std::string m_scope;
    std::map<std::string, Made> m_made;
};

}  // namespace throng::exporting::detail
