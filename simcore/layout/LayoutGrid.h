#pragma once
// A grid of agents by cell over a box on the ground, for the layout layer's neighbour
// searches (the check after the edits, the resolve): counts, then one array in cell order,
// built once and searched in constant time per cell. Points outside the box go to its edge
// cells. Internal to simcore/layout.

#include "simcore/world/FrameCache.h"

#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

namespace throng::sim::layout {

class CellGrid {
public:
    // Cells of `cell` over [lo, hi], or coarser when that would make more than a few cells
    // per agent (agents kilometres apart make a coarse grid, never a huge one).
    static CellGrid fitting(glm::vec2 lo, glm::vec2 hi, float cell, std::size_t agents)
    {
        const double area = double(hi.x - lo.x) * double(hi.y - lo.y);
        const double cap = 16.0 * double(agents) + 4096.0;
        if (area / (double(cell) * double(cell)) > cap)
            cell = float(std::sqrt(area / cap));
        return CellGrid(lo, hi, cell);
    }
    CellGrid(glm::vec2 lo, glm::vec2 hi, float cell)
        : m_lo(lo), m_cell(cell),
          m_cols(std::max(1, int(std::ceil((hi.x - lo.x) / cell)))),
          m_rows(std::max(1, int(std::ceil((hi.y - lo.y) / cell))))
    {
    }
    std::size_t cells() const { return std::size_t(m_cols) * std::size_t(m_rows); }
    void build(std::span<const AgentFrame> laid, const std::vector<std::uint32_t>& agents)
    {
        m_start.assign(cells() + 1, 0);
        m_cellOf.resize(agents.size());
        for (std::size_t k = 0; k < agents.size(); ++k) {
            const AgentFrame& a = laid[agents[k]];
            m_cellOf[k] = cellIndex({a.position.x, a.position.z});
            ++m_start[m_cellOf[k] + 1];
        }
        for (std::size_t c = 0; c < cells(); ++c)
            m_start[c + 1] += m_start[c];
        m_items.resize(agents.size());
        std::vector<std::uint32_t> fill(m_start.begin(), m_start.end() - 1);
        for (std::size_t k = 0; k < agents.size(); ++k)
            m_items[fill[m_cellOf[k]]++] = agents[k];
    }
    template <class F>
    void forNear(glm::vec2 p, F f) const
    {
        const int cx = column(p.x), cz = row(p.y);
        for (int z = std::max(0, cz - 1); z <= std::min(m_rows - 1, cz + 1); ++z)
            for (int x = std::max(0, cx - 1); x <= std::min(m_cols - 1, cx + 1); ++x) {
                const std::size_t c = std::size_t(z) * std::size_t(m_cols) + std::size_t(x);
                for (std::uint32_t k = m_start[c]; k < m_start[c + 1]; ++k)
                    f(std::size_t(m_items[k]));
            }
    }

private:
    int column(float x) const { return std::clamp(int(std::floor((x - m_lo.x) / m_cell)), 0, m_cols - 1); }
    int row(float z) const { return std::clamp(int(std::floor((z - m_lo.y) / m_cell)), 0, m_rows - 1); }
    std::uint32_t cellIndex(glm::vec2 p) const { return std::uint32_t(row(p.y) * m_cols + column(p.x)); }

    glm::vec2 m_lo;
    float m_cell;
    int m_cols, m_rows;
    std::vector<std::uint32_t> m_start, m_items, m_cellOf;
};

}  // namespace throng::sim::layout
