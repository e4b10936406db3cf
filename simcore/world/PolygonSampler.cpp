#include "simcore/world/PolygonSampler.h"

#include <algorithm>
#include <cmath>

namespace throng::sim {

PolygonSampler::PolygonSampler(std::span<const glm::vec2> corners) : m_triangles(triangulatePolygon(corners))
{
    double sum = 0.0;
    m_cumulativeArea.reserve(m_triangles.size());
    for (const GroundTriangle& t : m_triangles) {
        sum += std::abs(signedPolygonArea(t));
        m_cumulativeArea.push_back(sum);
    }
}

glm::vec2 PolygonSampler::at(float pick, float u, float v) const
{
    if (m_triangles.empty())
        return glm::vec2(0.0f);
    const double target = double(pick) * m_cumulativeArea.back();
    const auto it = std::upper_bound(m_cumulativeArea.begin(), m_cumulativeArea.end(), target);
    const std::size_t k = std::min(std::size_t(it - m_cumulativeArea.begin()), m_triangles.size() - 1);
    // Folding the far half of the unit square back onto the triangle keeps the density
    // uniform (Osada et al. 2002 use sqrt instead; both are exact).
    if (u + v > 1.0f) {
        u = 1.0f - u;
        v = 1.0f - v;
    }
    const GroundTriangle& t = m_triangles[k];
    return t[0] + u * (t[1] - t[0]) + v * (t[2] - t[0]);
}

}  // namespace throng::sim
