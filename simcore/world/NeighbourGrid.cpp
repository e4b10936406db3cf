#include "simcore/world/NeighbourGrid.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace throng::sim {

namespace {
constexpr int kMaxCellsPerAxis = 4096;
}

void NeighbourGrid::configure(glm::vec2 boundsMin, glm::vec2 boundsMax, float cellM)
{
    const glm::vec2 size = glm::max(boundsMax - boundsMin, glm::vec2(1.0f));
    // Cap the grid so a huge world with tiny agents still fits in memory; agents
    // outside the bounds are clamped into border cells.
    m_cell = std::max({cellM, size.x / kMaxCellsPerAxis, size.y / kMaxCellsPerAxis, 1e-3f});
    m_inv = 1.0f / m_cell;
    m_min = boundsMin;
    m_cols = std::max(1, int(std::ceil(size.x * m_inv)));
    m_rows = std::max(1, int(std::ceil(size.y * m_inv)));
    m_start.assign(std::size_t(m_cols) * std::size_t(m_rows) + 1, 0);
}

void NeighbourGrid::rebuild(std::span<const glm::vec3> positions, bool sortByHeight, std::span<const std::uint8_t> skip)
{
    const std::size_t n = positions.size();
    constexpr std::uint32_t kSkipped = UINT32_MAX;
    m_cellOf.resize(n);
    std::fill(m_start.begin(), m_start.end(), 0u);
    std::size_t indexed = 0;
    for (std::size_t i = 0; i < n; ++i) {
        if (i < skip.size() && skip[i]) {
            m_cellOf[i] = kSkipped;
            continue;
        }
        const std::uint32_t c = std::uint32_t(cellZ(positions[i].z) * m_cols + cellX(positions[i].x));
        m_cellOf[i] = c;
        ++m_start[c + 1];
        ++indexed;
    }
    m_sorted.resize(indexed);
    for (std::size_t c = 1; c < m_start.size(); ++c)
        m_start[c] += m_start[c - 1];
    // Counting sort, stable: indices stay ascending within a cell, so neighbour order
    // (and with it every float sum) is the same on every run.
    std::vector<std::uint32_t>& fill = m_cellOf;
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t c = fill[i];
        if (c == kSkipped)
            continue;
        fill[i] = m_start[c];  // reuse as the write cursor of the agent's slot
        ++m_start[c];
    }
    m_sortedPos.resize(indexed);
    for (std::size_t i = 0; i < n; ++i) {
        if (fill[i] == kSkipped)
            continue;
        m_sorted[fill[i]] = std::uint32_t(i);
        m_sortedPos[fill[i]] = positions[i];
    }
    // m_start[c] now holds the end of cell c; shift back to starts.
    for (std::size_t c = m_start.size() - 1; c > 0; --c)
        m_start[c] = m_start[c - 1];
    m_start[0] = 0;
    m_byHeight = sortByHeight;
    if (!sortByHeight)
        return;
    // Within each cell by height, ties by index: the order is fully determined. Cells hold
    // a few dozen agents, so an insertion sort in place (the indices arrive ascending, so
    // ties keep their order); std::sort for a crowded one.
    std::vector<std::pair<float, std::uint32_t>>& scratch = m_heightScratch;
    constexpr std::uint32_t kInsertionMax = 64;
    for (std::size_t c = 0; c + 1 < m_start.size(); ++c) {
        const std::uint32_t b = m_start[c], e = m_start[c + 1];
        if (e - b < 2)
            continue;
        if (e - b <= kInsertionMax) {
            for (std::uint32_t k = b + 1; k < e; ++k) {
                const glm::vec3 q = m_sortedPos[k];
                const std::uint32_t j = m_sorted[k];
                std::uint32_t at = k;
                for (; at > b && q.y < m_sortedPos[at - 1].y; --at) {
                    m_sortedPos[at] = m_sortedPos[at - 1];
                    m_sorted[at] = m_sorted[at - 1];
                }
                m_sortedPos[at] = q;
                m_sorted[at] = j;
            }
            continue;
        }
        scratch.clear();
        for (std::uint32_t k = b; k < e; ++k)
            scratch.push_back({m_sortedPos[k].y, m_sorted[k]});
        std::sort(scratch.begin(), scratch.end());
        for (std::uint32_t k = b; k < e; ++k) {
            m_sorted[k] = scratch[k - b].second;
            m_sortedPos[k] = positions[m_sorted[k]];
        }
    }
}

}  // namespace throng::sim
