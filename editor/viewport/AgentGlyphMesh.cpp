#include "editor/viewport/AgentGlyphMesh.h"

#include <cmath>
#include <numbers>

namespace throng::editor {

namespace {

glm::vec3 onCircle(int i, float r, float y, int segments)
{
    const float a = 2.0f * std::numbers::pi_v<float> * float(i) / float(segments);
    return {r * std::cos(a), y, r * std::sin(a)};
}

void add(std::vector<GlyphVertex>& out, glm::vec3 p, glm::vec3 n, GlyphPart part)
{
    out.push_back({p, n, float(int(part))});
}

}  // namespace

void AgentGlyphMesh::addCap(std::vector<GlyphVertex>& out, float y, float noseLiftY, int segments)
{
    // The coarse glyph has no rim: its body reaches the full radius.
    const bool rim = segments >= kDetailed;
    const float bodyTo = rim ? kRimFrom : 1.0f;
    auto onCircle = [segments](int i, float r, float h) { return ::throng::editor::onCircle(i, r, h, segments); };
    // Body, then rim, then nose: in the top view later triangles draw over earlier ones.
    const glm::vec3 up{0.0f, 1.0f, 0.0f};
    for (int i = 0; i < segments; ++i) {
        add(out, {0.0f, y, 0.0f}, up, GlyphPart::Body);
        add(out, onCircle(i, bodyTo, y), up, GlyphPart::Body);
        add(out, onCircle(i + 1, bodyTo, y), up, GlyphPart::Body);
    }
    for (int i = 0; rim && i < segments; ++i) {
        const glm::vec3 a0 = onCircle(i, kRimFrom, y), a1 = onCircle(i + 1, kRimFrom, y);
        const glm::vec3 b0 = onCircle(i, 1.0f, y), b1 = onCircle(i + 1, 1.0f, y);
        add(out, a0, up, GlyphPart::Rim);
        add(out, b0, up, GlyphPart::Rim);
        add(out, b1, up, GlyphPart::Rim);
        add(out, a0, up, GlyphPart::Rim);
        add(out, b1, up, GlyphPart::Rim);
        add(out, a1, up, GlyphPart::Rim);
    }
    const float ny = y + noseLiftY;
    add(out, {kNoseTo, ny, 0.0f}, up, GlyphPart::Nose);
    add(out, {kNoseFrom, ny, 0.42f}, up, GlyphPart::Nose);
    add(out, {kNoseFrom, ny, -0.42f}, up, GlyphPart::Nose);
}

std::vector<GlyphVertex> AgentGlyphMesh::flat(int segments)
{
    std::vector<GlyphVertex> out;
    addCap(out, 0.0f, 0.0f, segments);
    return out;
}

std::vector<GlyphVertex> AgentGlyphMesh::prism(int segments)
{
    std::vector<GlyphVertex> out;
    for (int i = 0; i < segments; ++i) {
        const glm::vec3 b0 = onCircle(i, 1.0f, 0.0f, segments), b1 = onCircle(i + 1, 1.0f, 0.0f, segments);
        const glm::vec3 t0 = onCircle(i, 1.0f, 1.0f, segments), t1 = onCircle(i + 1, 1.0f, 1.0f, segments);
        const glm::vec3 n0{b0.x, 0.0f, b0.z}, n1{b1.x, 0.0f, b1.z};
        add(out, b0, n0, GlyphPart::Body);
        add(out, t0, n0, GlyphPart::Body);
        add(out, t1, n1, GlyphPart::Body);
        add(out, b0, n0, GlyphPart::Body);
        add(out, t1, n1, GlyphPart::Body);
        add(out, b1, n1, GlyphPart::Body);
    }
    // The nose floats a hair above the cap so the depth test keeps it on top.
    addCap(out, 1.0f, 0.01f, segments);
    return out;
}

}  // namespace throng::editor
