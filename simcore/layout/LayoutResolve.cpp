#include "simcore/layout/LayoutResolve.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace throng::sim {

namespace {

constexpr int kRounds = 8;            // relaxation rounds (each visits every pair once, in order)
constexpr float kSettledM = 1e-4f;    // a round that pushes no body further than this ends them

bool standsInShot(const AgentFrame& a) { return a.present && !a.out; }

glm::vec2 xzOf(const AgentFrame& a) { return {a.position.x, a.position.z}; }

// A fixed direction per agent, for two bodies on one spot: the golden angle apart.
glm::vec2 fallbackDirection(std::size_t i)
{
    const float angle = 2.39996323f * float(i + 1);
    return {std::cos(angle), std::sin(angle)};
}

// Agents by grid cell over a box: counts, then one array in cell order (built once per
// round, searched in constant time per cell). Points outside the box go to its edge cells.
class CellGrid {
public:
    CellGrid(glm::vec2 lo, glm::vec2 hi, float cell)
        : m_lo(lo), m_cell(cell),
          m_cols(std::max(1, int(std::ceil((hi.x - lo.x) / cell)))),
          m_rows(std::max(1, int(std::ceil((hi.y - lo.y) / cell))))
    {
    }
    std::size_t cells() const { return std::size_t(m_cols) * std::size_t(m_rows); }
    void build(std::span<const AgentFrame> laid, const std::vector<std::uint32_t>& agents)
    {
        m_start.assign(cells() + 1, 0);
        m_cellOf.resize(agents.size());
        for (std::size_t k = 0; k < agents.size(); ++k) {
            m_cellOf[k] = cellIndex(xzOf(laid[agents[k]]));
            ++m_start[m_cellOf[k] + 1];
        }
        for (std::size_t c = 0; c < cells(); ++c)
            m_start[c + 1] += m_start[c];
        m_items.resize(agents.size());
        std::vector<std::uint32_t> fill(m_start.begin(), m_start.end() - 1);
        for (std::size_t k = 0; k < agents.size(); ++k)
            m_items[fill[m_cellOf[k]]++] = agents[k];
    }
    template <class F>
    void forNear(glm::vec2 p, F f) const
    {
        const int cx = column(p.x), cz = row(p.y);
        for (int z = std::max(0, cz - 1); z <= std::min(m_rows - 1, cz + 1); ++z)
            for (int x = std::max(0, cx - 1); x <= std::min(m_cols - 1, cx + 1); ++x) {
                const std::size_t c = std::size_t(z) * std::size_t(m_cols) + std::size_t(x);
                for (std::uint32_t k = m_start[c]; k < m_start[c + 1]; ++k)
                    f(std::size_t(m_items[k]));
            }
    }

private:
    int column(float x) const { return std::clamp(int(std::floor((x - m_lo.x) / m_cell)), 0, m_cols - 1); }
    int row(float z) const { return std::clamp(int(std::floor((z - m_lo.y) / m_cell)), 0, m_rows - 1); }
    std::uint32_t cellIndex(glm::vec2 p) const { return std::uint32_t(row(p.y) * m_cols + column(p.x)); }

    glm::vec2 m_lo;
    float m_cell;
    int m_cols, m_rows;
    std::vector<std::uint32_t> m_start, m_items, m_cellOf;
};

}  // namespace

void resolveFrame(const ResolveFrame& frame, float toleranceM)
{
    std::span<AgentFrame> laid = frame.laid;
    const std::size_t n = laid.size(), recordedCount = frame.recorded.size();
    std::vector<std::uint32_t> moving;
    for (std::size_t i = 0; i < n; ++i)
        if (frame.movable[i] && standsInShot(laid[i]))
            moving.push_back(std::uint32_t(i));
    if (moving.empty())
        return;
    float largest = 0.0f;
    for (const float r : frame.radius)
        largest = std::max(largest, r);
    const float cell = std::max(2.0f * largest, 0.1f);
    // The bodies that stay, near enough to the moving ones to touch them (a move of up to
    // a body's width each round included): found once per frame.
    glm::vec2 lo(std::numeric_limits<float>::max()), hi(std::numeric_limits<float>::lowest());
    for (const std::uint32_t i : moving) {
        lo = glm::min(lo, xzOf(laid[i]));
        hi = glm::max(hi, xzOf(laid[i]));
    }
    const float reach = float(kRounds + 1) * cell;
    lo -= glm::vec2(reach);
    hi += glm::vec2(reach);
    // Cells no finer than needed to hold the box in a few cells per body near it: movers
    // kilometres apart make a coarse grid (slower), never a huge one.
    float gridCell = cell;
    const double area = double(hi.x - lo.x) * double(hi.y - lo.y);
    const double cap = 16.0 * double(n) + 4096.0;
    if (area / (double(cell) * double(cell)) > cap)
        gridCell = float(std::sqrt(area / cap));
    std::vector<std::uint32_t> staying;
    staying.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        if (frame.movable[i] || !standsInShot(laid[i]))
            continue;
        const glm::vec2 p = xzOf(laid[i]);
        if (p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y)
            staying.push_back(std::uint32_t(i));
    }
    CellGrid still(lo, hi, gridCell), moved(lo, hi, gridCell);
    still.build(laid, staying);
    // Whether the recording had the pair overlapping: then it is the simulation's, not ours.
    auto recordedOverlap = [&](std::size_t i, std::size_t j) {
        if (i >= recordedCount || j >= recordedCount || !standsInShot(frame.recorded[i]) ||
            !standsInShot(frame.recorded[j]))
            return false;
        return glm::length(xzOf(frame.recorded[i]) - xzOf(frame.recorded[j])) <
               frame.radius[i] + frame.radius[j] - toleranceM;
    };
    auto move = [&](std::size_t i, glm::vec2 by) {
        laid[i].position.x += by.x;
        laid[i].position.z += by.y;
    };
    for (int round = 0; round < kRounds; ++round) {
        moved.build(laid, moving);
        float largestPush = 0.0f;
        for (const std::uint32_t i : moving) {
            auto separate = [&](std::size_t j) {
                if (j == i || (frame.movable[j] && j < i))  // a moving pair once, from its lower index
                    return;
                const float need = frame.radius[i] + frame.radius[j] - 0.5f * toleranceM;
                const glm::vec2 d = xzOf(laid[i]) - xzOf(laid[j]);
                const float gap = glm::length(d);
                if (gap >= need || recordedOverlap(i, j))
                    return;
                const glm::vec2 away = gap > 1e-6f ? d / gap : fallbackDirection(i);
                const float push = need - gap;
                largestPush = std::max(largestPush, push);
                if (frame.movable[j]) {
                    move(i, 0.5f * push * away);
                    move(j, -0.5f * push * away);
                } else {
                    move(i, push * away);
                }
            };
            still.forNear(xzOf(laid[i]), separate);
            moved.forNear(xzOf(laid[i]), separate);
        }
        if (largestPush < kSettledM)
            break;
    }
    // Off the walls: a moving body a radius clear of every segment, on the side it stands.
    for (const std::uint32_t i : moving)
        for (const auto& [a, b] : frame.walls) {
            const glm::vec2 p = xzOf(laid[i]), ab = b - a;
            const float len2 = glm::dot(ab, ab);
            const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
            const glm::vec2 d = p - (a + t * ab);
            const float gap = glm::length(d);
            if (gap >= frame.radius[i] || gap < 1e-6f)
                continue;
            move(i, d / gap * (frame.radius[i] - gap));
        }
}

}  // namespace throng::sim
