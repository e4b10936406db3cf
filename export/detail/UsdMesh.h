#pragma once
// One triangle Mesh prim in the USD export's text: points, vertex normals, its triangles,
// and as it has them four joint influences a point and its skeleton, a material, a
// constant display colour. The characters' parts and the set's pieces are written by it.
#ifndef THRONG_EXPORT_BUILD
#error "a detail/ header, private to throng::export: include the module's public headers instead"
#endif

#include <glm/vec3.hpp>

#include <optional>
#include <string>
#include <vector>

namespace throng::exporting::detail {

struct UsdMeshData {
    std::vector<glm::vec3> points, normals;  // one normal a point
    std::vector<unsigned> indices;           // triangles, counter-clockwise seen from outside
    std::vector<int> jointIndices;           // skinned: four a point
    std::vector<float> jointWeights;         // skinned: four a point, summing to 1
    std::string skeleton;                    // skinned: the Skeleton prim's path
    std::string material;                    // the bound material's path; empty: none
    std::optional<glm::vec3> displayColour;  // a constant displayColor primvar
    bool doubleSided = false;                // seen from both sides (solids wound either way)
};

// `<specifier> "<name>"` ("def Mesh", "class Mesh") at `depth`.
void writeUsdMesh(std::string& out, int depth, const std::string& specifier, const std::string& name,
                  const UsdMeshData& mesh);

}  // namespace throng::exporting::detail
