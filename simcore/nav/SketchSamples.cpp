#include "simcore/nav/SketchSamples.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>

namespace throng::sim {

namespace {

void sampleSegment(glm::vec2 a, glm::vec2 b, float spacingM, std::vector<BoundarySample>& out)
{
    const float len = glm::distance(a, b);
    if (len <= 0.0f)
        return;
    const glm::vec2 t = (b - a) / len;
    const int n = std::max(1, int(std::ceil(len / spacingM)));
    for (int k = 0; k <= n; ++k)
        out.push_back({a + (b - a) * (float(k) / float(n)), {-t.y, t.x}});
}

}  // namespace

std::vector<VectorSample> strokeSamples(std::span<const FlowStroke> strokes, float spacingM)
{
    std::vector<VectorSample> out;
    const float step = spacingM > 0.0f ? spacingM : 1.0f;
    for (const FlowStroke& s : strokes) {
        float carry = 0.0f;  // arc length from the segment start to its first sample
        for (std::size_t k = 0; k + 1 < s.points.size(); ++k) {
            const glm::vec2 a = s.points[k], b = s.points[k + 1];
            const float len = glm::distance(a, b);
            if (len <= 0.0f)
                continue;
            const glm::vec2 t = (b - a) / len;
            float at = carry;
            for (; at < len; at += step)
                out.push_back({a + t * at, t});
            carry = at - len;
        }
    }
    return out;
}

std::vector<BoundarySample> boundarySamples(const NavShapes& shapes, float spacingM, std::span<const VectorSample> near,
                                            float reachM)
{
    const float step = spacingM > 0.0f ? spacingM : 1.0f;
    std::vector<BoundarySample> all;
    for (const Segment& s : shapes.walls)
        sampleSegment(s.a, s.b, step, all);
    for (const NavBox& b : shapes.boxes) {
        Segment sides[4];
        boxSides(b, sides);
        for (const Segment& s : sides)
            sampleSegment(s.a, s.b, step, all);
    }
    for (const NavCircle& c : shapes.circles) {
        const int n = std::max(6, int(std::ceil(glm::two_pi<float>() * c.radiusM / step)));
        for (int k = 0; k < n; ++k) {
            const float a = glm::two_pi<float>() * float(k) / float(n);
            const glm::vec2 radial(std::cos(a), std::sin(a));
            all.push_back({c.centre + radial * c.radiusM, radial});
        }
    }
    if (near.empty())
        return all;
    std::vector<BoundarySample> kept;
    const float r2 = reachM * reachM;
    for (const BoundarySample& b : all)
        for (const VectorSample& v : near) {
            const glm::vec2 d = b.position - v.position;
            if (glm::dot(d, d) <= r2) {
                kept.push_back(b);
                break;
            }
        }
    return kept;
}

}  // namespace throng::sim
