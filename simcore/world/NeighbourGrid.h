#pragma once
// A uniform grid over agent positions, rebuilt each step by counting sort (O(N)); a
// query visits only the cells a radius overlaps. Holds indices, never agent data.

#include "simcore/base/ThreadTeam.h"
#include "simcore/base/Lanes.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <type_traits>
#include <utility>
#include <vector>

namespace throng::sim {

// Which cell edge a grid not sorted by height uses (NeighbourGrid::configure).
enum class GridCells : std::uint8_t {
    ByCrowd,  // by how many agents share a cell (configure), as the crowd spreads and gathers
    Fine,     // always configure's cellM
    Coarse,   // always the coarsest
};

class NeighbourGrid {
public:
    // cellM: cell edge in metres (> 0), usually the largest perception radius. A grid not
    // sorted by height may also use cells wider by powers of two (2, 4, ...), up to
    // coarseM, where `cells` says. ByCrowd starts with the coarsest and measures, at the first
    // rebuild and every kChooseEvery-th after it, how many others share an agent's cell on
    // average. Fewer than kKeepLeast: the crowd lies spread out, and a query reads rows of
    // cells that hold almost nobody, in a table of millions of cells where the ground is
    // wide. More than kKeepMost: the crowd has gathered, and a query's rows hold many
    // agents beyond its reach. Either way it takes the widest cells that would hold no
    // more than kAimMost others (else the fine ones). No query's answer depends on the
    // cells: the k-nearest searches rank what they are offered, the others test the
    // distance, and the counts add up the same in any order. Only the time does.
    void configure(glm::vec2 boundsMin, glm::vec2 boundsMax, float cellM, float coarseM = 0.0f,
                   GridCells cells = GridCells::Fine);
    // The edge of the cells in use now, and configure's.
    float cellM() const { return m_cell; }
    float fineCellM() const { return m_fineM; }
    static constexpr int kChooseEvery = 16;
    static constexpr double kKeepLeast = 1.0, kKeepMost = 8.0, kAimMost = 4.0;
    // Sorts agent indices into cells by their (x, z); with sortByHeight, each cell is also
    // ordered by y so forEachNear3D can skip the agents far above or below. Reuses its
    // buffers. Agents with skip[i] != 0 (agents that left through an exit) are not indexed;
    // an empty skip indexes everyone. Runs on `team` where given (else on the calling
    // thread); the order it leaves is the same for any number of threads. Where configure
    // lets it, it may first choose other cells, and then sorts again into those.
    void rebuild(std::span<const glm::vec3> positions, bool sortByHeight = false,
                 std::span<const std::uint8_t> skip = {}, const ThreadTeam* team = nullptr);

    // Calls f(j) or f(j, position of j) for every agent j whose cell overlaps the square
    // around p of half-size r. Positions come from a copy kept in cell order, so a query
    // reads contiguous memory instead of hopping through the agent arrays.
    template <typename F>
    void forEachNear(glm::vec2 p, float r, F&& f) const
    {
        const int x0 = cellX(p.x - r), x1 = cellX(p.x + r), z0 = cellZ(p.y - r), z1 = cellZ(p.y + r);
        for (int z = z0; z <= z1; ++z) {
            // Cells x0..x1 of one row are adjacent in the sorted order: one contiguous run.
            const std::size_t row = std::size_t(z) * std::size_t(m_cols);
            const std::uint32_t begin = m_start[row + std::size_t(x0)], end = m_start[row + std::size_t(x1) + 1];
            for (std::uint32_t k = begin; k < end; ++k) {
                if constexpr (std::is_invocable_v<F, std::uint32_t, const glm::vec3&>)
                    f(m_sorted[k], m_sortedPos[k]);
                else
                    f(m_sorted[k]);
            }
        }
    }
    // For 3D queries (fliers): like forEachNear with f(j, position), but only agents
    // whose height is within [p.y - r, p.y + r]. Needs rebuild(..., true).
    template <typename F>
    void forEachNear3D(glm::vec3 p, float r, F&& f) const
    {
        const int x0 = cellX(p.x - r), x1 = cellX(p.x + r), z0 = cellZ(p.z - r), z1 = cellZ(p.z + r);
        const float yLo = p.y - r, yHi = p.y + r;
        for (int z = z0; z <= z1; ++z)
            for (int x = x0; x <= x1; ++x) {
                const std::size_t c = std::size_t(z) * std::size_t(m_cols) + std::size_t(x);
                const std::uint32_t end = m_start[c + 1];
                for (std::uint32_t k = firstAtOrAbove(m_start[c], end, yLo); k < end && m_sortedPos[k].y <= yHi; ++k)
                    f(m_sorted[k], m_sortedPos[k]);
            }
    }
    // For k-nearest searches: like forEachNear (or forEachNear3D once sorted by height),
    // but rows are visited nearest first, and before each row boundSq() gives the
    // squared distance beyond which the caller no longer cares (it shrinks as the
    // caller's k best fill up), so cells wholly beyond it are skipped. Calls
    // f(j, position of j); which agents are offered beyond the bound is unspecified, so
    // the caller must rank them itself (by distance, ties broken the same way each run).
    template <typename B, typename F>
    void forEachNearest(glm::vec3 p, float r, B&& boundSq, F&& f) const
    {
        if (!(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(r))) {
            if (m_byHeight)
                forEachNear3D(p, r, f);
            else
                forEachNear(glm::vec2(p.x, p.z), r, f);
            return;
        }
        const int zc = cellZ(p.z), z0 = cellZ(p.z - r), z1 = cellZ(p.z + r);
        const float r2 = r * r;
        for (int step = 0;; ++step) {
            bool any = false;
            for (int side = 0; side < (step == 0 ? 1 : 2); ++side) {
                const int z = side == 0 ? zc - step : zc + step;
                if (z < z0 || z > z1)
                    continue;
                // Lower bound on the distance across z to any agent in this row (agents
                // clamped into a border row lie beyond it, so the bound still holds).
                const float rowLo = m_min.y + float(z) * m_cell;
                const float dz = z == zc ? 0.0f : std::max(0.0f, z < zc ? p.z - (rowLo + m_cell) : rowLo - p.z);
                const float left = std::min(r2, boundSq()) - dz * dz;
                if (left < 0.0f)
                    continue;
                any = true;
                const float reach = std::sqrt(left) * 1.0001f + 1e-4f;  // never skip on rounding
                const int x0 = cellX(p.x - reach), x1 = cellX(p.x + reach);
                const std::size_t row = std::size_t(z) * std::size_t(m_cols);
                if (!m_byHeight) {
                    offerWithin(p, m_start[row + std::size_t(x0)], m_start[row + std::size_t(x1) + 1], boundSq, f);
                    continue;
                }
                const float yLo = p.y - reach, yHi = p.y + reach;
                for (int x = x0; x <= x1; ++x) {
                    const std::size_t c = row + std::size_t(x);
                    const std::uint32_t end = m_start[c + 1];
                    for (std::uint32_t k = firstAtOrAbove(m_start[c], end, yLo); k < end && m_sortedPos[k].y <= yHi;
                         ++k)
                        f(m_sorted[k], m_sortedPos[k]);
                }
            }
            if (!any && step > 0)
                return;
        }
    }
    // A cursor for forEachNearestSweep: the columns around one cell, and in each where
    // the last query's height window began. One per thread; any state is valid.
    struct Sweep {
        static constexpr int kMaxColumns = 49;  // 7 x 7: a radius of up to 3 cells
        std::uint32_t cell = UINT32_MAX;
        float radius = -1.0f;
        int count = 0;
        int xLo = 0, xHi = -1, zLo = 0, zHi = -1;  // the columns' range of cells
        std::uint32_t begin[kMaxColumns], end[kMaxColumns], lo[kMaxColumns];
        float x0[kMaxColumns], z0[kMaxColumns];  // each column's low corner; the own column first
    };
    // forEachNearest for queries made in the grid's own order (order()): consecutive
    // queries then lie in the same cell at rising heights, so each column's height window
    // is found by moving the last one a step or two instead of by a search. Offers every
    // agent within the bound as forEachNearest does (which others, is unspecified).
    template <typename B, typename F>
    void forEachNearestSweep(glm::vec3 p, float r, B&& boundSq, F&& f, Sweep& sweep) const
    {
        if (!m_byHeight || !(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) && std::isfinite(r)) ||
            !(aimedAt(p, r, sweep) || aimSweep(p, r, sweep))) {
            forEachNearest(p, r, boundSq, f);
            return;
        }
        const float reach = std::sqrt(std::min(r * r, boundSq())) * 1.0001f + 1e-4f;  // never skip on rounding
        if (!withinColumns(p, reach, sweep)) {
            forEachNearest(p, r, boundSq, f);
            return;
        }
        const float yLo = p.y - reach, yHi = p.y + reach, reach2 = reach * reach;
        for (int k = 0; k < sweep.count; ++k) {
            // How far across x and z the column lies (agents clamped into a border column
            // lie beyond its edge, so this still bounds them): p less its nearest point of
            // the column, by min and max, which compile to instructions and not branches.
            const float cx = sweep.x0[k], cz = sweep.z0[k];
            const float dx = p.x - std::min(std::max(p.x, cx), cx + m_cell);
            const float dz = p.z - std::min(std::max(p.z, cz), cz + m_cell);
            if (k > 0 && dx * dx + dz * dz > std::min(reach2, boundSq() * 1.0002f))
                continue;
            scanColumn(k, yLo, yHi, f, sweep);
        }
    }
    // forEachNearestSweep for four queries at once, all in one cell and with one radius
    // (consecutive boids of the grid's order): each column's window is scanned once for
    // the four, from the lowest query's reach to the highest's, and skipped only when it
    // lies beyond every query's bound. boundSq() gives the four squared bounds, lane by
    // lane (each only shrinks; a negative one leaves its lane out); f(j, position of j) is
    // offered every agent within any query's bound (which others, is unspecified). False,
    // having offered nothing, when the sweep cannot serve all four or a reach leaves its
    // columns: the caller then queries one by one.
    template <typename B, typename F>
    bool forEachNearestSweep4(const glm::vec3 (&p)[4], float r, B&& boundSq, F&& f, Sweep& sweep) const
    {
        using simd::F4;
        if (!m_byHeight || !std::isfinite(r))
            return false;
        for (const glm::vec3& q : p)
            if (!(std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z)))
                return false;
        if (!(aimedAt(p[0], r, sweep) || aimSweep(p[0], r, sweep)) || !aimedAt(p[1], r, sweep) ||
            !aimedAt(p[2], r, sweep) || !aimedAt(p[3], r, sweep))
            return false;
        const F4 bounds = boundSq();
        F4 reach2;
        float yLo = INFINITY, yHi = -INFINITY;
        for (int l = 0; l < 4; ++l) {
            // As forEachNearestSweep (a negative bound: a lane left empty).
            const float reach = std::sqrt(std::min(r * r, std::max(bounds[l], 0.0f))) * 1.0001f + 1e-4f;
            if (!withinColumns(p[l], reach, sweep))
                return false;
            reach2[l] = reach * reach;
            yLo = std::min(yLo, p[l].y - reach);
            yHi = std::max(yHi, p[l].y + reach);
        }
        const F4 px{p[0].x, p[1].x, p[2].x, p[3].x}, pz{p[0].z, p[1].z, p[2].z, p[3].z};
        for (int k = 0; k < sweep.count; ++k) {
            // As forEachNearestSweep, lane by lane: skipped when no query can reach it.
            const F4 cx = simd::f4(sweep.x0[k]), cz = simd::f4(sweep.z0[k]);
            const F4 dx = px - simd::minOf(simd::maxOf(px, cx), cx + m_cell);
            const F4 dz = pz - simd::minOf(simd::maxOf(pz, cz), cz + m_cell);
            if (k > 0 && !simd::any(dx * dx + dz * dz <= simd::minOf(reach2, boundSq() * 1.0002f)))
                continue;
            scanColumn(k, yLo, yHi, f, sweep);
        }
        return true;
    }
    // For visiting each close pair once, in the grid's order: calls f(j, position of j)
    // for the agents j after the k-th of order() (later in its cell, or in a later cell)
    // whose cell overlaps the square of half-size r around it and, once sorted by height,
    // whose height lies within r of its. So every pair within r of each other on each
    // axis is offered once, from the earlier of the two. (Cells round monotonically, so
    // the later one's cell lies in the earlier one's square.) Not sorted by height, the
    // agents farther than r are mostly left out (offerWithin): every pair within r of each
    // other is still offered once.
    template <typename F>
    void forEachLaterNear(std::size_t k, float r, F&& f) const
    {
        const glm::vec3 p = m_sortedPos[k];
        const int xc = cellX(p.x), zc = cellZ(p.z);
        const int x0 = cellX(p.x - r), x1 = cellX(p.x + r), z1 = cellZ(p.z + r);
        const float yLo = p.y - r, yHi = p.y + r, r2 = r * r;
        auto within = [r2] { return r2; };
        auto visit = [&](std::uint32_t from, std::uint32_t end) {
            if (!m_byHeight)
                return offerWithin(p, from, end, within, f);
            for (std::uint32_t j = from; j < end && m_sortedPos[j].y <= yHi; ++j)
                f(m_sorted[j], m_sortedPos[j]);
        };
        const std::size_t own = std::size_t(zc) * std::size_t(m_cols) + std::size_t(xc);
        visit(std::uint32_t(k + 1), m_start[own + 1]);
        for (int z = zc; z <= z1; ++z)
            for (int x = z == zc ? xc + 1 : x0; x <= x1; ++x) {
                const std::size_t c = std::size_t(z) * std::size_t(m_cols) + std::size_t(x);
                const std::uint32_t end = m_start[c + 1];
                visit(m_byHeight ? firstAtOrAbove(m_start[c], end, yLo) : m_start[c], end);
            }
    }
    // forEachLaterNear for the k-th agents of order(), k in [begin, end), in one walk:
    // f(k, j, position of j), with r(k) the k-th agent's reach. Offers what
    // forEachLaterNear(k, r(k), ...) offers. With every reach below a cell's edge (rMax),
    // the later cells a reach can touch are the own cell's right and the three below it;
    // as a cell's agents come at rising heights, the window of each of those cells is
    // found by moving the last one a step (as scanColumn does) instead of by a search.
    // False, having offered nothing, where it cannot: not sorted by height, or a reach
    // too long.
    template <typename R, typename F>
    bool forEachLaterNearRun(std::size_t begin, std::size_t end, float rMax, R&& r, F&& f) const
    {
        if (!m_byHeight || !(rMax >= 0.0f && rMax < 0.99f * m_cell))
            return false;
        if (begin >= end)
            return true;
        const glm::vec3* pos = m_sortedPos.data();
        // The cell of the first agent: the last whose start is at or before it.
        std::size_t c = std::size_t(std::upper_bound(m_start.begin(), m_start.end(), std::uint32_t(begin)) -
                                    m_start.begin()) - 1;
        for (std::size_t k = begin; k < end; ++c) {
            const std::uint32_t cellEnd = m_start[c + 1];
            if (k >= cellEnd)
                continue;
            const int x = int(c % std::size_t(m_cols)), z = int(c / std::size_t(m_cols));
            // The later cells a reach can touch: right, below left, below, below right
            // (past the grid's edge: empty), each [first, last) of the order, and the
            // first agent of its window (lo).
            std::uint32_t first[4] = {}, last[4] = {}, lo[4] = {};
            const int at[4][2] = {{x + 1, z}, {x - 1, z + 1}, {x, z + 1}, {x + 1, z + 1}};
            for (int n = 0; n < 4; ++n) {
                const auto [cx, cz] = at[n];
                if (cx < 0 || cx >= m_cols || cz >= m_rows)
                    continue;
                const std::size_t d = std::size_t(cz) * std::size_t(m_cols) + std::size_t(cx);
                first[n] = lo[n] = m_start[d];
                last[n] = m_start[d + 1];
            }
            auto scan = [&](int n, std::size_t from, float yLo, float yHi) {
                std::uint32_t at = lo[n];
                while (at > first[n] && pos[at - 1].y >= yLo)
                    --at;
                while (at < last[n] && pos[at].y < yLo)
                    ++at;
                lo[n] = at;
                for (std::uint32_t j = at; j < last[n] && pos[j].y <= yHi; ++j)
                    f(from, m_sorted[j], pos[j]);
            };
            for (const std::size_t stop = std::min<std::size_t>(cellEnd, end); k < stop; ++k) {
                const glm::vec3 p = pos[k];
                const float reach = r(k), yLo = p.y - reach, yHi = p.y + reach;
                for (std::size_t j = k + 1; j < cellEnd && pos[j].y <= yHi; ++j)
                    f(k, m_sorted[j], pos[j]);
                // As forEachLaterNear: the cells the square of half-size reach overlaps.
                const bool right = cellX(p.x + reach) > x, left = cellX(p.x - reach) < x;
                if (right)
                    scan(0, k, yLo, yHi);
                if (cellZ(p.z + reach) > z) {
                    if (left)
                        scan(1, k, yLo, yHi);
                    scan(2, k, yLo, yHi);
                    if (right)
                        scan(3, k, yLo, yHi);
                }
            }
        }
        return true;
    }
    // The cell a point lies in (forEachNearestSweep4's queries share one).
    std::uint32_t cellIndex(glm::vec3 p) const { return std::uint32_t(cellZ(p.z) * m_cols + cellX(p.x)); }
    // The agents in the grid's order (by cell, then by height): the order to make
    // forEachNearestSweep queries in. Holds every agent only when none was skipped.
    std::span<const std::uint32_t> order() const { return m_sorted; }
    // The position of the k-th agent of order(), from the grid's copy.
    glm::vec3 orderedPosition(std::size_t k) const { return m_sortedPos[k]; }
    bool sortedByHeight() const { return m_byHeight; }
    std::size_t memoryBytes() const
    {
        return (m_start.capacity() + m_sorted.capacity() + m_cellOf.capacity() + m_rank.capacity()) *
                   sizeof(std::uint32_t) +
               m_sortedPos.capacity() * sizeof(glm::vec3);
    }

private:
    // A run [begin, end) of the sorted agents, such as forEachNearest's row of cells:
    // offers f, in order, those whose squared distance from p is not above boundSq() (read
    // again every four, as it may shrink), four at a time, and the last few of the run
    // unsifted. Sifting is what a caller does first itself (the distance the same dot
    // product, here a hair wider), so the agents the caller keeps, and the order it meets
    // them in, are the same; the rows a walker reads hold mostly agents beyond its bound,
    // and this drops them without a call and a branch each.
    template <typename B, typename F>
    [[gnu::always_inline]] void offerWithin(glm::vec3 p, std::uint32_t begin, std::uint32_t end, B& boundSq,
                                            F& f) const
    {
        using simd::F4;
        const F4 px{p.x, p.x, p.x, p.x}, py{p.y, p.y, p.y, p.y}, pz{p.z, p.z, p.z, p.z};
        std::uint32_t k = begin;
        for (; k + 4 <= end; k += 4) {
            const glm::vec3* q = &m_sortedPos[k];
            const F4 dx = F4{q[0].x, q[1].x, q[2].x, q[3].x} - px;
            const F4 dy = F4{q[0].y, q[1].y, q[2].y, q[3].y} - py;
            const F4 dz = F4{q[0].z, q[1].z, q[2].z, q[3].z} - pz;
            const F4 d2 = dx * dx + dy * dy + dz * dz;
            // Not above the bound (a NaN is offered, as the caller's own test lets it by).
            for (unsigned bits = simd::bitsOf(!(d2 > boundSq() * 1.0002f)); bits != 0; bits &= bits - 1) {
                const std::uint32_t at = k + std::uint32_t(__builtin_ctz(bits));
                f(m_sorted[at], m_sortedPos[at]);
            }
        }
        for (; k < end; ++k)
            f(m_sorted[k], m_sortedPos[k]);
    }
    // The sweep's k-th column from height yLo to yHi: its window moved from where the last
    // query left it (queries come at rising heights, so a few steps), then f for each agent.
    template <typename F>
    void scanColumn(int k, float yLo, float yHi, F& f, Sweep& sweep) const
    {
        const glm::vec3* pos = m_sortedPos.data();
        std::uint32_t lo = sweep.lo[k];
        const std::uint32_t b = sweep.begin[k], e = sweep.end[k];
        while (lo > b && pos[lo - 1].y >= yLo)
            --lo;
        while (lo < e && pos[lo].y < yLo)
            ++lo;
        sweep.lo[k] = lo;
        for (std::uint32_t j = lo; j < e && pos[j].y <= yHi; ++j)
            f(m_sorted[j], pos[j]);
    }
    // Whether a reach around p stays within the sweep's columns, computed as cellX and cellZ
    // do (which round monotonically, so no agent within reach lies in a cell outside).
    // Only a query within a hair of its cell's edge fails.
    bool withinColumns(glm::vec3 p, float reach, const Sweep& sweep) const
    {
        const float ux0 = (p.x - reach - m_min.x) * m_inv, ux1 = (p.x + reach - m_min.x) * m_inv;
        const float uz0 = (p.z - reach - m_min.y) * m_inv, uz1 = (p.z + reach - m_min.y) * m_inv;
        return !((sweep.xLo > 0 && ux0 < float(sweep.xLo)) || (sweep.xHi < m_cols - 1 && ux1 >= float(sweep.xHi + 1)) ||
                 (sweep.zLo > 0 && uz0 < float(sweep.zLo)) || (sweep.zHi < m_rows - 1 && uz1 >= float(sweep.zHi + 1)));
    }
    // Whether the sweep already holds the columns for a query at p with radius r.
    bool aimedAt(glm::vec3 p, float r, const Sweep& sweep) const
    {
        return sweep.radius == r && sweep.cell == std::uint32_t(cellZ(p.z) * m_cols + cellX(p.x));
    }
    // Points the sweep at the columns around p's cell that a radius r can reach (the own
    // column first); false when they are too many. Called only when !aimedAt(p, r, sweep).
    bool aimSweep(glm::vec3 p, float r, Sweep& sweep) const;

    // A cell edge, made no smaller than the bounds allow (kMaxCellsPerAxis).
    float cappedCellM(float cellM) const;
    // The geometry and an empty table for cells of edge cellM over the configured bounds.
    void setCell(float cellM);
    // rebuild's sort, on the cells in use.
    void sortIntoCells(std::span<const glm::vec3> positions, bool sortByHeight, std::span<const std::uint8_t> skip,
                       const ThreadTeam* team);
    // Which cell edge configure's choice wants after this rebuild (the one in use if
    // none other).
    float chosenCellM() const;
    // rebuild with one chunk: count, prefix sums and scatter in place.
    void rebuildSerial(std::span<const glm::vec3> positions, std::span<const std::uint8_t> skip);
    // Sorts cells [firstCell, endCell) by height (rebuild's last pass).
    void sortCellsByHeight(std::span<const glm::vec3> positions, std::size_t firstCell, std::size_t endCell,
                           std::vector<std::pair<float, std::uint32_t>>& scratch);
    // In a cell sorted by height, [begin, end): the first agent at or above y (end when
    // none). Branch-free halving, so a short cell costs a few conditional moves.
    std::uint32_t firstAtOrAbove(std::uint32_t begin, std::uint32_t end, float y) const
    {
        if (begin == end)
            return end;
        std::uint32_t lo = begin, n = end - begin;
        while (n > 1) {
            const std::uint32_t half = n / 2;
            lo = m_sortedPos[lo + half].y < y ? lo + half : lo;
            n -= half;
        }
        return m_sortedPos[lo].y < y ? lo + 1 : lo;
    }

    // NaN lands in cell 0; positions outside the bounds clamp into the border cells.
    // (Non-negative, so truncating is the floor: std::floor is a call on baseline x86-64.)
    int cellX(float x) const { return cellOf((x - m_min.x) * m_inv, m_cols); }
    int cellZ(float z) const { return cellOf((z - m_min.y) * m_inv, m_rows); }
    static int cellOf(float c, int n) { return c >= 0.0f ? int(std::min(c, float(n) - 0.5f)) : 0; }

    glm::vec2 m_min{0.0f}, m_max{1.0f};
    float m_cell = 1.0f, m_inv = 1.0f;
    float m_fineM = 1.0f, m_coarseM = 1.0f;  // configure's cells, and the coarsest (fine: none)
    GridCells m_choice = GridCells::Fine;
    std::uint64_t m_rebuilds = 0;
    int m_cols = 1, m_rows = 1;
    std::vector<std::uint32_t> m_start;   // cols*rows + 1 prefix sums
    std::vector<std::uint32_t> m_sorted;  // agent indices by cell
    std::vector<glm::vec3> m_sortedPos;   // their positions, in the same order
    bool m_byHeight = false;
    std::vector<std::vector<std::pair<float, std::uint32_t>>> m_heightScratch;  // one per chunk
    std::vector<std::uint32_t> m_cellOf;     // per agent: its cell
    std::vector<std::uint32_t> m_rank;       // per agent: its place among its cell's agents
    std::vector<std::uint32_t> m_partTotal;  // prefix sums of the cell blocks' counts
};

}  // namespace throng::sim
