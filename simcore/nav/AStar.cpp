#include "simcore/nav/AStar.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace throng::sim {

namespace {

constexpr double kSqrt2 = 1.4142135623730951;
constexpr int kDx[8] = {1, -1, 0, 0, 1, 1, -1, -1};
constexpr int kDz[8] = {0, 0, 1, -1, 1, -1, 1, -1};

// Min-heap order: lower f first; on equal f the deeper node (higher g) first, then the
// lower cell index, so the expansion order never depends on container details.
bool after(const auto& a, const auto& b)
{
    if (a.f != b.f)
        return a.f > b.f;
    if (a.g != b.g)
        return a.g < b.g;
    return a.cell > b.cell;
}

}  // namespace

const char* toString(PlanStatus status)
{
    switch (status) {
    case PlanStatus::Found: return "found";
    case PlanStatus::StartBlocked: return "start blocked";
    case PlanStatus::GoalBlocked: return "goal blocked";
    case PlanStatus::Unreachable: return "unreachable";
    }
    return "?";
}

double octileCells(NavCell a, NavCell b)
{
    const int dx = std::abs(a.x - b.x), dz = std::abs(a.z - b.z);
    return double(std::max(dx, dz) - std::min(dx, dz)) + kSqrt2 * double(std::min(dx, dz));
}

bool lineOfSight(const NavGrid& grid, NavCell a, NavCell b)
{
    // Walks every cell the segment enters (Amanatides & Woo on cell centres, integer form).
    if (!grid.walkable(a) || !grid.walkable(b))
        return false;
    const int nx = std::abs(b.x - a.x), nz = std::abs(b.z - a.z);
    const int sx = b.x > a.x ? 1 : -1, sz = b.z > a.z ? 1 : -1;
    NavCell c = a;
    for (int ix = 0, iz = 0; ix < nx || iz < nz;) {
        const long decision = long(1 + 2 * ix) * nz - long(1 + 2 * iz) * nx;
        if (decision == 0) {
            if (!grid.walkable({c.x + sx, c.z}) || !grid.walkable({c.x, c.z + sz}))
                return false;
            c.x += sx;
            c.z += sz;
            ++ix;
            ++iz;
        } else if (decision < 0) {
            c.x += sx;
            ++ix;
        } else {
            c.z += sz;
            ++iz;
        }
        if (!grid.walkable(c))
            return false;
    }
    return true;
}

bool lineOfSight(const NavGrid& grid, glm::vec2 a, glm::vec2 b)
{
    // Amanatides & Woo: step to whichever cell boundary the segment reaches first.
    NavCell c = grid.cellOf(a);
    const NavCell last = grid.cellOf(b);
    if (!grid.walkable(c) || !grid.walkable(last))
        return false;
    const glm::vec2 d = b - a, q = (a - grid.origin()) / grid.cellM();
    const int sx = d.x > 0.0f ? 1 : -1, sz = d.y > 0.0f ? 1 : -1;
    constexpr float inf = std::numeric_limits<float>::infinity();
    // Parameter t in [0, 1] along the segment at which the next x / z boundary is crossed.
    const float dx = d.x / grid.cellM(), dz = d.y / grid.cellM();
    float tx = dx != 0.0f ? ((sx > 0 ? std::floor(q.x) + 1.0f : std::floor(q.x)) - q.x) / dx : inf;
    float tz = dz != 0.0f ? ((sz > 0 ? std::floor(q.y) + 1.0f : std::floor(q.y)) - q.y) / dz : inf;
    const float stepX = dx != 0.0f ? std::abs(1.0f / dx) : inf, stepZ = dz != 0.0f ? std::abs(1.0f / dz) : inf;
    const int steps = std::abs(last.x - c.x) + std::abs(last.z - c.z);
    for (int k = 0; k < steps && !(c == last); ++k) {
        if (std::abs(tx - tz) <= 1e-5f) {  // through a corner, give or take rounding: both sides
            if (!grid.walkable({c.x + sx, c.z}) || !grid.walkable({c.x, c.z + sz}))
                return false;
            c.x += sx;
            c.z += sz;
            tx += stepX;
            tz += stepZ;
            ++k;
        } else if (tx < tz) {
            c.x += sx;
            tx += stepX;
        } else {
            c.z += sz;
            tz += stepZ;
        }
        if (!grid.walkable(c))
            return false;
    }
    return true;
}

std::vector<NavCell> smoothPath(const NavGrid& grid, const std::vector<NavCell>& cells)
{
    if (cells.size() <= 2)
        return cells;
    std::vector<NavCell> out{cells.front()};
    for (std::size_t k = 2; k < cells.size(); ++k)
        if (!lineOfSight(grid, out.back(), cells[k]))
            out.push_back(cells[k - 1]);
    out.push_back(cells.back());
    // Greedy pulling can keep a corner whose two neighbours see each other after all
    // (visibility is not monotone along the path): drop those until none is left.
    for (bool dropped = true; dropped;) {
        dropped = false;
        for (std::size_t k = 1; k + 1 < out.size(); ++k)
            if (lineOfSight(grid, out[k - 1], out[k + 1])) {
                out.erase(out.begin() + std::ptrdiff_t(k));
                dropped = true;
            }
    }
    return out;
}

NavPlan AStar::plan(const NavGrid& grid, NavCell start, NavCell goal)
{
    NavPlan result;
    result.generation = grid.generation();
    m_expanded = 0;
    if (!grid.walkable(start)) {
        result.status = PlanStatus::StartBlocked;
        return result;
    }
    if (!grid.walkable(goal)) {
        result.status = PlanStatus::GoalBlocked;
        return result;
    }
    const std::size_t n = std::size_t(grid.cellCount());
    if (m_g.size() != n) {
        m_g.assign(n, 0.0);
        m_parent.assign(n, -1);
        m_stamp.assign(n, 0);
        m_closed.assign(n, 0);
        m_search = 0;
    }
    if (++m_search == 0) {  // the stamp wrapped: forget every old search
        std::fill(m_stamp.begin(), m_stamp.end(), 0u);
        std::fill(m_closed.begin(), m_closed.end(), 0u);
        m_search = 1;
    }
    const int s = grid.index(start), t = grid.index(goal);
    m_heap.clear();
    m_g[std::size_t(s)] = 0.0;
    m_parent[std::size_t(s)] = -1;
    m_stamp[std::size_t(s)] = m_search;
    m_heap.push_back({octileCells(start, goal), 0.0, s});
    const auto cmp = [](const Open& a, const Open& b) { return after(a, b); };
    bool reached = false;
    while (!m_heap.empty()) {
        std::pop_heap(m_heap.begin(), m_heap.end(), cmp);
        const Open top = m_heap.back();
        m_heap.pop_back();
        // A stale entry (the cell was reached more cheaply since), or a cell already
        // expanded: the octile heuristic is consistent, so its first expansion was optimal.
        if (top.g > m_g[std::size_t(top.cell)] || m_closed[std::size_t(top.cell)] == m_search)
            continue;
        m_closed[std::size_t(top.cell)] = m_search;
        ++m_expanded;
        if (top.cell == t) {
            reached = true;
            break;
        }
        const NavCell c = grid.cellAt(top.cell);
        for (int k = 0; k < 8; ++k) {
            const NavCell nb{c.x + kDx[k], c.z + kDz[k]};
            if (!grid.walkable(nb))
                continue;
            // No corner cutting: a diagonal step needs both cells beside it walkable.
            if (k >= 4 && (!grid.walkable({c.x + kDx[k], c.z}) || !grid.walkable({c.x, c.z + kDz[k]})))
                continue;
            const int i = grid.index(nb);
            const double g = top.g + (k >= 4 ? kSqrt2 : 1.0);
            if (m_closed[std::size_t(i)] == m_search ||
                (m_stamp[std::size_t(i)] == m_search && g >= m_g[std::size_t(i)]))
                continue;
            m_stamp[std::size_t(i)] = m_search;
            m_g[std::size_t(i)] = g;
            m_parent[std::size_t(i)] = top.cell;
            m_heap.push_back({g + octileCells(nb, goal), g, i});
            std::push_heap(m_heap.begin(), m_heap.end(), cmp);
        }
    }
    if (!reached) {
        result.status = PlanStatus::Unreachable;
        return result;
    }
    result.status = PlanStatus::Found;
    for (int i = t; i >= 0; i = m_parent[std::size_t(i)])
        result.cells.push_back(grid.cellAt(i));
    std::reverse(result.cells.begin(), result.cells.end());
    result.lengthM = float(m_g[std::size_t(t)] * double(grid.cellM()));
    result.corners = smoothPath(grid, result.cells);
    if (result.corners.size() == 1)  // start == goal: the one waypoint is where the agent stands
        result.waypoints.push_back(grid.centre(result.corners[0]));
    for (std::size_t k = 1; k < result.corners.size(); ++k) {
        result.waypoints.push_back(grid.centre(result.corners[k]));
        result.smoothedLengthM += glm::distance(grid.centre(result.corners[k - 1]), result.waypoints.back());
    }
    return result;
}

NavPlan planAround(AStar& astar, const NavGrid& grid, NavCell start, NavCell goal, glm::vec2 avoidAt,
                   float avoidRadiusM)
{
    NavGrid detour = grid;
    const NavCell c0 = grid.cellOf(avoidAt - glm::vec2(avoidRadiusM)),
                  c1 = grid.cellOf(avoidAt + glm::vec2(avoidRadiusM));
    for (int z = std::max(c0.z, 0); z <= std::min(c1.z, grid.rows() - 1); ++z)
        for (int x = std::max(c0.x, 0); x <= std::min(c1.x, grid.cols() - 1); ++x)
            if (!(NavCell{x, z} == start) && !(NavCell{x, z} == goal) &&
                glm::distance(grid.centre({x, z}), avoidAt) <= avoidRadiusM)
                detour.setWalkable({x, z}, false);
    NavPlan plan = astar.plan(detour, start, goal);
    plan.generation = grid.generation();
    return plan;
}

}  // namespace throng::sim
