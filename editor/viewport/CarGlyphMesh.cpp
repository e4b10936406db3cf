#include "editor/viewport/CarGlyphMesh.h"

namespace throng::editor {

namespace {

constexpr float kL = CarGlyphMesh::kHalfLength, kW = CarGlyphMesh::kHalfWidth;
constexpr float kBodyTop = 0.42f, kCabinTop = 0.8f;

void quad(std::vector<GlyphVertex>& out, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 n,
          GlyphPart part)
{
    const float p = float(int(part));
    for (glm::vec3 v : {a, b, c, a, c, d})
        out.push_back({v, n, p});
}

// A rectangle lying at height y, x in [x0, x1], z in [-w, w]; later ones draw on top.
void rect(std::vector<GlyphVertex>& out, float x0, float x1, float z0, float z1, float y, GlyphPart part)
{
    quad(out, {x0, y, z0}, {x1, y, z0}, {x1, y, z1}, {x0, y, z1}, {0, 1, 0}, part);
}

// The four sides and the top of a box.
void box(std::vector<GlyphVertex>& out, glm::vec3 lo, glm::vec3 hi, GlyphPart sides, GlyphPart top)
{
    quad(out, {hi.x, lo.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, hi.y, hi.z}, {hi.x, lo.y, hi.z}, {1, 0, 0}, sides);
    quad(out, {lo.x, lo.y, lo.z}, {lo.x, lo.y, hi.z}, {lo.x, hi.y, hi.z}, {lo.x, hi.y, lo.z}, {-1, 0, 0}, sides);
    quad(out, {lo.x, lo.y, hi.z}, {hi.x, lo.y, hi.z}, {hi.x, hi.y, hi.z}, {lo.x, hi.y, hi.z}, {0, 0, 1}, sides);
    quad(out, {lo.x, lo.y, lo.z}, {lo.x, hi.y, lo.z}, {hi.x, hi.y, lo.z}, {hi.x, lo.y, lo.z}, {0, 0, -1}, sides);
    rect(out, lo.x, hi.x, lo.z, hi.z, hi.y, top);
}

void headlights(std::vector<GlyphVertex>& out, float y)
{
    rect(out, kL - 0.14f, kL, -0.7f, -0.4f, y, GlyphPart::Nose);
    rect(out, kL - 0.14f, kL, 0.4f, 0.7f, y, GlyphPart::Nose);
}

}  // namespace

std::vector<GlyphVertex> CarGlyphMesh::flat()
{
    std::vector<GlyphVertex> out;
    rect(out, -kL, kL, -kW, kW, 0.0f, GlyphPart::Body);
    rect(out, 0.45f, 0.85f, -0.68f, 0.68f, 0.0f, GlyphPart::Rim);   // windscreen
    rect(out, -1.2f, -0.95f, -0.68f, 0.68f, 0.0f, GlyphPart::Rim);  // rear window
    headlights(out, 0.0f);
    return out;
}

std::vector<GlyphVertex> CarGlyphMesh::solid()
{
    std::vector<GlyphVertex> out;
    box(out, {-kL, 0.0f, -kW}, {kL, kBodyTop, kW}, GlyphPart::Body, GlyphPart::Body);
    box(out, {-1.09f, kBodyTop, -0.72f}, {0.82f, kCabinTop, 0.72f}, GlyphPart::Rim, GlyphPart::Body);
    headlights(out, kBodyTop + 0.005f);
    return out;
}

}  // namespace throng::editor
