#include "editor/viewport/BirdGlyphMesh.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace throng::editor {

namespace {

constexpr float kRootY = BirdGlyphMesh::kRootY, kTipY = BirdGlyphMesh::kTipY;

// Height of a wing point `z` (across, -1..1) out from the body.
float wingY(float z)
{
    return kRootY + (kTipY - kRootY) * std::abs(z);
}

glm::vec3 onWing(float x, float z)
{
    return {x, wingY(z), z};
}

// One triangle, its normal facing away from `inside` (upward when `inside` lies below).
void triangle(std::vector<GlyphVertex>& out, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 inside, GlyphPart part)
{
    glm::vec3 n = glm::cross(b - a, c - a);
    const float len = glm::length(n);
    n = len > 0.0f ? n / len : glm::vec3(0.0f, 1.0f, 0.0f);
    if (glm::dot(n, (a + b + c) / 3.0f - inside) < 0.0f)
        n = -n;
    for (glm::vec3 p : {a, b, c})
        out.push_back({p, n, float(int(part))});
}

// The wings first: in the top view, drawn without depth, the body then lies over them.
void wings(std::vector<GlyphVertex>& out, bool coarse)
{
    for (float s : {-1.0f, 1.0f}) {
        const glm::vec3 below{0.0f, -1.0f, 0.0f};
        const glm::vec3 rootFront = onWing(0.18f, 0.06f * s), rootBack = onWing(-0.22f, 0.06f * s);
        const glm::vec3 tip = onWing(-0.24f, s);
        if (coarse) {
            triangle(out, rootFront, tip, rootBack, below, GlyphPart::Body);
            continue;
        }
        const glm::vec3 midFront = onWing(0.08f, 0.55f * s), midBack = onWing(-0.20f, 0.5f * s);
        triangle(out, rootFront, midFront, midBack, below, GlyphPart::Body);
        triangle(out, rootFront, midBack, rootBack, below, GlyphPart::Body);
        triangle(out, midFront, tip, midBack, below, GlyphPart::Body);
    }
}

}  // namespace

std::vector<GlyphVertex> BirdGlyphMesh::detailed()
{
    std::vector<GlyphVertex> out;
    wings(out, false);
    const glm::vec3 below{0.0f, -1.0f, 0.0f};
    // The tail fans out behind the body, in the plane of the wing roots.
    triangle(out, {-0.30f, kRootY, 0.0f}, {-0.62f, kRootY, 0.17f}, {-0.62f, kRootY, -0.17f}, below, GlyphPart::Rim);
    // The body: a spindle of eight faces from beak to tail.
    const glm::vec3 centre{0.0f, kRootY, 0.0f};
    const glm::vec3 nose{0.42f, kRootY, 0.0f}, tail{-0.40f, kRootY, 0.0f};
    const glm::vec3 ring[4] = {{0.0f, kRootY + 0.09f, 0.0f}, {0.0f, kRootY, 0.09f}, {0.0f, kRootY - 0.07f, 0.0f},
                               {0.0f, kRootY, -0.09f}};
    for (int k = 0; k < 4; ++k) {
        triangle(out, nose, ring[k], ring[(k + 1) % 4], centre, GlyphPart::Rim);
        triangle(out, tail, ring[k], ring[(k + 1) % 4], centre, GlyphPart::Rim);
    }
    // The beak, on top of the head.
    triangle(out, {0.56f, kRootY + 0.03f, 0.0f}, {0.34f, kRootY + 0.05f, 0.06f}, {0.34f, kRootY + 0.05f, -0.06f}, below,
             GlyphPart::Nose);
    return out;
}

std::vector<GlyphVertex> BirdGlyphMesh::coarse()
{
    std::vector<GlyphVertex> out;
    wings(out, true);
    const glm::vec3 below{0.0f, -1.0f, 0.0f};
    const float y = kRootY + 0.02f;
    triangle(out, {0.45f, y, 0.0f}, {0.0f, y, 0.09f}, {0.0f, y, -0.09f}, below, GlyphPart::Rim);
    triangle(out, {-0.55f, y, 0.0f}, {0.0f, y, 0.09f}, {0.0f, y, -0.09f}, below, GlyphPart::Rim);
    return out;
}

std::vector<GlyphVertex> BirdGlyphMesh::far()
{
    // Each wing from beak to tail out to its tip: the bird's outline in two triangles,
    // broad at the root so that a few pixels still show it.
    std::vector<GlyphVertex> out;
    const glm::vec3 below{0.0f, -1.0f, 0.0f};
    for (float s : {-1.0f, 1.0f})
        triangle(out, {0.4f, kRootY, 0.0f}, onWing(-0.3f, s), {-0.5f, kRootY, 0.0f}, below, GlyphPart::Body);
    return out;
}

}  // namespace throng::editor
