#include "simcore/scene/GroundPolygon.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>

namespace throng::sim {

namespace {

// Doubles: the crossing test multiplies coordinates, and floats of a town-sized set lose
// the sign of a nearly straight corner.
glm::dvec2 d(glm::vec2 p)
{
    return glm::dvec2(p);
}

double orient(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c)
{
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// c lies within the bounding box of a-b (used once a, b, c are known collinear).
bool withinBox(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c)
{
    return std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= c.y &&
           c.y <= std::max(a.y, b.y);
}

// Segments a-b and c-d share at least one point.
bool segmentsMeet(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 e)
{
    const double o1 = orient(a, b, c), o2 = orient(a, b, e), o3 = orient(c, e, a), o4 = orient(c, e, b);
    if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
        return true;
    return (o1 == 0 && withinBox(a, b, c)) || (o2 == 0 && withinBox(a, b, e)) || (o3 == 0 && withinBox(c, e, a)) ||
           (o4 == 0 && withinBox(c, e, b));
}

bool insideTriangle(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c, glm::dvec2 p)
{
    return orient(a, b, p) >= 0 && orient(b, c, p) >= 0 && orient(c, a, p) >= 0;
}

}  // namespace

double signedPolygonArea(std::span<const glm::vec2> corners)
{
    double twice = 0.0;
    for (std::size_t i = 0, n = corners.size(); i < n; ++i) {
        const glm::dvec2 a = d(corners[i]), b = d(corners[(i + 1) % n]);
        twice += a.x * b.y - b.x * a.y;
    }
    return 0.5 * twice;
}

double polygonArea(std::span<const glm::vec2> corners)
{
    return std::abs(signedPolygonArea(corners));
}

std::optional<std::pair<std::size_t, std::size_t>> polygonSelfCrossing(std::span<const glm::vec2> corners)
{
    const std::size_t n = corners.size();
    if (n < 3)
        return std::nullopt;
    auto start = [&](std::size_t i) { return d(corners[i]); };
    auto end = [&](std::size_t i) { return d(corners[(i + 1) % n]); };
    for (std::size_t i = 0; i < n; ++i) {
        if (start(i) == end(i))
            return std::pair(std::min(i, (i + 1) % n), std::max(i, (i + 1) % n));
        // Neighbours share a corner; they cross only by folding back along each other.
        const std::size_t j = (i + 1) % n;
        const glm::dvec2 a = start(i), b = end(i), c = end(j);
        if (orient(a, b, c) == 0 && glm::dot(a - b, c - b) > 0)
            return std::pair(std::min(i, j), std::max(i, j));
    }
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = i + 2; j < n; ++j) {
            if (i == 0 && j == n - 1)
                continue;
            if (segmentsMeet(start(i), end(i), start(j), end(j)))
                return std::pair(i, j);
        }
    return std::nullopt;
}

bool polygonContains(std::span<const glm::vec2> corners, glm::vec2 p)
{
    bool inside = false;
    for (std::size_t i = 0, n = corners.size(), j = n - 1; i < n; j = i++) {
        const glm::vec2 a = corners[i], b = corners[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x)
            inside = !inside;
    }
    return inside;
}

glm::vec2 nearestOnPolygonOutline(std::span<const glm::vec2> corners, glm::vec2 p)
{
    glm::vec2 best = corners.empty() ? p : corners[0];
    float bestD2 = 1e38f;
    for (std::size_t i = 0, n = corners.size(); i < n; ++i) {
        const glm::vec2 a = corners[i], ab = corners[(i + 1) % n] - a;
        const float len2 = glm::dot(ab, ab);
        const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
        const glm::vec2 q = a + t * ab;
        if (const float d2 = glm::dot(p - q, p - q); d2 < bestD2) {
            bestD2 = d2;
            best = q;
        }
    }
    return best;
}

std::vector<GroundTriangle> triangulatePolygon(std::span<const glm::vec2> corners)
{
    std::vector<GroundTriangle> out;
    if (corners.size() < 3)
        return out;
    std::vector<std::size_t> left(corners.size());
    for (std::size_t i = 0; i < left.size(); ++i)
        left[i] = i;
    if (signedPolygonArea(corners) < 0.0)
        std::reverse(left.begin(), left.end());
    out.reserve(corners.size() - 2);
    while (left.size() >= 3) {
        const std::size_t n = left.size();
        bool clipped = false;
        for (std::size_t k = 0; k < n && !clipped; ++k) {
            const std::size_t ip = left[(k + n - 1) % n], i = left[k], in = left[(k + 1) % n];
            const glm::dvec2 a = d(corners[ip]), b = d(corners[i]), c = d(corners[in]);
            const double turn = orient(a, b, c);
            if (turn < 0)
                continue;  // a reflex corner is never an ear
            bool ear = true;
            for (std::size_t m = 0; m < n && ear && turn > 0; ++m) {
                const std::size_t q = left[m];
                if (q == ip || q == i || q == in)
                    continue;
                const glm::dvec2 p = d(corners[q]);
                ear = p == a || p == b || p == c || !insideTriangle(a, b, c, p);
            }
            if (!ear)
                continue;
            // A straight corner (turn 0) goes without a triangle: it would have no area.
            if (turn > 0)
                out.push_back({corners[ip], corners[i], corners[in]});
            left.erase(left.begin() + std::ptrdiff_t(k));
            clipped = true;
        }
        if (!clipped)
            break;  // crosses itself: no ear left
    }
    return out;
}

}  // namespace throng::sim
