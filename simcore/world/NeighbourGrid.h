#pragma once
// A uniform grid over agent positions, rebuilt each step by counting sort (O(N)); a
// query visits only the cells a radius overlaps. Holds indices, never agent data.

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace throng::sim {

class NeighbourGrid {
public:
    // cellM: cell edge in metres (> 0), usually the largest perception radius.
    void configure(glm::vec2 boundsMin, glm::vec2 boundsMax, float cellM);
    // Sorts agent indices into cells by their (x, z). Reuses its buffers.
    void rebuild(std::span<const glm::vec3> positions);

    // Calls f(j) for every agent j whose cell overlaps the square around p of half-size r.
    template <typename F>
    void forEachNear(glm::vec2 p, float r, F&& f) const
    {
        const int x0 = cellX(p.x - r), x1 = cellX(p.x + r), z0 = cellZ(p.y - r), z1 = cellZ(p.y + r);
        for (int z = z0; z <= z1; ++z)
            for (int x = x0; x <= x1; ++x) {
                const std::size_t c = std::size_t(z) * std::size_t(m_cols) + std::size_t(x);
                for (std::uint32_t k = m_start[c]; k < m_start[c + 1]; ++k)
                    f(m_sorted[k]);
            }
    }
    float cellM() const { return m_cell; }

private:
    int cellX(float x) const;
    int cellZ(float z) const;

    glm::vec2 m_min{0.0f};
    float m_cell = 1.0f, m_inv = 1.0f;
    int m_cols = 1, m_rows = 1;
    std::vector<std::uint32_t> m_start;   // cols*rows + 1 prefix sums
    std::vector<std::uint32_t> m_sorted;  // agent indices by cell
    std::vector<std::uint32_t> m_cellOf;
};

}  // namespace throng::sim
