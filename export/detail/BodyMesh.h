#pragma once
// The stand-in body of an agent type until skinned characters exist: an upright,
// flat-shaded closed octagonal prism with a tapered top and a pyramid nose pointing +X
// (the agent's forward at heading 0). Pure geometry; never writes files or knows glTF.

#include <glm/vec3.hpp>

#include <vector>

namespace throng::exporting::detail {

struct BodyMesh {
    std::vector<glm::vec3> positions;  // m, feet at y = 0, non-indexed triangles (3 per face)
    std::vector<glm::vec3> normals;    // unit length, one per position, pointing outward
    glm::vec3 min{0.0f}, max{0.0f};    // bounds of positions, exact
};

// radiusM: body radius in m, > 0; heightM: total height in m, > 0.
BodyMesh makeBodyMesh(float radiusM, float heightM);

}  // namespace throng::exporting::detail
