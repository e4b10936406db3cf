#include "export/set/SolidMesh.h"

#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <numbers>

namespace throng::exporting {

void SolidMesh::push(glm::vec3 p, glm::vec3 normal, glm::vec4 colour, float glow)
{
    m_vertices.push_back({p, normal, colour, glow});
}

void SolidMesh::addPrism(std::span<const glm::vec2> outline, float bottomY, float topY, glm::vec4 colour,
                         bool bottom, float glow)
{
    const std::size_t n = outline.size();
    if (n < 3)
        return;
    glm::vec2 centroid(0.0f);
    for (glm::vec2 p : outline)
        centroid += p;
    centroid /= float(n);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec2 a = outline[i], b = outline[(i + 1) % n];
        const glm::vec2 d = b - a;
        if (!(glm::dot(d, d) > 0.0f))
            continue;
        // Outward whichever way the outline winds: away from the middle of a convex shape.
        glm::vec2 side = glm::normalize(glm::vec2(d.y, -d.x));
        if (glm::dot(side, 0.5f * (a + b) - centroid) < 0.0f)
            side = -side;
        const glm::vec3 normal(side.x, 0.0f, side.y);
        const glm::vec3 a0(a.x, bottomY, a.y), b0(b.x, bottomY, b.y), b1(b.x, topY, b.y), a1(a.x, topY, a.y);
        for (glm::vec3 p : {a0, b0, b1, a0, b1, a1})
            push(p, normal, colour, glow);
    }
    for (std::size_t i = 1; i + 1 < n; ++i)
        for (glm::vec2 p : {outline[0], outline[i], outline[i + 1]})
            push({p.x, topY, p.y}, {0.0f, 1.0f, 0.0f}, colour, glow);
    for (std::size_t i = 1; bottom && i + 1 < n; ++i)
        for (glm::vec2 p : {outline[0], outline[i], outline[i + 1]})
            push({p.x, bottomY, p.y}, {0.0f, -1.0f, 0.0f}, colour, glow);
}

void SolidMesh::addCylinder(glm::vec2 centre, float radiusM, int segments, float bottomY, float topY,
                            glm::vec4 colour, bool bottom, float glow)
{
    std::vector<glm::vec2> outline;
    outline.reserve(std::size_t(segments));
    for (int i = 0; i < segments; ++i) {
        const float a = 2.0f * std::numbers::pi_v<float> * float(i) / float(segments);
        outline.push_back(centre + radiusM * glm::vec2(std::cos(a), std::sin(a)));
    }
    addPrism(outline, bottomY, topY, colour, bottom, glow);
}

void SolidMesh::addBox(glm::vec2 centre, glm::vec2 size, float angleRad, float bottomY, float topY, glm::vec4 colour)
{
    // The axes World::buildStatics turns a box obstacle with, so the solid covers what agents avoid.
    const glm::vec2 ax(std::cos(angleRad), -std::sin(angleRad)), az(std::sin(angleRad), std::cos(angleRad));
    const glm::vec2 x = ax * (0.5f * size.x), z = az * (0.5f * size.y);
    const std::array<glm::vec2, 4> corners{centre - x - z, centre + x - z, centre + x + z, centre - x + z};
    addPrism(corners, bottomY, topY, colour);
}

void SolidMesh::addSurface(std::span<const glm::vec3> polygon, glm::vec4 colour)
{
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
        const glm::vec3 a = polygon[0], b = polygon[i], c = polygon[i + 1];
        glm::vec3 n = glm::cross(b - a, c - a);
        const float len = glm::length(n);
        if (!(len > 0.0f))
            continue;
        n /= len;
        // Up, and counter-clockwise seen from above (glTF's front face).
        if (n.y < 0.0f) {
            push(a, -n, colour, 0.0f);
            push(c, -n, colour, 0.0f);
            push(b, -n, colour, 0.0f);
        } else {
            push(a, n, colour, 0.0f);
            push(b, n, colour, 0.0f);
            push(c, n, colour, 0.0f);
        }
    }
}

}  // namespace throng::exporting
