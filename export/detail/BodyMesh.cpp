#include "export/detail/BodyMesh.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace throng::exporting::detail {

namespace {

constexpr int kSides = 8;
constexpr double kShoulderHeight = 0.8;  // fraction of the height where the taper starts
constexpr double kCrownRadius = 0.55;    // top radius as a fraction of the body radius

using DVec3 = glm::dvec3;

// Adds one flat triangle facing away from `inside`, whatever order the corners come in.
void addTriangle(BodyMesh& mesh, DVec3 a, DVec3 b, DVec3 c, DVec3 inside)
{
    DVec3 n = glm::cross(b - a, c - a);
    if (glm::dot(n, (a + b + c) / 3.0 - inside) < 0.0) {
        std::swap(b, c);
        n = -n;
    }
    const glm::vec3 normal(glm::normalize(n));
    for (const DVec3& p : {a, b, c}) {
        mesh.positions.emplace_back(p);
        mesh.normals.push_back(normal);
    }
}

void addQuad(BodyMesh& mesh, DVec3 a, DVec3 b, DVec3 c, DVec3 d, DVec3 inside)
{
    addTriangle(mesh, a, b, c, inside);
    addTriangle(mesh, a, c, d, inside);
}

DVec3 ringPoint(int i, double radius, double y)
{
    // Offset by half a side so that one flat face looks straight down +X.
    const double a = (i + 0.5) * 2.0 * std::numbers::pi / kSides;
    return {radius * std::cos(a), y, radius * std::sin(a)};
}

}  // namespace

BodyMesh makeBodyMesh(float radiusM, float heightM)
{
    const double r = radiusM, h = heightM;
    const double shoulderY = kShoulderHeight * h;
    const DVec3 bodyInside(0.0, 0.5 * h, 0.0);
    BodyMesh mesh;
    for (int i = 0; i < kSides; ++i) {
        const int j = (i + 1) % kSides;
        addTriangle(mesh, {0.0, 0.0, 0.0}, ringPoint(i, r, 0.0), ringPoint(j, r, 0.0), bodyInside);
        addQuad(mesh, ringPoint(i, r, 0.0), ringPoint(j, r, 0.0), ringPoint(j, r, shoulderY), ringPoint(i, r, shoulderY),
                bodyInside);
        addQuad(mesh, ringPoint(i, r, shoulderY), ringPoint(j, r, shoulderY), ringPoint(j, kCrownRadius * r, h),
                ringPoint(i, kCrownRadius * r, h), bodyInside);
        addTriangle(mesh, {0.0, h, 0.0}, ringPoint(i, kCrownRadius * r, h), ringPoint(j, kCrownRadius * r, h),
                    bodyInside);
    }

    // The nose: a closed pyramid whose base sits just inside the +X face at head height
    // and whose tip sticks out well past the body, readable from any camera. The hidden
    // base keeps the mesh a union of closed solids, which some tools expect.
    const double faceX = r * std::cos(std::numbers::pi / kSides);
    const double baseX = 0.9 * faceX, halfW = 0.3 * r;
    const double lowY = 0.62 * h, highY = 0.76 * h;
    const DVec3 tip(1.6 * r, 0.5 * (lowY + highY), 0.0);
    const DVec3 base[4] = {{baseX, lowY, -halfW}, {baseX, lowY, halfW}, {baseX, highY, halfW}, {baseX, highY, -halfW}};
    const DVec3 noseInside(baseX - r, tip.y, 0.0);
    for (int i = 0; i < 4; ++i)
        addTriangle(mesh, base[i], base[(i + 1) % 4], tip, noseInside);
    addQuad(mesh, base[0], base[1], base[2], base[3], tip);

    mesh.min = mesh.max = mesh.positions.front();
    for (const glm::vec3& p : mesh.positions) {
        mesh.min = glm::min(mesh.min, p);
        mesh.max = glm::max(mesh.max, p);
    }
    return mesh;
}

}  // namespace throng::exporting::detail
