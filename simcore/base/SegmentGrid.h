#pragma once
// Static line segments (walls, box obstacle sides) bucketed into a uniform grid once,
// so an agent asks only about the segments near it. Built at World compile time;
// never changes during a step and never allocates in a query.

#include <glm/vec2.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

namespace throng::sim {

struct Segment {
    glm::vec2 a{0.0f}, b{0.0f};
};

class SegmentGrid {
public:
    // cellM: cell edge in metres, > 0 (a few agent radii works well). The cells cover the
    // segments' extent clipped to [focusMin, focusMax] (where queries happen); segments
    // beyond it are kept in the border cells, so every query still finds them.
    void build(std::span<const Segment> segments, float cellM, glm::vec2 focusMin = glm::vec2(-INFINITY),
               glm::vec2 focusMax = glm::vec2(INFINITY));

    // Calls f(segmentIndex) once for each segment whose cells overlap the square
    // [p - r, p + r]. Indices come in ascending order, so results never depend on how
    // segments were bucketed.
    template <typename F>
    void forEachNear(glm::vec2 p, float r, F&& f) const
    {
        if (m_segments.empty())
            return;
        int x0 = cellX(p.x - r), x1 = cellX(p.x + r), z0 = cellZ(p.y - r), z1 = cellZ(p.y + r);
        // Past a clipped side, the border cells hold what lies beyond.
        if ((x1 < 0 && !m_clippedLo.x) || (z1 < 0 && !m_clippedLo.y) || (x0 >= m_cols && !m_clippedHi.x) ||
            (z0 >= m_rows && !m_clippedHi.y))
            return;
        x0 = std::clamp(x0, 0, m_cols - 1);
        x1 = std::clamp(x1, 0, m_cols - 1);
        z0 = std::clamp(z0, 0, m_rows - 1);
        z1 = std::clamp(z1, 0, m_rows - 1);
        if (x0 == x1 && z0 == z1) {  // the common case: one cell, already sorted and unique
            const std::size_t c = std::size_t(z0) * std::size_t(m_cols) + std::size_t(x0);
            for (std::uint32_t k = m_start[c]; k < m_start[c + 1]; ++k)
                f(m_items[k]);
            return;
        }
        // Over more cells than there are segments (a feeler kilometres long), the merge
        // below would cost cells x results: test each segment's box against the cells'
        // extent instead: the segments whose boxes reach those cells, in index order.
        const std::size_t span = std::size_t(x1 - x0 + 1) * std::size_t(z1 - z0 + 1);
        if (span > m_segments.size()) {
            const glm::vec2 lo(x0 == 0 && m_clippedLo.x ? -INFINITY : m_min.x + float(x0) * m_cell,
                               z0 == 0 && m_clippedLo.y ? -INFINITY : m_min.y + float(z0) * m_cell);
            const glm::vec2 hi(x1 == m_cols - 1 && m_clippedHi.x ? INFINITY : m_min.x + float(x1 + 1) * m_cell,
                               z1 == m_rows - 1 && m_clippedHi.y ? INFINITY : m_min.y + float(z1 + 1) * m_cell);
            for (std::uint32_t k = 0; k < m_segments.size(); ++k) {
                const Segment& s = m_segments[k];
                if (std::max(s.a.x, s.b.x) >= lo.x && std::min(s.a.x, s.b.x) <= hi.x &&
                    std::max(s.a.y, s.b.y) >= lo.y && std::min(s.a.y, s.b.y) <= hi.y)
                    f(k);
            }
            return;
        }
        // Several cells: merge their sorted lists, skipping repeats.
        std::uint32_t last = UINT32_MAX;
        for (;;) {
            std::uint32_t best = UINT32_MAX;
            for (int z = std::max(z0, 0); z <= std::min(z1, m_rows - 1); ++z)
                for (int x = std::max(x0, 0); x <= std::min(x1, m_cols - 1); ++x) {
                    const std::size_t c = std::size_t(z) * std::size_t(m_cols) + std::size_t(x);
                    for (std::uint32_t k = m_start[c]; k < m_start[c + 1]; ++k)
                        if (m_items[k] > last || last == UINT32_MAX) {
                            if (m_items[k] < best)
                                best = m_items[k];
                            break;
                        }
                }
            if (best == UINT32_MAX)
                return;
            f(best);
            last = best;
        }
    }

    const std::vector<Segment>& segments() const { return m_segments; }
    const Segment& segment(std::uint32_t i) const { return m_segments[i]; }

private:
    // Inline: every wall query (steering, constraint, commit) asks for four of these.
    int cellX(float x) const
    {
        const float c = std::floor((x - m_min.x) * m_inv);
        return c != c ? 0 : int(std::clamp(c, -1.0f, float(m_cols)));
    }
    int cellZ(float z) const
    {
        const float c = std::floor((z - m_min.y) * m_inv);
        return c != c ? 0 : int(std::clamp(c, -1.0f, float(m_rows)));
    }

    std::vector<Segment> m_segments;
    glm::vec2 m_min{0.0f};
    float m_inv = 1.0f;
    float m_cell = 1.0f;  // 1 / m_inv
    int m_cols = 0, m_rows = 0;
    glm::bvec2 m_clippedLo{false}, m_clippedHi{false};  // sides where segments reach past the cells
    std::vector<std::uint32_t> m_start;  // prefix sums, cols*rows + 1
    std::vector<std::uint32_t> m_items;  // segment indices, ascending within a cell
};

}  // namespace throng::sim
