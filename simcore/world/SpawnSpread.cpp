#include "simcore/world/SpawnSpread.h"

#include "simcore/base/Rng.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <unordered_map>

namespace throng::sim {

namespace {

// The bodies by square cell of the largest diameter, so a body's overlaps lie in its own
// and the 8 cells around. Cells are kept as bodies move.
class SpreadGrid {
public:
    explicit SpreadGrid(float cellM) : m_inv(1.0f / cellM) {}
    std::int64_t cellX(float v) const { return clampCell(v * m_inv); }
    void insert(std::uint32_t i, glm::vec2 p) { m_cells[key(cellX(p.x), cellX(p.y))].push_back(i); }
    void move(std::uint32_t i, glm::vec2 from, glm::vec2 to)
    {
        const std::uint64_t a = key(cellX(from.x), cellX(from.y)), b = key(cellX(to.x), cellX(to.y));
        if (a == b)
            return;
        std::vector<std::uint32_t>& old = m_cells[a];
        old.erase(std::find(old.begin(), old.end(), i));
        m_cells[b].push_back(i);
    }
    template <class F>
    void forEachNear(glm::vec2 p, F&& f) const
    {
        const std::int64_t cx = cellX(p.x), cz = cellX(p.y);
        for (std::int64_t x = cx - 1; x <= cx + 1; ++x)
            for (std::int64_t z = cz - 1; z <= cz + 1; ++z)
                if (const auto it = m_cells.find(key(x, z)); it != m_cells.end())
                    for (const std::uint32_t j : it->second)
                        f(j);
    }

private:
    static std::int64_t clampCell(float c)
    {
        if (!(c >= -1e15f))  // NaN too: a place that is not a number lands in an end cell
            return std::int64_t(-1e15);
        return std::int64_t(std::floor(std::min(c, 1e15f)));
    }
    static std::uint64_t key(std::int64_t x, std::int64_t z)
    {
        return (std::uint64_t(x) * 0x9E3779B97F4A7C15ull) ^ std::uint64_t(z);
    }
    float m_inv;
    std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> m_cells;
};

}  // namespace

void spreadBodies(std::vector<SpreadBody>& bodies, const SettleFn& settle, float toleranceM, int maxRounds)
{
    float largest = 0.0f;
    for (const SpreadBody& b : bodies)
        largest = std::max(largest, b.r);
    if (bodies.empty() || !(largest > 0.0f))
        return;
    SpreadGrid grid(2.0f * largest);
    for (std::uint32_t i = 0; i < bodies.size(); ++i)
        grid.insert(i, bodies[i].p);
    // Each round looks at the movable bodies that may overlap: at first all, then those
    // that moved or were overlapped by one that did.
    std::vector<std::uint32_t> active, next;
    std::vector<std::uint8_t> queued(bodies.size(), 0);
    for (std::uint32_t i = 0; i < bodies.size(); ++i)
        if (bodies[i].movable)
            active.push_back(i);
    std::vector<glm::vec2> push(bodies.size(), glm::vec2(0.0f));
    for (int round = 0; round < maxRounds && !active.empty(); ++round) {
        // Jacobi: every push is worked out from the places at the start of the round.
        for (const std::uint32_t i : active) {
            const SpreadBody& a = bodies[i];
            glm::vec2 sum(0.0f);
            grid.forEachNear(a.p, [&](std::uint32_t j) {
                if (j == i)
                    return;
                const SpreadBody& b = bodies[j];
                const glm::vec2 d = a.p - b.p;
                const float contact = a.r + b.r, d2 = glm::dot(d, d);
                if (!(d2 < (contact - toleranceM) * (contact - toleranceM)))
                    return;
                const float dist = std::sqrt(d2);
                glm::vec2 dir;
                if (dist > 1e-6f) {
                    dir = d / dist;
                } else {  // coincident: apart along a direction both derive, in opposite senses
                    const std::uint64_t lo = std::min(a.key, b.key), hi = std::max(a.key, b.key);
                    const float angle = float(rngUniform(lo, hi, 0, 78)) * 6.2831853f;
                    dir = glm::vec2(std::cos(angle), std::sin(angle)) * (a.key == lo ? 1.0f : -1.0f);
                }
                sum += dir * ((contact - dist) * (b.movable ? 0.5f : 1.0f));
            });
            push[i] = sum;
        }
        next.clear();
        auto queue = [&](std::uint32_t j) {
            if (bodies[j].movable && !queued[j]) {
                queued[j] = 1;
                next.push_back(j);
            }
        };
        for (const std::uint32_t i : active) {
            if (push[i] == glm::vec2(0.0f) && round > 0)
                continue;  // (the first round settles every member: one may overlap a wall's edge)
            SpreadBody& a = bodies[i];
            glm::vec2 to;
            if (!settle(a.p + push[i], a.r, to) || to == a.p)
                continue;
            grid.move(i, a.p, to);
            a.p = to;
            queue(i);
            grid.forEachNear(a.p, [&](std::uint32_t j) {
                const float contact = a.r + bodies[j].r;
                const glm::vec2 d = a.p - bodies[j].p;
                if (j != i && glm::dot(d, d) < contact * contact)
                    queue(j);
            });
        }
        for (const std::uint32_t j : next)
            queued[j] = 0;
        std::sort(next.begin(), next.end());  // the same rounds whatever order they were met in
        active.swap(next);
    }
}

}  // namespace throng::sim
