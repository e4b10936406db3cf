#include "simcore/layout/LayoutResolve.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace throng::sim {

namespace {

constexpr int kRounds = 24;  // relaxation rounds; a squeezed group of a dozen settles in fewer

bool standsInShot(const AgentFrame& a) { return a.present && !a.out; }

glm::vec2 xzOf(const AgentFrame& a) { return {a.position.x, a.position.z}; }

// A fixed direction per agent, for two bodies on one spot: the golden angle apart.
glm::vec2 fallbackDirection(std::size_t i)
{
    const float angle = 2.39996323f * float(i + 1);
    return {std::cos(angle), std::sin(angle)};
}

class ResolveGrid {
public:
    ResolveGrid(std::span<const AgentFrame> laid, float cell) : m_cell(cell)
    {
        for (std::size_t i = 0; i < laid.size(); ++i)
            if (standsInShot(laid[i]))
                m_cells[key(cellOf(xzOf(laid[i])))].push_back(i);
    }
    template <class F>
    void forNear(glm::vec2 p, F f) const
    {
        const auto c = cellOf(p);
        for (long long dx = -1; dx <= 1; ++dx)
            for (long long dz = -1; dz <= 1; ++dz)
                if (const auto it = m_cells.find(key({c.first + dx, c.second + dz})); it != m_cells.end())
                    for (const std::size_t j : it->second)
                        f(j);
    }

private:
    std::pair<long long, long long> cellOf(glm::vec2 p) const
    {
        return {std::llround(std::floor(p.x / m_cell)), std::llround(std::floor(p.y / m_cell))};
    }
    static std::uint64_t key(std::pair<long long, long long> c)
    {
        return (std::uint64_t(c.first) << 32) ^ std::uint64_t(c.second & 0xffffffff);
    }
    float m_cell;
    std::unordered_map<std::uint64_t, std::vector<std::size_t>> m_cells;
};

}  // namespace

void resolveFrame(const ResolveFrame& frame, float toleranceM)
{
    std::span<AgentFrame> laid = frame.laid;
    const std::size_t n = laid.size(), recordedCount = frame.recorded.size();
    if (std::none_of(frame.movable.begin(), frame.movable.end(), [](std::uint8_t m) { return m != 0; }))
        return;
    float largest = 0.0f;
    for (const float r : frame.radius)
        largest = std::max(largest, r);
    const float cell = std::max(2.0f * largest, 0.1f);
    // Whether the recording had the pair overlapping: then it is the simulation's, not ours.
    auto recordedOverlap = [&](std::size_t i, std::size_t j) {
        if (i >= recordedCount || j >= recordedCount || !standsInShot(frame.recorded[i]) ||
            !standsInShot(frame.recorded[j]))
            return false;
        return glm::length(xzOf(frame.recorded[i]) - xzOf(frame.recorded[j])) <
               frame.radius[i] + frame.radius[j] - toleranceM;
    };
    std::vector<glm::vec2> delta(n);
    for (int round = 0; round < kRounds; ++round) {
        const ResolveGrid grid(laid, cell);
        std::fill(delta.begin(), delta.end(), glm::vec2(0.0f));
        bool pushed = false;
        for (std::size_t i = 0; i < n; ++i) {
            if (!frame.movable[i] || !standsInShot(laid[i]))
                continue;
            const glm::vec2 p = xzOf(laid[i]);
            grid.forNear(p, [&](std::size_t j) {
                if (j == i || (frame.movable[j] && j < i))  // a movable pair once, from its lower index
                    return;
                const float need = frame.radius[i] + frame.radius[j] - 0.5f * toleranceM;
                const glm::vec2 d = p - xzOf(laid[j]);
                const float gap = glm::length(d);
                if (gap >= need || recordedOverlap(i, j))
                    return;
                const glm::vec2 away = gap > 1e-6f ? d / gap : fallbackDirection(i);
                const float push = need - gap;
                if (frame.movable[j]) {
                    delta[i] += 0.5f * push * away;
                    delta[j] -= 0.5f * push * away;
                } else {
                    delta[i] += push * away;
                }
                pushed = true;
            });
        }
        if (!pushed)
            break;
        for (std::size_t i = 0; i < n; ++i)
            if (frame.movable[i]) {
                laid[i].position.x += delta[i].x;
                laid[i].position.z += delta[i].y;
            }
    }
    // Off the walls: a movable body a radius clear of every segment, on the side it stands.
    for (std::size_t i = 0; i < n; ++i) {
        if (!frame.movable[i] || !standsInShot(laid[i]))
            continue;
        for (const auto& [a, b] : frame.walls) {
            const glm::vec2 p = xzOf(laid[i]), ab = b - a;
            const float len2 = glm::dot(ab, ab);
            const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
            const glm::vec2 d = p - (a + t * ab);
            const float gap = glm::length(d);
            if (gap >= frame.radius[i] || gap < 1e-6f)
                continue;
            const glm::vec2 out = d / gap * (frame.radius[i] - gap);
            laid[i].position.x += out.x;
            laid[i].position.z += out.y;
        }
    }
}

}  // namespace throng::sim
