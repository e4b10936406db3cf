#include "editor/viewport/ShapeMesh.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace throng::editor {

int ShapeMesh::segmentsFor(float radiusM)
{
    return std::clamp(int(radiusM * 32.0f), 20, 96);
}

void ShapeMesh::push(glm::vec2 p, glm::vec2 normal, float halfWidthM, glm::vec4 colour)
{
    m_vertices.push_back({{p.x, m_y, p.y}, normal, halfWidthM, colour});
}

void ShapeMesh::addSegmentQuad(glm::vec2 a, glm::vec2 b, float halfWidthM, glm::vec4 colour)
{
    const glm::vec2 d = b - a;
    const float len = glm::length(d);
    if (!(len > 0.0f))
        return;
    const glm::vec2 n = glm::vec2(-d.y, d.x) / len;
    const glm::vec2 o = n * halfWidthM;
    push(a + o, n, halfWidthM, colour);
    push(a - o, -n, halfWidthM, colour);
    push(b + o, n, halfWidthM, colour);
    push(b + o, n, halfWidthM, colour);
    push(a - o, -n, halfWidthM, colour);
    push(b - o, -n, halfWidthM, colour);
}

void ShapeMesh::addRoundCap(glm::vec2 centre, float halfWidthM, glm::vec4 colour)
{
    // A disc whose rim widens with the line, so joints stay round at any zoom.
    const int n = std::clamp(int(halfWidthM * 64.0f), 10, 32);
    for (int i = 0; i < n; ++i) {
        const float a0 = 2.0f * std::numbers::pi_v<float> * float(i) / float(n);
        const float a1 = 2.0f * std::numbers::pi_v<float> * float(i + 1) / float(n);
        const glm::vec2 d0{std::cos(a0), std::sin(a0)}, d1{std::cos(a1), std::sin(a1)};
        push(centre, glm::vec2(0.0f), 0.0f, colour);
        push(centre + d0 * halfWidthM, d0, halfWidthM, colour);
        push(centre + d1 * halfWidthM, d1, halfWidthM, colour);
    }
}

void ShapeMesh::addLine(glm::vec2 a, glm::vec2 b, float halfWidthM, glm::vec4 colour)
{
    addSegmentQuad(a, b, halfWidthM, colour);
    addRoundCap(a, halfWidthM, colour);
    addRoundCap(b, halfWidthM, colour);
}

void ShapeMesh::addPolyline(std::span<const glm::vec2> points, bool closed, float halfWidthM, glm::vec4 colour)
{
    if (points.size() < 2)
        return;
    for (std::size_t i = 0; i + 1 < points.size(); ++i)
        addSegmentQuad(points[i], points[i + 1], halfWidthM, colour);
    if (closed)
        addSegmentQuad(points.back(), points.front(), halfWidthM, colour);
    for (glm::vec2 p : points)
        addRoundCap(p, halfWidthM, colour);
}

void ShapeMesh::addDashedPolyline(std::span<const glm::vec2> points, float halfWidthM, float dashM, float gapM,
                                  glm::vec4 colour)
{
    const float period = dashM + gapM;
    if (points.size() < 2 || !(dashM > 0.0f) || !(period > 0.0f))
        return;
    float along = 0.0f;  // distance from the polyline's start, so dashes continue across corners
    for (std::size_t i = 0; i + 1 < points.size(); ++i) {
        const glm::vec2 a = points[i], b = points[i + 1];
        const float len = glm::length(b - a);
        if (!(len > 0.0f))
            continue;
        const glm::vec2 dir = (b - a) / len;
        // Dash k covers [k * period, k * period + dashM] of the whole polyline's length.
        for (double k = std::floor(double(along) / double(period));; k += 1.0) {
            const float d0 = float(k * double(period) - double(along)), d1 = d0 + dashM;
            if (d0 >= len)
                break;
            if (d1 > 0.0f)
                addSegmentQuad(a + dir * std::max(d0, 0.0f), a + dir * std::min(d1, len), halfWidthM, colour);
        }
        along += len;
    }
}

void ShapeMesh::addDisc(glm::vec2 centre, float radiusM, glm::vec4 colour)
{
    const int n = segmentsFor(radiusM);
    for (int i = 0; i < n; ++i) {
        const float a0 = 2.0f * std::numbers::pi_v<float> * float(i) / float(n);
        const float a1 = 2.0f * std::numbers::pi_v<float> * float(i + 1) / float(n);
        push(centre, glm::vec2(0.0f), 0.0f, colour);
        push(centre + radiusM * glm::vec2(std::cos(a0), std::sin(a0)), glm::vec2(0.0f), 0.0f, colour);
        push(centre + radiusM * glm::vec2(std::cos(a1), std::sin(a1)), glm::vec2(0.0f), 0.0f, colour);
    }
}

void ShapeMesh::addRing(glm::vec2 centre, float radiusM, float halfWidthM, glm::vec4 colour)
{
    const int n = segmentsFor(radiusM);
    const float inner = std::max(0.0f, radiusM - halfWidthM), outer = radiusM + halfWidthM;
    for (int i = 0; i < n; ++i) {
        const float a0 = 2.0f * std::numbers::pi_v<float> * float(i) / float(n);
        const float a1 = 2.0f * std::numbers::pi_v<float> * float(i + 1) / float(n);
        const glm::vec2 d0{std::cos(a0), std::sin(a0)}, d1{std::cos(a1), std::sin(a1)};
        push(centre + d0 * outer, d0, halfWidthM, colour);
        push(centre + d0 * inner, -d0, halfWidthM, colour);
        push(centre + d1 * outer, d1, halfWidthM, colour);
        push(centre + d1 * outer, d1, halfWidthM, colour);
        push(centre + d0 * inner, -d0, halfWidthM, colour);
        push(centre + d1 * inner, -d1, halfWidthM, colour);
    }
}

void ShapeMesh::addConvexPolygon(std::span<const glm::vec2> points, glm::vec4 colour)
{
    for (std::size_t i = 1; i + 1 < points.size(); ++i) {
        push(points[0], glm::vec2(0.0f), 0.0f, colour);
        push(points[i], glm::vec2(0.0f), 0.0f, colour);
        push(points[i + 1], glm::vec2(0.0f), 0.0f, colour);
    }
}

}  // namespace throng::editor
