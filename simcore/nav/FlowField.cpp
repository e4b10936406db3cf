#include "simcore/nav/FlowField.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace throng::sim {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

struct Front {
    double t;
    int cell;
};

// Min-heap on arrival time; equal times pop in cell order, so the march is deterministic.
bool later(const Front& a, const Front& b) { return a.t != b.t ? a.t > b.t : a.cell > b.cell; }

}  // namespace

void FlowField::build(const NavGrid& grid, std::span<const FlowGoal> goals)
{
    std::vector<NavCell> cells;
    for (const FlowGoal& g : goals) {
        const NavCell c0 = grid.cellOf(g.centre - glm::vec2(g.radiusM)), c1 = grid.cellOf(g.centre + glm::vec2(g.radiusM));
        bool any = false;
        for (int z = std::max(c0.z, 0); z <= std::min(c1.z, grid.rows() - 1); ++z)
            for (int x = std::max(c0.x, 0); x <= std::min(c1.x, grid.cols() - 1); ++x)
                if (grid.walkable({x, z}) && glm::distance(grid.centre({x, z}), g.centre) <= g.radiusM) {
                    cells.push_back({x, z});
                    any = true;
                }
        if (!any) {
            const NavCell n = grid.nearestWalkable(grid.cellOf(g.centre));
            if (grid.walkable(n))
                cells.push_back(n);
        }
    }
    build(grid, cells);
}

void FlowField::build(const NavGrid& grid, std::span<const NavCell> goalCells)
{
    m_grid = grid;
    std::vector<int> seeds;
    for (NavCell c : goalCells)
        if (grid.walkable(c))
            seeds.push_back(grid.index(c));
    std::sort(seeds.begin(), seeds.end());
    seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
    march(seeds);
    buildDirections();
}

void FlowField::march(std::span<const int> seeds)
{
    const int n = m_grid.cellCount(), cols = m_grid.cols();
    const double h = double(m_grid.cellM());
    std::vector<double> t(std::size_t(n), std::numeric_limits<double>::infinity());
    std::vector<std::uint8_t> frozen(std::size_t(n), 0);
    std::vector<Front> heap;
    heap.reserve(std::size_t(n) / 4 + seeds.size());
    for (int s : seeds) {
        t[std::size_t(s)] = 0.0;
        heap.push_back({0.0, s});
    }
    std::make_heap(heap.begin(), heap.end(), later);
    // The smaller frozen time of the two neighbours of c at c +- (dx, dz) (inf if none);
    // a diagonal neighbour counts only where both cells beside the step are walkable.
    const auto upwind = [&](NavCell c, int dx, int dz) {
        double best = std::numeric_limits<double>::infinity();
        for (int s = -1; s <= 1; s += 2) {
            const NavCell nb{c.x + s * dx, c.z + s * dz};
            if (!m_grid.inside(nb) || frozen[std::size_t(m_grid.index(nb))] == 0)
                continue;
            if (dx != 0 && dz != 0 && (!m_grid.walkable({nb.x, c.z}) || !m_grid.walkable({c.x, nb.z})))
                continue;
            best = std::min(best, t[std::size_t(m_grid.index(nb))]);
        }
        return best;
    };
    // First-order upwind solve of |grad T| = 1 from two orthogonal stencil arms of spacing step.
    const auto solve = [](double a, double b, double step) {
        if (std::abs(a - b) >= step || !std::isfinite(a) || !std::isfinite(b))
            return std::min(a, b) + step;
        return 0.5 * (a + b + std::sqrt(2.0 * step * step - (a - b) * (a - b)));
    };
    m_settled = 0;
    while (!heap.empty()) {
        std::pop_heap(heap.begin(), heap.end(), later);
        const Front f = heap.back();
        heap.pop_back();
        if (frozen[std::size_t(f.cell)] != 0 || f.t > t[std::size_t(f.cell)])
            continue;
        frozen[std::size_t(f.cell)] = 1;
        ++m_settled;
        const NavCell c{f.cell % cols, f.cell / cols};
        for (int dz = -1; dz <= 1; ++dz)
            for (int dx = -1; dx <= 1; ++dx) {
                const NavCell nb{c.x + dx, c.z + dz};
                if ((dx == 0 && dz == 0) || !m_grid.walkable(nb))
                    continue;
                const int i = m_grid.index(nb);
                if (frozen[std::size_t(i)] != 0)
                    continue;
                // Multi-stencil marching (Hassouna & Farag 2007): the axis stencil and the
                // diagonal one (spacing h * sqrt 2), whichever arrives first. The diagonal
                // stencil removes the axis stencil's 20 % overestimate along diagonals.
                const double axis = solve(upwind(nb, 1, 0), upwind(nb, 0, 1), h);
                const double diag = solve(upwind(nb, 1, 1), upwind(nb, 1, -1), h * 1.4142135623730951);
                const double u = std::min(axis, diag);
                if (u < t[std::size_t(i)]) {
                    t[std::size_t(i)] = u;
                    heap.push_back({u, i});
                    std::push_heap(heap.begin(), heap.end(), later);
                }
            }
    }
    m_distance.resize(std::size_t(n));
    for (int i = 0; i < n; ++i)
        m_distance[std::size_t(i)] = float(t[std::size_t(i)]);
}

bool FlowField::clearAhead(glm::vec2 p, glm::vec2 d) const
{
    return m_grid.clearAhead(p, d) && reachable(m_grid.cellOf(p + d * (0.5f * m_grid.cellM())));
}

void FlowField::buildDirections()
{
    const int n = m_grid.cellCount();
    m_dir.assign(std::size_t(n), glm::vec2(0.0f));
    for (int i = 0; i < n; ++i) {
        const float ti = m_distance[std::size_t(i)];
        if (!std::isfinite(ti) || ti == 0.0f)
            continue;
        const NavCell c = m_grid.cellAt(i);
        // Upwind gradient: on each axis, the fall toward the lower reachable neighbour.
        glm::vec2 fall(0.0f);
        NavCell step[2] = {c, c};
        for (int axis = 0; axis < 2; ++axis) {
            float best = ti;
            for (int s = -1; s <= 1; s += 2) {
                const NavCell nb = axis == 0 ? NavCell{c.x + s, c.z} : NavCell{c.x, c.z + s};
                const float tn = reachable(nb) ? distanceM(nb) : kInf;
                if (tn < best) {
                    best = tn;
                    fall[axis] = float(s) * (ti - tn);
                    step[axis] = nb;
                }
            }
        }
        glm::vec2 d = glm::normalize(fall);
        // A diagonal is kept only where the diagonal cell is lower still: at a watershed
        // between two routes the upwind gradient can point at a higher cell, and two such
        // cells would send a follower back and forth. Otherwise, and where the diagonal
        // passes too near a blocked cell, go along the steeper axis (its neighbour is lower).
        const NavCell diagonal{step[0].x, step[1].z};
        const bool bothAxes = fall.x != 0.0f && fall.y != 0.0f;
        if ((bothAxes && !(reachable(diagonal) && distanceM(diagonal) < ti)) || !clearAhead(m_grid.centre(c), d))
            d = std::abs(fall.x) >= std::abs(fall.y) ? glm::vec2(fall.x > 0.0f ? 1.0f : -1.0f, 0.0f)
                                                     : glm::vec2(0.0f, fall.y > 0.0f ? 1.0f : -1.0f);
        m_dir[std::size_t(i)] = d;
    }
}

float FlowField::distanceM(NavCell c) const
{
    return m_grid.inside(c) ? m_distance[std::size_t(m_grid.index(c))] : kInf;
}

bool FlowField::reachable(NavCell c) const { return m_grid.walkable(c) && std::isfinite(distanceM(c)); }

glm::vec2 FlowField::direction(NavCell c) const
{
    return m_grid.inside(c) ? m_dir[std::size_t(m_grid.index(c))] : glm::vec2(0.0f);
}

glm::vec2 FlowField::sample(glm::vec2 p) const
{
    const NavCell own = m_grid.cellOf(p);
    if (!reachable(own) || isGoal(own))
        return glm::vec2(0.0f);
    const glm::vec2 q = (p - m_grid.origin()) / m_grid.cellM() - 0.5f;
    const int x0 = int(std::floor(q.x)), z0 = int(std::floor(q.y));
    const float fx = q.x - float(x0), fz = q.y - float(z0);
    glm::vec2 sum(0.0f);
    for (int k = 0; k < 4; ++k) {
        const NavCell c{x0 + (k & 1), z0 + (k >> 1)};
        const float w = ((k & 1) ? fx : 1.0f - fx) * ((k >> 1) ? fz : 1.0f - fz);
        sum += w * direction(c);  // blocked and unreachable cells hold zero
    }
    const float len = glm::length(sum);
    if (len > 1e-6f) {
        const glm::vec2 d = sum / len;
        if (clearAhead(p, d))
            return d;
    }
    const glm::vec2 d = direction(own);
    if (clearAhead(p, d))
        return d;
    const glm::vec2 toCentre = m_grid.centre(own) - p;
    const float l = glm::length(toCentre);
    return l > 1e-6f ? toCentre / l : d;
}

}  // namespace throng::sim
