#include "simcore/nav/FlowField.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace throng::sim {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// The marching front: a binary min-heap of cells keyed by their tentative arrival time,
// each cell at most once (decrease-key), so the heap stays as small as the front. Equal
// times pop in cell order, so the march is deterministic.
class NarrowBand {
public:
    NarrowBand(const std::vector<double>& t, std::size_t cells)
        : m_t(t)
        , m_pos(cells, -1)
    {
    }
    bool empty() const { return m_heap.empty(); }
    // Inserts the cell, or moves it up after its time dropped.
    void update(int cell)
    {
        int i = m_pos[std::size_t(cell)];
        if (i < 0) {
            i = int(m_heap.size());
            m_heap.push_back(cell);
        }
        siftUp(i, cell);
    }
    int pop()
    {
        const int top = m_heap.front(), last = m_heap.back();
        m_heap.pop_back();
        m_pos[std::size_t(top)] = -1;
        if (!m_heap.empty())
            siftDown(0, last);
        return top;
    }

private:
    bool before(int a, int b) const
    {
        const double ta = m_t[std::size_t(a)], tb = m_t[std::size_t(b)];
        return ta != tb ? ta < tb : a < b;
    }
    void place(int i, int cell)
    {
        m_heap[std::size_t(i)] = cell;
        m_pos[std::size_t(cell)] = i;
    }
    void siftUp(int i, int cell)
    {
        while (i > 0 && before(cell, m_heap[std::size_t((i - 1) / 2)])) {
            place(i, m_heap[std::size_t((i - 1) / 2)]);
            i = (i - 1) / 2;
        }
        place(i, cell);
    }
    void siftDown(int i, int cell)
    {
        const int n = int(m_heap.size());
        for (;;) {
            int child = 2 * i + 1;
            if (child >= n)
                break;
            if (child + 1 < n && before(m_heap[std::size_t(child + 1)], m_heap[std::size_t(child)]))
                ++child;
            if (!before(m_heap[std::size_t(child)], cell))
                break;
            place(i, m_heap[std::size_t(child)]);
            i = child;
        }
        place(i, cell);
    }

    const std::vector<double>& m_t;
    std::vector<int> m_pos;  // index in m_heap per cell, -1 when not in the front
    std::vector<int> m_heap;
};

}  // namespace

void FlowField::build(const NavGrid& grid, std::span<const FlowGoal> goals)
{
    std::vector<NavCell> cells;
    for (const FlowGoal& g : goals) {
        const NavCell c0 = grid.cellOf(g.centre - glm::vec2(g.radiusM)),
                      c1 = grid.cellOf(g.centre + glm::vec2(g.radiusM));
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
    // Padded copies (one blocked cell of border all round) so neighbour reads need no
    // bounds checks: w = padded width, cell (x, z) sits at (z + 1) * w + x + 1.
    const int cols = m_grid.cols(), rows = m_grid.rows(), w = cols + 2;
    const std::size_t padded = std::size_t(w) * std::size_t(rows + 2);
    const double h = double(m_grid.cellM()), hd = h * 1.4142135623730951;
    constexpr double inf = std::numeric_limits<double>::infinity();
    std::vector<std::uint8_t> walk(padded, 0);
    for (int z = 0; z < rows; ++z)
        for (int x = 0; x < cols; ++x)
            walk[std::size_t((z + 1) * w + x + 1)] = m_grid.walkable({x, z}) ? 1 : 0;
    std::vector<double> t(padded, inf);       // tentative arrival times
    std::vector<double> frozenT(padded, inf); // arrival times of frozen cells only
    NarrowBand front(t, padded);
    for (int s : seeds) {
        const int p = (s / cols + 1) * w + s % cols + 1;
        t[std::size_t(p)] = 0.0;
        front.update(p);
    }
    // First-order upwind solve of |grad T| = 1 from two orthogonal stencil arms of spacing step.
    const auto solve = [](double a, double b, double step) {
        if (std::abs(a - b) >= step || a == inf || b == inf)
            return std::min(a, b) + step;
        return 0.5 * (a + b + std::sqrt(2.0 * step * step - (a - b) * (a - b)));
    };
    // A diagonal neighbour's time counts only where both cells beside the step are walkable.
    const auto diagonal = [&](int p, int dx, int dz) {
        return walk[std::size_t(p + dx)] != 0 && walk[std::size_t(p + dz * w)] != 0
                   ? frozenT[std::size_t(p + dx + dz * w)]
                   : inf;
    };
    constexpr int kDx[8] = {1, -1, 0, 0, 1, -1, 1, -1}, kDz[8] = {0, 0, 1, -1, 1, 1, -1, -1};
    m_settled = 0;
    while (!front.empty()) {
        const int c = front.pop();
        frozenT[std::size_t(c)] = t[std::size_t(c)];
        ++m_settled;
        for (int k = 0; k < 8; ++k) {
            const int p = c + kDx[k] + kDz[k] * w;
            if (walk[std::size_t(p)] == 0 || frozenT[std::size_t(p)] != inf)
                continue;
            if (k >= 4 && (walk[std::size_t(c + kDx[k])] == 0 || walk[std::size_t(c + kDz[k] * w)] == 0))
                continue;  // no corner cutting: the front does not leak through a diagonal gap
            // Multi-stencil marching (Hassouna & Farag 2007): the axis stencil and the
            // diagonal one (spacing h * sqrt 2), whichever arrives first. The diagonal
            // stencil removes the axis stencil's 20 % overestimate along diagonals.
            const double ax = std::min(frozenT[std::size_t(p - 1)], frozenT[std::size_t(p + 1)]);
            const double az = std::min(frozenT[std::size_t(p - w)], frozenT[std::size_t(p + w)]);
            const double d1 = std::min(diagonal(p, 1, 1), diagonal(p, -1, -1));
            const double d2 = std::min(diagonal(p, 1, -1), diagonal(p, -1, 1));
            const double u = std::min(solve(ax, az, h), solve(d1, d2, hd));
            if (u < t[std::size_t(p)]) {
                t[std::size_t(p)] = u;
                front.update(p);
            }
        }
    }
    m_distance.resize(std::size_t(m_grid.cellCount()));
    for (int z = 0; z < rows; ++z)
        for (int x = 0; x < cols; ++x)
            m_distance[std::size_t(z * cols + x)] = float(frozenT[std::size_t((z + 1) * w + x + 1)]);
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
        if (fall == glm::vec2(0.0f)) {
            // Reached only along a diagonal (both side cells higher): head for the lowest
            // legal 8-neighbour, so no reachable cell is left without a way down.
            float best = ti;
            for (int dz = -1; dz <= 1; ++dz)
                for (int dx = -1; dx <= 1; ++dx) {
                    const NavCell nb{c.x + dx, c.z + dz};
                    const bool legal =
                        (dx == 0 || dz == 0) || (m_grid.walkable({nb.x, c.z}) && m_grid.walkable({c.x, nb.z}));
                    if ((dx != 0 || dz != 0) && legal && reachable(nb) && distanceM(nb) < best) {
                        best = distanceM(nb);
                        fall = glm::normalize(glm::vec2(float(dx), float(dz)));
                    }
                }
            m_dir[std::size_t(i)] = fall;
            continue;
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
    // Blocked and unreachable cells hold zero.
    const glm::vec2 sum = m_grid.blendAtCentres(p, [&](NavCell c) { return direction(c); });
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
