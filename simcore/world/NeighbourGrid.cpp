#include "simcore/world/NeighbourGrid.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace throng::sim {

namespace {
constexpr int kMaxCellsPerAxis = 4096;
// Fewer agents than this per chunk are not worth a thread.
constexpr std::size_t kMinAgentsPerChunk = 2048;
constexpr std::uint32_t kSkipped = UINT32_MAX;

// [begin, end) of part t when [0, n) is cut into `parts` nearly equal runs.
std::pair<std::size_t, std::size_t> part(std::size_t n, std::size_t parts, std::size_t t)
{
    return {n * t / parts, n * (t + 1) / parts};
}
}  // namespace

void NeighbourGrid::configure(glm::vec2 boundsMin, glm::vec2 boundsMax, float cellM, float coarseM, GridCells cells)
{
    m_min = boundsMin;
    m_max = boundsMax;
    m_rebuilds = 0;
    m_fineM = cappedCellM(cellM);
    // The coarse cells: the fine ones times a power of two, at most coarseM.
    m_coarseM = m_fineM;
    while (2.0f * m_coarseM <= coarseM)
        m_coarseM *= 2.0f;
    m_choice = m_coarseM > m_fineM ? cells : GridCells::Fine;
    setCell(m_choice == GridCells::Fine ? m_fineM : m_coarseM);
    m_sorted.clear();
    m_sortedPos.clear();
}

float NeighbourGrid::cappedCellM(float cellM) const
{
    // Cap the grid so a huge world with tiny agents still fits in memory; agents
    // outside the bounds are clamped into border cells.
    const glm::vec2 size = glm::max(m_max - m_min, glm::vec2(1.0f));
    return std::max({cellM, size.x / kMaxCellsPerAxis, size.y / kMaxCellsPerAxis, 1e-3f});
}

void NeighbourGrid::setCell(float cellM)
{
    const glm::vec2 size = glm::max(m_max - m_min, glm::vec2(1.0f));
    m_cell = cellM;
    m_inv = 1.0f / m_cell;
    m_cols = std::max(1, int(std::ceil(size.x * m_inv)));
    m_rows = std::max(1, int(std::ceil(size.y * m_inv)));
    // A new table, so that one of other cells does not keep the old one's memory.
    std::vector<std::uint32_t>(std::size_t(m_cols) * std::size_t(m_rows) + 1, 0).swap(m_start);
}

void NeighbourGrid::rebuild(std::span<const glm::vec3> positions, bool sortByHeight, std::span<const std::uint8_t> skip,
                            const ThreadTeam* team)
{
    // Sorted by height (fliers), a grid keeps its cells: the boids' sweeps are tuned to
    // them. Otherwise, when configure's choice wants other cells, sort again into them.
    const bool choose = m_choice == GridCells::ByCrowd && m_coarseM > m_fineM && !sortByHeight &&
                        m_rebuilds++ % std::uint64_t(kChooseEvery) == 0;
    sortIntoCells(positions, sortByHeight, skip, team);
    if (const float wanted = choose ? chosenCellM() : m_cell; wanted != m_cell) {
        setCell(wanted);
        sortIntoCells(positions, sortByHeight, skip, team);
    }
}

float NeighbourGrid::chosenCellM() const
{
    // How many others share an agent's cell, on average: the sum over cells of their
    // counts squared, over the agents, less the agent itself. Integers: the same on any
    // thread count.
    const std::uint64_t agents = m_sorted.size();
    if (agents == 0)
        return m_cell;
    std::uint64_t shared = 0;
    for (std::size_t c = 0; c + 1 < m_start.size(); ++c) {
        const std::uint64_t count = m_start[c + 1] - m_start[c];
        shared += count * count;
    }
    const double others = double(shared) / double(agents) - 1.0;
    if (others >= kKeepLeast && others <= kKeepMost)
        return m_cell;
    // The widest cells (fine, twice, four times) that would hold at most kAimMost others,
    // the crowd spread over them as it is over these; else the fine ones.
    for (float edge = m_coarseM; edge > m_fineM; edge *= 0.5f)
        if (others * double(edge / m_cell) * double(edge / m_cell) <= kAimMost)
            return edge;
    return m_fineM;
}

// A counting sort whose only serial pass is one load and one store per agent: each
// agent's rank in its cell is the cell's count before it, so indices stay ascending
// within a cell (the order is the serial stable sort's) and the scatter needs no
// cursors. Cells, the prefix sums over cells and the scatter run in parallel.
void NeighbourGrid::sortIntoCells(std::span<const glm::vec3> positions, bool sortByHeight,
                                  std::span<const std::uint8_t> skip, const ThreadTeam* team)
{
    const std::size_t n = positions.size();
    const std::size_t cells = m_start.size() - 1;
    // Chunks in multiples of the team, so that a thread the machine holds back leaves
    // little for the others to wait on; the order is the stable sort's for any count.
    const std::size_t threads = team ? std::size_t(team->size()) : 1;
    const std::size_t chunks = threads == 1 ? 1 : std::clamp<std::size_t>(n / kMinAgentsPerChunk, 1, 4 * threads);
    auto forChunks = [&](auto&& fn) { team->forEach(chunks, 1, fn); };
    m_cellOf.resize(n);
    m_byHeight = sortByHeight;
    if (chunks == 1) {
        rebuildSerial(positions, skip);
        if (sortByHeight) {
            m_heightScratch.resize(1);
            sortCellsByHeight(positions, 0, cells, m_heightScratch[0]);
        }
        return;
    }
    m_rank.resize(n);
    m_partTotal.assign(chunks + 1, 0u);
    std::uint32_t* start = m_start.data();
    // Each agent's cell; the counts (m_start[c + 1] for cell c) cleared.
    forChunks([&](std::size_t t) {
        const auto [cb, ce] = part(cells + 1, chunks, t);
        std::fill(start + cb, start + ce, 0u);
        const auto [b, e] = part(n, chunks, t);
        for (std::size_t i = b; i < e; ++i)
            m_cellOf[i] = i < skip.size() && skip[i]
                              ? kSkipped
                              : std::uint32_t(cellZ(positions[i].z) * m_cols + cellX(positions[i].x));
    });
    // Count, in index order.
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t c = m_cellOf[i];
        if (c != kSkipped)
            m_rank[i] = start[c + 1]++;
    }
    // Prefix sums over cells, in blocks: each block's total, the blocks' starts, then
    // each block on its own. m_start[c] becomes the first slot of cell c.
    forChunks([&](std::size_t t) {
        const auto [b, e] = part(cells, chunks, t);
        std::uint32_t sum = 0;
        for (std::size_t c = b; c < e; ++c)
            sum += start[c + 1];
        m_partTotal[t + 1] = sum;
    });
    for (std::size_t t = 0; t < chunks; ++t)
        m_partTotal[t + 1] += m_partTotal[t];
    forChunks([&](std::size_t t) {
        const auto [b, e] = part(cells, chunks, t);
        std::uint32_t run = m_partTotal[t];
        for (std::size_t c = b; c < e; ++c) {
            run += start[c + 1];
            start[c + 1] = run;
        }
    });
    start[0] = 0;
    const std::uint32_t indexed = start[cells];
    // Scatter: every agent to its own slot.
    m_sorted.resize(indexed);
    m_sortedPos.resize(indexed);
    forChunks([&](std::size_t t) {
        const auto [b, e] = part(n, chunks, t);
        for (std::size_t i = b; i < e; ++i) {
            const std::uint32_t c = m_cellOf[i];
            if (c == kSkipped)
                continue;
            const std::uint32_t k = start[c] + m_rank[i];
            m_sorted[k] = std::uint32_t(i);
            m_sortedPos[k] = positions[i];
        }
    });
    if (!sortByHeight)
        return;
    // Within each cell by height, ties by index: the order is fully determined, and each
    // cell is sorted on its own, so in parallel over blocks of cells.
    m_heightScratch.resize(chunks);
    forChunks([&](std::size_t t) {
        const auto [cb, ce] = part(cells, chunks, t);
        sortCellsByHeight(positions, cb, ce, m_heightScratch[t]);
    });
}

bool NeighbourGrid::aimSweep(glm::vec3 p, float r, Sweep& sweep) const
{
    const int cx = cellX(p.x), cz = cellZ(p.z);
    const auto cell = std::uint32_t(cz * m_cols + cx);
    // Two points a distance d apart lie at most ceil(d / cell) cells apart; a query
    // whose reach rounds past the columns found here goes the slow way (see
    // forEachNearestSweep).
    const float span = std::ceil(r * m_inv);
    if (!(span <= 3.0f))
        return false;
    const int s = std::max(1, int(span));
    sweep.cell = cell;
    sweep.radius = r;
    sweep.count = 0;
    sweep.xLo = std::max(0, cx - s);
    sweep.xHi = std::min(m_cols - 1, cx + s);
    sweep.zLo = std::max(0, cz - s);
    sweep.zHi = std::min(m_rows - 1, cz + s);
    auto add = [&](int x, int z) {
        const std::size_t c = std::size_t(z) * std::size_t(m_cols) + std::size_t(x);
        const int k = sweep.count++;
        sweep.begin[k] = sweep.lo[k] = m_start[c];
        sweep.end[k] = m_start[c + 1];
        sweep.x0[k] = m_min.x + float(x) * m_cell;
        sweep.z0[k] = m_min.y + float(z) * m_cell;
    };
    add(cx, cz);  // first: forEachNearestSweep never skips it (p may lie outside it, clamped in)
    for (int z = sweep.zLo; z <= sweep.zHi; ++z)
        for (int x = sweep.xLo; x <= sweep.xHi; ++x)
            if (x != cx || z != cz)
                add(x, z);
    return true;
}

// One chunk: the same order with fewer passes over the cells (most of them empty).
void NeighbourGrid::rebuildSerial(std::span<const glm::vec3> positions, std::span<const std::uint8_t> skip)
{
    const std::size_t n = positions.size();
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
    for (std::size_t c = 1; c < m_start.size(); ++c)
        m_start[c] += m_start[c - 1];
    // Counting sort, stable: indices stay ascending within a cell. m_start[c] serves as
    // cell c's write cursor, so it ends as the cell's end and is shifted back to starts.
    m_sorted.resize(indexed);
    m_sortedPos.resize(indexed);
    for (std::size_t i = 0; i < n; ++i) {
        const std::uint32_t c = m_cellOf[i];
        if (c == kSkipped)
            continue;
        const std::uint32_t k = m_start[c]++;
        m_sorted[k] = std::uint32_t(i);
        m_sortedPos[k] = positions[i];
    }
    for (std::size_t c = m_start.size() - 1; c > 0; --c)
        m_start[c] = m_start[c - 1];
    m_start[0] = 0;
}

void NeighbourGrid::sortCellsByHeight(std::span<const glm::vec3> positions, std::size_t firstCell, std::size_t endCell,
                                      std::vector<std::pair<float, std::uint32_t>>& scratch)
{
    constexpr std::uint32_t kInsertionMax = 64;
    for (std::size_t c = firstCell; c < endCell; ++c) {
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
        // A flock keeps its order from step to step, and the counting sort keeps indices
        // ascending: a column of birds stored from the ground up comes out already sorted.
        // Then the sort below would give the same order again (it is a total order), so
        // it is skipped.
        bool sorted = true;
        for (std::uint32_t k = b + 1; sorted && k < e; ++k) {
            const float below = m_sortedPos[k - 1].y, y = m_sortedPos[k].y;
            sorted = below < y || (below == y && m_sorted[k - 1] < m_sorted[k]);
        }
        if (sorted)
            continue;
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
