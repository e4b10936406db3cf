#pragma once
// A walkable/blocked grid over the scene bounds: a cell is blocked when a wall or obstacle
// comes within an agent radius of its centre, or within 0.75 of a cell (so every cell a
// shape touches is blocked, and walls stay watertight however coarse the cells).
// Answers cell queries in O(1); never plans and never moves agents.

#include "simcore/nav/NavShapes.h"

#include <glm/vec2.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

namespace throng::sim {

struct NavCell {
    int x = 0, z = 0;  // column (along x) and row (along z)
    bool operator==(const NavCell&) const = default;
};

struct NavGridParams {
    float cellM = 0.5f;          // m, > 0: cell edge
    float agentRadiusM = 0.3f;   // m, >= 0: every shape is inflated by this
};

class NavGrid {
public:
    NavGrid() = default;
    // An all-walkable grid of cols x rows cells whose cell (0, 0) starts at origin.
    NavGrid(int cols, int rows, glm::vec2 origin, float cellM);

    // Covers scene.settings bounds; blocks every cell whose centre lies within agentRadiusM
    // (or 0.75 of a cell, whichever is more) of a wall segment, circle or box (inside counts).
    void build(const Scene& scene, const NavGridParams& params);
    void build(const NavShapes& shapes, glm::vec2 boundsMin, glm::vec2 boundsMax, const NavGridParams& params);

    int cols() const { return m_cols; }
    int rows() const { return m_rows; }
    float cellM() const { return m_cellM; }
    glm::vec2 origin() const { return m_origin; }
    int cellCount() const { return m_cols * m_rows; }

    bool inside(NavCell c) const { return c.x >= 0 && c.z >= 0 && c.x < m_cols && c.z < m_rows; }
    // Outside the grid counts as blocked.
    bool walkable(NavCell c) const { return inside(c) && m_walkable[std::size_t(index(c))] != 0; }
    bool walkableIndex(int i) const { return m_walkable[std::size_t(i)] != 0; }
    int index(NavCell c) const { return c.z * m_cols + c.x; }
    NavCell cellAt(int index) const { return {index % m_cols, index / m_cols}; }

    // The cell containing p (possibly outside the grid: check inside()).
    NavCell cellOf(glm::vec2 p) const;
    glm::vec2 centre(NavCell c) const;
    // The walkable cell nearest to c by centre distance (ties: lowest row, then column);
    // c itself when walkable; {-1, -1} when the grid has no walkable cell.
    NavCell nearestWalkable(NavCell c) const;

    // True when the points a quarter and a half cell from p along the unit direction d lie
    // in walkable cells: d does not lead into a blocked cell (the test every field passes).
    bool clearAhead(glm::vec2 p, glm::vec2 d) const;
    // The bilinear blend at p of a vector each cell holds at its centre, value(NavCell),
    // over the four centres round p (the fields' sample: FlowField, SketchField). Cells
    // outside the grid are asked too: value answers for them.
    template <class Value>
    glm::vec2 blendAtCentres(glm::vec2 p, Value&& value) const
    {
        const glm::vec2 q = (p - m_origin) / m_cellM - 0.5f;
        const int x0 = int(std::floor(q.x)), z0 = int(std::floor(q.y));
        const float fx = q.x - float(x0), fz = q.y - float(z0);
        glm::vec2 sum(0.0f);
        for (int k = 0; k < 4; ++k) {
            const float w = ((k & 1) ? fx : 1.0f - fx) * ((k >> 1) ? fz : 1.0f - fz);
            sum += w * value(NavCell{x0 + (k & 1), z0 + (k >> 1)});
        }
        return sum;
    }

    // Marks one cell; a change gives the grid a new generation() so cached plans and fields
    // know to re-plan (the scene changed). Generations are unique across grids; copies share
    // theirs until either changes.
    void setWalkable(NavCell c, bool walkable);
    std::uint64_t generation() const { return m_generation; }

private:
    void blockNearSegment(const Segment& s, float r);
    void blockNearCircle(const NavCircle& c, float r);
    void blockNearBox(const NavBox& b, float r);
    glm::vec2 cellMin(NavCell c) const;

    int m_cols = 0, m_rows = 0;
    glm::vec2 m_origin{0.0f};
    float m_cellM = 1.0f;
    std::vector<std::uint8_t> m_walkable;  // rows * cols, row-major along x
    std::uint64_t m_generation = 0;
};

}  // namespace throng::sim
