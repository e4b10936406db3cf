#pragma once
// Flat coloured ground shapes (lines, polylines, discs, rings, polygons) as a CPU
// triangle list for ShapeRenderer. Thin lines carry their widening direction so the
// shader can keep them at least a pixel or two wide when zoomed out. Owns no GL.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <span>
#include <vector>

namespace throng::editor {

struct ShapeVertex {
    glm::vec3 position{0.0f};  // m, already offset by halfWidthM along normal
    glm::vec2 normal{0.0f};    // unit (x, z) direction the outline widens along; zero for fills
    float halfWidthM = 0.0f;   // how far position already lies out along normal
    glm::vec4 colour{1.0f};    // RGBA in 0..1
};

class ShapeMesh {
public:
    void clear() { m_vertices.clear(); }
    bool empty() const { return m_vertices.empty(); }
    const std::vector<ShapeVertex>& vertices() const { return m_vertices; }

    // Every shape lies at height `y` (m) on the ground; later shapes draw over earlier ones.
    void setHeight(float y) { m_y = y; }

    // A line of width 2 * halfWidthM with round ends.
    void addLine(glm::vec2 a, glm::vec2 b, float halfWidthM, glm::vec4 colour);
    // Segments with round joints; `closed` joins the last point back to the first.
    void addPolyline(std::span<const glm::vec2> points, bool closed, float halfWidthM, glm::vec4 colour);
    // Dashes of `dashM` separated by `gapM` along the polyline (flat ends).
    void addDashedPolyline(std::span<const glm::vec2> points, float halfWidthM, float dashM, float gapM,
                           glm::vec4 colour);
    void addDisc(glm::vec2 centre, float radiusM, glm::vec4 colour);
    void addRing(glm::vec2 centre, float radiusM, float halfWidthM, glm::vec4 colour);
    // A filled convex polygon (fan from the first point).
    void addConvexPolygon(std::span<const glm::vec2> points, glm::vec4 colour);

private:
    void addSegmentQuad(glm::vec2 a, glm::vec2 b, float halfWidthM, glm::vec4 colour);
    void addRoundCap(glm::vec2 centre, float halfWidthM, glm::vec4 colour);
    void push(glm::vec2 p, glm::vec2 normal, float halfWidthM, glm::vec4 colour);
    static int segmentsFor(float radiusM);

    std::vector<ShapeVertex> m_vertices;
    float m_y = 0.0f;
};

}  // namespace throng::editor
