#include "simcore/nav/NavGrid.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>

namespace throng::sim {

namespace {

// Generations are unique across all grids, so a plan or field made on one grid is never
// mistaken for current on another. Only compared for equality: the values never affect results.
std::uint64_t nextGeneration()
{
    static std::atomic<std::uint64_t> counter{0};
    return ++counter;
}

float pointSegmentDistance(glm::vec2 p, glm::vec2 a, glm::vec2 b)
{
    const glm::vec2 ab = b - a;
    const float len2 = glm::dot(ab, ab);
    const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
    return glm::distance(p, a + ab * t);
}

// How near a cell's centre a shape must come to block it: the body's radius, but never less
// than 0.75 of a cell, which is more than half the cell's diagonal: every cell a shape
// touches is then blocked, so a wall stays watertight however coarse the cells. (Measured
// from the cell's rectangle instead, a 1 m door closed on 0.25 m cells when its posts lay on
// cell edges, and walkers stood in their rooms for good.)
float blockingReach(float r, float cellM) { return std::max(r, 0.75f * cellM); }

}  // namespace

NavGrid::NavGrid(int cols, int rows, glm::vec2 origin, float cellM)
    : m_cols(std::max(cols, 0))
    , m_rows(std::max(rows, 0))
    , m_origin(origin)
    , m_cellM(cellM)
    , m_walkable(std::size_t(m_cols) * std::size_t(m_rows), 1)
    , m_generation(nextGeneration())
{
}

void NavGrid::build(const Scene& scene, const NavGridParams& params)
{
    build(navShapes(scene), scene.settings.boundsMin, scene.settings.boundsMax, params);
}

void NavGrid::build(const NavShapes& shapes, glm::vec2 boundsMin, glm::vec2 boundsMax, const NavGridParams& params)
{
    m_cellM = params.cellM > 0.0f ? params.cellM : 1.0f;
    m_origin = boundsMin;
    const glm::vec2 extent = glm::max(boundsMax - boundsMin, glm::vec2(0.0f));
    m_cols = std::max(1, int(std::ceil(extent.x / m_cellM)));
    m_rows = std::max(1, int(std::ceil(extent.y / m_cellM)));
    m_walkable.assign(std::size_t(m_cols) * std::size_t(m_rows), 1);
    const float r = std::max(params.agentRadiusM, 0.0f);
    for (const Segment& s : shapes.walls)
        blockNearSegment(s, r);
    for (const NavCircle& c : shapes.circles)
        blockNearCircle(c, r);
    for (const NavBox& b : shapes.boxes)
        blockNearBox(b, r);
    m_generation = nextGeneration();
}

NavCell NavGrid::cellOf(glm::vec2 p) const
{
    // Far or non-finite points are clamped well outside the grid but inside int, so callers can
    // add a grid's width to a cell index without overflow.
    static constexpr float kFar = float(1 << 29);
    const glm::vec2 q = (p - m_origin) / m_cellM;
    const auto toCell = [](float v) { return v == v ? int(std::floor(std::clamp(v, -kFar, kFar))) : -(1 << 29); };
    return {toCell(q.x), toCell(q.y)};
}

glm::vec2 NavGrid::cellMin(NavCell c) const { return m_origin + glm::vec2(float(c.x), float(c.z)) * m_cellM; }

glm::vec2 NavGrid::centre(NavCell c) const { return cellMin(c) + glm::vec2(0.5f * m_cellM); }

NavCell NavGrid::nearestWalkable(NavCell c) const
{
    if (walkable(c))
        return c;
    // Rings of growing Chebyshev radius r hold cells at least r away, so once a ring
    // can no longer beat the best squared distance the search is over. Only the part of a
    // ring inside the grid is visited, and rings wholly outside it are skipped.
    NavCell best{-1, -1};
    // |dx| and |dz| are at most 2^31 plus the grid's size, so each square is about 2^62 and
    // their sum fits in 64 unsigned bits (for grids under 8e8 cells a side): exact, ties
    // included, from any int cell.
    using U = unsigned long long;
    bool found = false;
    U bestD2 = 0;
    const auto consider = [&](int x, int z) {
        if (!walkable({x, z}))
            return;
        const U dx = U(std::llabs((long long)x - c.x)), dz = U(std::llabs((long long)z - c.z));
        const U d2 = dx * dx + dz * dz;
        if (!found || d2 < bestD2 || (d2 == bestD2 && (z < best.z || (z == best.z && x < best.x)))) {
            best = {x, z};
            bestD2 = d2;
            found = true;
        }
    };
    // Ring bounds are worked in 64 bits: c may lie far outside the grid (any int), and a row or
    // column of the ring outside the grid is skipped before it is narrowed back to int.
    const long long cx = c.x, cz = c.z, cols = m_cols, rows = m_rows;
    const long long first = std::max({1LL, -cx, cx - (cols - 1), -cz, cz - (rows - 1)});
    const long long last = first + std::max(cols, rows);
    const auto onGrid = [](long long v, long long n) { return v >= 0 && v < n; };
    for (long long r = first; r <= last; ++r) {
        if (found && U(r) * U(r) > bestD2)
            break;
        const long long x0 = std::max(cx - r, 0LL), x1 = std::min(cx + r, cols - 1);
        const long long z0 = std::max(cz - r + 1, 0LL), z1 = std::min(cz + r - 1, rows - 1);
        for (long long x = x0; x <= x1; ++x) {  // the top and bottom rows of the ring
            if (onGrid(cz - r, rows))
                consider(int(x), int(cz - r));
            if (onGrid(cz + r, rows))
                consider(int(x), int(cz + r));
        }
        for (long long z = z0; z <= z1; ++z) {  // its left and right columns, corners excluded
            if (onGrid(cx - r, cols))
                consider(int(cx - r), int(z));
            if (onGrid(cx + r, cols))
                consider(int(cx + r), int(z));
        }
    }
    return best;
}

bool NavGrid::clearAhead(glm::vec2 p, glm::vec2 d) const
{
    return walkable(cellOf(p + d * (0.25f * m_cellM))) && walkable(cellOf(p + d * (0.5f * m_cellM)));
}

void NavGrid::setWalkable(NavCell c, bool walkable)
{
    if (!inside(c))
        return;
    auto& v = m_walkable[std::size_t(index(c))];
    if ((v != 0) != walkable) {
        v = walkable ? 1 : 0;
        m_generation = nextGeneration();
    }
}

void NavGrid::blockNearSegment(const Segment& s, float r)
{
    const float reach = blockingReach(r, m_cellM);
    const glm::vec2 lo = glm::min(s.a, s.b) - glm::vec2(reach), hi = glm::max(s.a, s.b) + glm::vec2(reach);
    const NavCell c0 = cellOf(lo), c1 = cellOf(hi);
    for (int z = std::max(c0.z, 0); z <= std::min(c1.z, m_rows - 1); ++z)
        for (int x = std::max(c0.x, 0); x <= std::min(c1.x, m_cols - 1); ++x)
            if (pointSegmentDistance(centre({x, z}), s.a, s.b) <= reach)
                m_walkable[std::size_t(index({x, z}))] = 0;
}

void NavGrid::blockNearCircle(const NavCircle& c, float r)
{
    const float reach = c.radiusM + blockingReach(r, m_cellM);
    const NavCell c0 = cellOf(c.centre - glm::vec2(reach)), c1 = cellOf(c.centre + glm::vec2(reach));
    for (int z = std::max(c0.z, 0); z <= std::min(c1.z, m_rows - 1); ++z)
        for (int x = std::max(c0.x, 0); x <= std::min(c1.x, m_cols - 1); ++x)
            if (glm::distance(c.centre, centre({x, z})) <= reach)
                m_walkable[std::size_t(index({x, z}))] = 0;
}

void NavGrid::blockNearBox(const NavBox& b, float r)
{
    Segment sides[4];
    boxSides(b, sides);
    for (const Segment& s : sides)
        blockNearSegment(s, r);
    // Cells wholly inside the box touch no side.
    const float reach = glm::length(b.halfSize);
    const NavCell c0 = cellOf(b.centre - glm::vec2(reach)), c1 = cellOf(b.centre + glm::vec2(reach));
    for (int z = std::max(c0.z, 0); z <= std::min(c1.z, m_rows - 1); ++z)
        for (int x = std::max(c0.x, 0); x <= std::min(c1.x, m_cols - 1); ++x)
            if (b.contains(centre({x, z})))
                m_walkable[std::size_t(index({x, z}))] = 0;
}

}  // namespace throng::sim
