#pragma once
// A flow field over a NavGrid: the travel distance from every walkable cell to the nearest
// of one or several goals (fast marching, Sethian 1996: a first-order upwind Eikonal solve
// with axis and diagonal stencils, Hassouna & Farag 2007), and a unit direction per cell down that distance that never
// leads into a blocked cell. Thousands of agents read it at the cost of one lookup; it never moves agents and never
// changes after build.

#include "simcore/nav/NavGrid.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace throng::sim {

// A goal region: every walkable cell whose centre lies within radiusM of centre is a goal
// cell; when none does, the walkable cell nearest to the centre is.
struct FlowGoal {
    glm::vec2 centre{0.0f};
    float radiusM = 1.0f;  // m, >= 0
};

class FlowField {
public:
    // Takes a copy of the grid (flags only are kept; a few bytes a cell).
    void build(const NavGrid& grid, std::span<const NavCell> goalCells);
    void build(const NavGrid& grid, std::span<const FlowGoal> goals);

    const NavGrid& grid() const { return m_grid; }
    // The grid generation built on: differs from the live grid's after an edit (rebuild).
    std::uint64_t generation() const { return m_grid.generation(); }

    // Travel distance to the nearest goal in metres; +infinity for blocked cells and cells
    // no goal can be reached from.
    float distanceM(NavCell c) const;
    bool reachable(NavCell c) const;
    bool isGoal(NavCell c) const { return reachable(c) && distanceM(c) == 0.0f; }
    // Unit direction of travel at a cell centre; zero at goal, blocked and unreachable cells.
    glm::vec2 direction(NavCell c) const;

    // O(1): bilinear blend of the directions of the walkable cells around p, normalised;
    // a blend that would lead into a blocked cell within half a cell falls back to the cell's
    // own direction, then to the way to the cell's centre. Zero outside the grid, in a blocked
    // or unreachable cell, or in a goal cell.
    glm::vec2 sample(glm::vec2 p) const;

    // Cells popped by the last build (the marching front's work, a bench figure).
    int settledCells() const { return m_settled; }

private:
    void march(std::span<const int> seeds);
    void buildDirections();
    bool clearAhead(glm::vec2 p, glm::vec2 d) const;

    NavGrid m_grid;
    std::vector<float> m_distance;  // m, per cell
    std::vector<glm::vec2> m_dir;   // unit or zero, per cell
    int m_settled = 0;
};

}  // namespace throng::sim
