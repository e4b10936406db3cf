#pragma once
// Lit solids standing on the ground (upright prisms over a convex outline: boxes,
// cylinders, wall segments) and flat surfaces on it, as a CPU triangle list with a normal
// and a colour per vertex: the editor's 3D view draws it (SolidRenderer) and the glTF
// export writes it. Knows nothing of scenes; owns no GL.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <span>
#include <vector>

namespace throng::exporting {

struct SolidVertex {
    glm::vec3 position{0.0f};                // m
    glm::vec3 normal{0.0f, 1.0f, 0.0f};      // unit, outward
    glm::vec4 colour{1.0f};                  // RGBA in 0..1
    float glow = 0.0f;                       // 1: shown at its colour, unlit (a lamp); 0: lit
};

class SolidMesh {
public:
    void clear() { m_vertices.clear(); }
    bool empty() const { return m_vertices.empty(); }
    const std::vector<SolidVertex>& vertices() const { return m_vertices; }

    // An upright prism over `outline` (a convex polygon of >= 3 ground points (x, z), in
    // either winding) from `bottomY` to `topY` (m, bottomY < topY): its sides and its top,
    // and its bottom too when `bottom` (a solid seen from below, such as a lamp).
    void addPrism(std::span<const glm::vec2> outline, float bottomY, float topY, glm::vec4 colour,
                  bool bottom = false, float glow = 0.0f);
    // An upright cylinder of `segments` (>= 3) sides round `centre`.
    void addCylinder(glm::vec2 centre, float radiusM, int segments, float bottomY, float topY, glm::vec4 colour,
                     bool bottom = false, float glow = 0.0f);
    // A box of `size` (x, z extent) round `centre`, turned by `angleRad` about +y
    // (counter-clockwise seen from above, as scene headings and obstacle angles).
    void addBox(glm::vec2 centre, glm::vec2 size, float angleRad, float bottomY, float topY, glm::vec4 colour);
    // A flat, upward-facing fan over a convex polygon of points (x, y, z): the ground, a
    // lane, a crosswalk's bar. Each triangle's normal is its own, turned up.
    void addSurface(std::span<const glm::vec3> polygon, glm::vec4 colour);

private:
    void push(glm::vec3 p, glm::vec3 normal, glm::vec4 colour, float glow);

    std::vector<SolidVertex> m_vertices;
};

}  // namespace throng::exporting
