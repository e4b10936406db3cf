#include "export/set/SetSurfaces.h"

#include "export/set/SetColours.h"
#include "simcore/scene/TerrainHeight.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace throng::exporting {

namespace {

constexpr float kPieceM = 2.0f;  // strips follow the terrain in pieces no longer than this
constexpr float kBarM = 0.5f;    // zebra bars and the gaps between them
constexpr float kDashM = 1.5f, kCentreLineM = 0.12f;
constexpr int kBendSegments = 12;

float groundUnder(const sim::Scene& scene, glm::vec2 p)
{
    return sim::terrainHeight(scene.terrain, p.x, p.y);
}

// A strip `halfWidth` either side of the straight a -> b, `lift` above the ground, in
// pieces that follow the terrain.
void addStrip(const sim::Scene& scene, glm::vec2 a, glm::vec2 b, float halfWidth, float lift, glm::vec4 colour,
              SolidMesh& mesh)
{
    const float len = glm::length(b - a);
    if (!(len > 0.0f))
        return;
    const glm::vec2 along = (b - a) / len, side(-along.y * halfWidth, along.x * halfWidth);
    const int pieces = std::max(1, int(std::ceil(len / kPieceM)));
    auto at = [&](glm::vec2 p) { return glm::vec3(p.x, groundUnder(scene, p) + lift, p.y); };
    for (int k = 0; k < pieces; ++k) {
        const glm::vec2 p0 = a + (b - a) * (float(k) / float(pieces));
        const glm::vec2 p1 = a + (b - a) * (float(k + 1) / float(pieces));
        const std::array<glm::vec3, 4> quad{at(p0 - side), at(p1 - side), at(p1 + side), at(p0 + side)};
        mesh.addSurface(quad, colour);
    }
}

}  // namespace

void SetSurfaces::addGround(const sim::Scene& scene, SolidMesh& mesh)
{
    const glm::vec2 lo = scene.settings.boundsMin, hi = scene.settings.boundsMax;
    if (!(hi.x > lo.x && hi.y > lo.y))
        return;
    const sim::Terrain& t = scene.terrain;
    if (t.heights.empty() || t.cols < 2 || t.rows < 2) {
        const std::array<glm::vec3, 4> quad{glm::vec3(lo.x, 0.0f, lo.y), glm::vec3(hi.x, 0.0f, lo.y),
                                            glm::vec3(hi.x, 0.0f, hi.y), glm::vec3(lo.x, 0.0f, hi.y)};
        mesh.addSurface(quad, setcolours::kGround);
        return;
    }
    // The terrain's cells over the bounds, cut at the bounds' edges.
    std::vector<float> xs{lo.x}, zs{lo.y};
    for (std::uint32_t c = 0; c < t.cols; ++c)
        if (const float x = t.origin.x + float(c) * t.cellM; x > lo.x && x < hi.x)
            xs.push_back(x);
    for (std::uint32_t r = 0; r < t.rows; ++r)
        if (const float z = t.origin.y + float(r) * t.cellM; z > lo.y && z < hi.y)
            zs.push_back(z);
    xs.push_back(hi.x);
    zs.push_back(hi.y);
    auto at = [&](float x, float z) { return glm::vec3(x, sim::terrainHeight(t, x, z), z); };
    for (std::size_t j = 0; j + 1 < zs.size(); ++j)
        for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
            const std::array<glm::vec3, 4> quad{at(xs[i], zs[j]), at(xs[i + 1], zs[j]), at(xs[i + 1], zs[j + 1]),
                                                at(xs[i], zs[j + 1])};
            mesh.addSurface(quad, setcolours::kGround);
        }
}

void SetSurfaces::addLanes(const sim::Scene& scene, SolidMesh& mesh)
{
    for (const sim::Lane& lane : scene.lanes) {
        const float half = 0.5f * lane.widthM;
        for (std::size_t i = 0; i + 1 < lane.points.size(); ++i)
            addStrip(scene, lane.points[i], lane.points[i + 1], half, kLaneLiftM, setcolours::kLane, mesh);
        // Round at the bends: a disc at each inner point fills the wedge two strips leave.
        for (std::size_t i = 1; i + 1 < lane.points.size(); ++i) {
            const glm::vec2 c = lane.points[i];
            const float y = groundUnder(scene, c) + kLaneLiftM;
            std::vector<glm::vec3> disc;
            for (int k = 0; k < kBendSegments; ++k) {
                const float a = 2.0f * std::numbers::pi_v<float> * float(k) / float(kBendSegments);
                disc.emplace_back(c.x + half * std::cos(a), y, c.y + half * std::sin(a));
            }
            mesh.addSurface(disc, setcolours::kLane);
        }
        // The centre line: dashes measured along the whole lane.
        float along = 0.0f;
        for (std::size_t i = 0; i + 1 < lane.points.size(); ++i) {
            const glm::vec2 a = lane.points[i], b = lane.points[i + 1];
            const float len = glm::length(b - a);
            for (float s = 0.0f; s < len;) {
                const float phase = std::fmod(along + s, 2.0f * kDashM);
                const float step = std::min(len - s, phase < kDashM ? kDashM - phase : 2.0f * kDashM - phase);
                if (phase < kDashM && step > 1e-3f)
                    addStrip(scene, a + (b - a) * (s / len), a + (b - a) * ((s + step) / len), 0.5f * kCentreLineM,
                             kMarkingLiftM, setcolours::kLaneCentre, mesh);
                s += std::max(step, 1e-3f);
            }
            along += len;
        }
    }
}

void SetSurfaces::addCrosswalks(const sim::Scene& scene, SolidMesh& mesh)
{
    for (const sim::Crosswalk& c : scene.crosswalks) {
        const glm::vec2 d = c.to - c.from;
        const float len = glm::length(d);
        if (!(len > 0.0f))
            continue;
        const glm::vec2 across = glm::vec2(-d.y, d.x) / len;
        const int bars = std::max(1, int(std::floor(c.widthM / (2.0f * kBarM))));
        const float first = -0.5f * float(2 * bars - 1) * kBarM;
        for (int i = 0; i < bars; ++i) {
            const float middle = first + (float(2 * i) + 0.5f) * kBarM;
            addStrip(scene, c.from + across * middle, c.to + across * middle, 0.5f * kBarM, kMarkingLiftM,
                     setcolours::kCrosswalkStripe, mesh);
        }
    }
}

}  // namespace throng::exporting
