#pragma once
// Shortest paths on a NavGrid: 8-connected A* (a diagonal step only where both cells it
// passes beside are walkable), octile heuristic, deterministic tie-breaking, and
// line-of-sight smoothing down to corner waypoints. Reuses its own scratch arrays, so one
// AStar serves one thread; never moves agents.

#include "simcore/nav/NavGrid.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <vector>

namespace throng::sim {

enum class PlanStatus { Found, StartBlocked, GoalBlocked, Unreachable };
const char* toString(PlanStatus status);

struct NavPlan {
    PlanStatus status = PlanStatus::Unreachable;
    std::vector<NavCell> cells;         // the A* path, start to goal inclusive (Found only)
    std::vector<NavCell> corners;       // smoothed: start, the corners, goal
    std::vector<glm::vec2> waypoints;   // centres of corners after the start, in metres; never
                                        // empty when found (start == goal: the start's centre)
    float lengthM = 0.0f;               // length of the A* path (cells), m
    float smoothedLengthM = 0.0f;       // length through the corners, m, <= lengthM
    std::uint64_t generation = 0;       // the grid generation the plan was made on
    bool found() const { return status == PlanStatus::Found; }
};

// Octile distance in cells: the exact 8-connected distance on an empty grid, so never
// more than the true path length (admissible).
double octileCells(NavCell a, NavCell b);

// True when the straight segment between the centres of a and b touches only walkable
// cells (every cell it enters; where it passes exactly through a corner, both side cells).
bool lineOfSight(const NavGrid& grid, NavCell a, NavCell b);

// The same for any two points (an agent's own position to a waypoint, say): true when the
// segment from a to b touches only walkable cells; where it passes exactly through a cell
// corner both side cells must be walkable.
bool lineOfSight(const NavGrid& grid, glm::vec2 a, glm::vec2 b);

// Greedy string pulling: keeps a cell only where the next cell is not visible from the
// last kept one. First and last cells are always kept.
std::vector<NavCell> smoothPath(const NavGrid& grid, const std::vector<NavCell>& cells);

class AStar {
public:
    // Plans from start to goal. Blocked or outside ends give StartBlocked/GoalBlocked (snap
    // them with NavGrid::nearestWalkable first); a goal in another component gives
    // Unreachable after the start's component is exhausted: never loops.
    NavPlan plan(const NavGrid& grid, NavCell start, NavCell goal);
    // Cells taken off the open list by the last plan (a cost figure for benches and tests).
    int expandedLast() const { return m_expanded; }

private:
    struct Open {
        double f, g;
        int cell;
    };
    std::vector<double> m_g;
    std::vector<int> m_parent;
    std::vector<std::uint32_t> m_stamp;   // m_g/m_parent valid where m_stamp == m_search
    std::vector<std::uint32_t> m_closed;  // expanded in this search where == m_search
    std::vector<Open> m_heap;
    std::uint32_t m_search = 0;
    int m_expanded = 0;
};

// The re-plan for a stuck agent (no progress for a while, see NavFollow's StallWatch): as
// astar.plan(), but cells whose centres lie within avoidRadiusM of avoidAt (the jam or the
// obstacle it keeps pushing against) count as blocked, start and goal excepted. The plan
// carries the grid's own generation; it is not for sharing through a PlanCache.
// Unreachable means there is no way round: side-step or wait instead.
NavPlan planAround(AStar& astar, const NavGrid& grid, NavCell start, NavCell goal, glm::vec2 avoidAt,
                   float avoidRadiusM);

}  // namespace throng::sim
