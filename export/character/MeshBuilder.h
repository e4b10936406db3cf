#pragma once
// Appends low-poly solids (boxes, tapered boxes, prisms), each bound rigidly to one joint,
// to a CharacterMesh: flat-shaded, wound counter-clockwise from outside (the car and the
// bird; humanoids are smooth surfaces, SurfaceBuilder). Geometry only.

#include "export/character/Character.h"

namespace throng::exporting {

class MeshBuilder {
public:
    explicit MeshBuilder(CharacterMesh& mesh) : m_mesh(mesh) {}

    // Axis-aligned box [lo, hi] (m); the top face (y = hi.y) is scaled by `topScale` in x
    // and z about the box's centre line, for tapered shapes.
    void box(int joint, glm::vec3 lo, glm::vec3 hi, glm::vec2 topScale = glm::vec2(1.0f));
    // Prism with `sides` sides around `axis` (0 = x, 1 = y, 2 = z) through `centre`,
    // `halfLength` along it, circumradius `radius`: wheels, hats, necks.
    void prism(int joint, glm::vec3 centre, int axis, float radius, float halfLength, int sides);

private:
    void quad(int joint, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c, const glm::vec3& d);
    void polygon(int joint, const std::vector<glm::vec3>& ring);
    CharacterMesh& m_mesh;
};

}  // namespace throng::exporting
