#include "simcore/nav/SketchSamples.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace throng::sim {

namespace {

// Cap on samples along one boundary piece: beyond, the piece is far longer than any
// area agents walk (a typo'd coordinate) and its samples far from strokes are dropped.
constexpr double kMaxPieceSamples = 1e7;

void sampleSegment(glm::vec2 a, glm::vec2 b, float spacingM, std::vector<BoundarySample>& out)
{
    const float len = glm::distance(a, b);
    if (!(len > 0.0f) || !std::isfinite(len))
        return;
    const glm::vec2 t = (b - a) / len;
    const int n = int(std::clamp(std::ceil(double(len) / double(spacingM)), 1.0, kMaxPieceSamples));
    for (int k = 0; k <= n; ++k)
        out.push_back({a + (b - a) * (float(k) / float(n)), {-t.y, t.x}});
}

// The part of segment ab inside the box [lo, hi] (Liang-Barsky); false when none is.
bool clipSegment(glm::vec2& a, glm::vec2& b, glm::vec2 lo, glm::vec2 hi)
{
    double t0 = 0.0, t1 = 1.0;
    const glm::dvec2 p(a), d = glm::dvec2(b) - glm::dvec2(a);
    for (int k = 0; k < 2; ++k) {
        for (const auto& [q, r] : {std::pair(-d[k], p[k] - double(lo[k])), std::pair(d[k], double(hi[k]) - p[k])}) {
            if (q == 0.0) {
                if (r < 0.0)
                    return false;
                continue;
            }
            const double t = r / q;
            if (q < 0.0)
                t0 = std::max(t0, t);
            else
                t1 = std::min(t1, t);
        }
    }
    if (t0 > t1)
        return false;
    a = glm::vec2(p + d * t0);
    b = glm::vec2(p + d * t1);
    return true;
}

// Stroke samples bucketed by cells of the reach, to ask "is any within reach?" looking
// at the 3 x 3 cells round a point only.
class NearStrokes {
public:
    NearStrokes(std::span<const VectorSample> near, float reachM) : m_reach(std::max(reachM, 1e-3f))
    {
        for (const VectorSample& v : near)
            m_cells[key(v.position)].push_back(v.position);
    }
    bool anyWithin(glm::vec2 p) const
    {
        const float r2 = m_reach * m_reach;
        const auto [cx, cz] = key(p);
        for (long long dz = -1; dz <= 1; ++dz)
            for (long long dx = -1; dx <= 1; ++dx)
                if (const auto it = m_cells.find({cx + dx, cz + dz}); it != m_cells.end())
                    for (glm::vec2 q : it->second)
                        if (glm::dot(p - q, p - q) <= r2)
                            return true;
        return false;
    }

private:
    std::pair<long long, long long> key(glm::vec2 p) const
    {
        auto c = [&](float v) { return (long long)(std::clamp(std::floor(double(v) / double(m_reach)), -1e15, 1e15)); };
        return {c(p.x), c(p.y)};
    }
    float m_reach;
    std::map<std::pair<long long, long long>, std::vector<glm::vec2>> m_cells;
};

}  // namespace

std::vector<VectorSample> strokeSamples(std::span<const FlowStroke> strokes, float spacingM)
{
    std::vector<VectorSample> out;
    const double step = spacingM > 0.0f ? double(spacingM) : 1.0;
    for (const FlowStroke& s : strokes) {
        double carry = 0.0;  // arc length from the segment start to its first sample
        for (std::size_t k = 0; k + 1 < s.points.size(); ++k) {
            const glm::dvec2 a = s.points[k], b = s.points[k + 1];
            const double len = glm::distance(a, b);
            if (!(len > 0.0) || !std::isfinite(len))
                continue;
            const glm::dvec2 t = (b - a) / len;
            // Counted, not accumulated: a float sum stops growing on a long stroke.
            const double count = std::ceil((len - carry) / step);
            for (double j = 0.0; j < count; j += 1.0)
                out.push_back({glm::vec2(a + t * (carry + j * step)), glm::vec2(t)});
            carry = carry + count * step - len;
        }
    }
    return out;
}

std::vector<BoundarySample> boundarySamples(const NavShapes& shapes, float spacingM, std::span<const VectorSample> near,
                                            float reachM)
{
    const float step = spacingM > 0.0f ? spacingM : 1.0f;
    // Only the parts of the set within reach of the strokes' extent are sampled at all.
    glm::vec2 lo(-INFINITY), hi(INFINITY);
    if (!near.empty()) {
        lo = glm::vec2(INFINITY);
        hi = glm::vec2(-INFINITY);
        for (const VectorSample& v : near) {
            lo = glm::min(lo, v.position);
            hi = glm::max(hi, v.position);
        }
        lo -= glm::vec2(reachM + step);
        hi += glm::vec2(reachM + step);
    }
    std::vector<BoundarySample> all;
    auto segment = [&](glm::vec2 a, glm::vec2 b) {
        if (near.empty() || clipSegment(a, b, lo, hi))
            sampleSegment(a, b, step, all);
    };
    for (const Segment& s : shapes.walls)
        segment(s.a, s.b);
    for (const NavBox& b : shapes.boxes) {
        Segment sides[4];
        boxSides(b, sides);
        for (const Segment& s : sides)
            segment(s.a, s.b);
    }
    for (const NavCircle& c : shapes.circles) {
        // Skip a circle whose outline misses the box (wholly outside it, or round it).
        const glm::vec2 nearest = glm::clamp(c.centre, lo, hi);
        const glm::vec2 farthest = glm::max(glm::abs(c.centre - lo), glm::abs(c.centre - hi));
        if (!near.empty() && (glm::distance(nearest, c.centre) > c.radiusM || glm::length(farthest) < c.radiusM))
            continue;
        const int n = int(std::clamp(std::ceil(double(glm::two_pi<float>()) * double(c.radiusM) / double(step)), 6.0,
                                     kMaxPieceSamples));
        for (int k = 0; k < n; ++k) {
            const double a = glm::two_pi<double>() * double(k) / double(n);
            const glm::vec2 radial(float(std::cos(a)), float(std::sin(a)));
            const glm::vec2 p = c.centre + radial * c.radiusM;
            if (near.empty() || (p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y))
                all.push_back({p, radial});
        }
    }
    if (near.empty())
        return all;
    std::vector<BoundarySample> kept;
    const NearStrokes strokes(near, reachM);
    for (const BoundarySample& b : all)
        if (strokes.anyWithin(b.position))
            kept.push_back(b);
    return kept;
}

}  // namespace throng::sim
