#include "simcore/base/SegmentGrid.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::sim {

namespace {
constexpr int kMaxCellsPerAxis = 2048;
}

void SegmentGrid::build(std::span<const Segment> segments, float cellM, glm::vec2 focusMin, glm::vec2 focusMax)
{
    m_segments.assign(segments.begin(), segments.end());
    m_start.clear();
    m_items.clear();
    m_cols = m_rows = 0;
    if (m_segments.empty())
        return;
    glm::vec2 lo(INFINITY), hi(-INFINITY);
    for (const Segment& s : m_segments) {
        lo = glm::min(lo, glm::min(s.a, s.b));
        hi = glm::max(hi, glm::max(s.a, s.b));
    }
    // Clip to the focus unless nothing is left of the extent on an axis (all segments
    // lie beyond it, and a query at the focus finds none of them anyway).
    const glm::vec2 clipLo = glm::max(lo, focusMin), clipHi = glm::min(hi, focusMax);
    m_clippedLo = m_clippedHi = glm::bvec2(false);
    for (int k = 0; k < 2; ++k)
        if (clipLo[k] <= clipHi[k]) {
            m_clippedLo[k] = clipLo[k] > lo[k];
            m_clippedHi[k] = clipHi[k] < hi[k];
            lo[k] = clipLo[k];
            hi[k] = clipHi[k];
        }
    const glm::vec2 size = glm::max(hi - lo, glm::vec2(1e-3f));
    const float cell = std::max({cellM, size.x / kMaxCellsPerAxis, size.y / kMaxCellsPerAxis});
    m_inv = 1.0f / cell;
    m_cell = cell;
    m_min = lo;
    m_cols = std::max(1, int(std::ceil(size.x * m_inv)) + 1);
    m_rows = std::max(1, int(std::ceil(size.y * m_inv)) + 1);

    // Each segment goes into every cell its bounding box touches (conservative), counted
    // first, then filled in segment order so each cell's list is ascending.
    std::vector<std::uint32_t> count(std::size_t(m_cols) * std::size_t(m_rows) + 1, 0);
    auto visit = [&](const Segment& s, auto&& f) {
        const glm::vec2 a = glm::min(s.a, s.b), b = glm::max(s.a, s.b);
        const int x0 = std::clamp(cellX(a.x), 0, m_cols - 1), x1 = std::clamp(cellX(b.x), 0, m_cols - 1);
        for (int z = std::clamp(cellZ(a.y), 0, m_rows - 1); z <= std::clamp(cellZ(b.y), 0, m_rows - 1); ++z)
            for (int x = x0; x <= x1; ++x)
                f(std::size_t(z) * std::size_t(m_cols) + std::size_t(x));
    };
    for (const Segment& s : m_segments)
        visit(s, [&](std::size_t c) { ++count[c + 1]; });
    for (std::size_t c = 1; c < count.size(); ++c)
        count[c] += count[c - 1];
    m_start = count;
    m_items.resize(count.back());
    for (std::uint32_t i = 0; i < m_segments.size(); ++i)
        visit(m_segments[i], [&](std::size_t c) { m_items[count[c]++] = i; });
}

}  // namespace throng::sim
