#pragma once
// A World stepped to its end state, and whether two such runs agree bit for bit, and a
// packed flock to run: for the tests that prove a fast path changes nothing
// (TestCollideShortcut, TestContactShortcut, TestNeighbourSweep).

#include "simcore/world/World.h"

#include <glm/vec3.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace throng::test {

struct RunBits {
    std::vector<glm::vec3> pos, vel, up;
    std::uint64_t overlaps = 0;

    // The same positions, velocities and up vectors, to the bit.
    bool sameStateAs(const RunBits& o) const { return same(pos, o.pos) && same(vel, o.vel) && same(up, o.up); }

private:
    static bool same(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b)
    {
        return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(glm::vec3)) == 0;
    }
};

// Packs the birds of a flock scene (every agent but the first, the lead bird) on a lattice
// 12 wide and 12 high from (100, y0, -12), spacingM apart, each nudged across by up to
// jitterM in a fixed pattern: a dense start where many birds touch.
inline void packOnLattice(sim::Scene& s, float spacingM, float jitterM = 0.0f, float y0 = 30.0f)
{
    for (std::size_t k = 1; k < s.agents.size(); ++k) {
        const auto i = float(k);
        s.agents[k].position = glm::vec3(100.0f + spacingM * std::fmod(i, 12.0f) + jitterM * std::sin(i * 12.9898f),
                                         y0 + spacingM * std::fmod(std::floor(i / 12.0f), 12.0f),
                                         -12.0f + spacingM * std::floor(i / 144.0f) + jitterM * std::cos(i * 78.233f));
    }
}

// A World's state now, and the overlaps it has counted.
inline RunBits bitsOf(const sim::World& w)
{
    return {{w.positions().begin(), w.positions().end()},
            {w.velocities().begin(), w.velocities().end()},
            {w.ups().begin(), w.ups().end()},
            w.counters().overlappingPairs};
}

// The scene stepped `steps` times with these options.
inline RunBits runToEnd(const sim::Scene& s, const sim::WorldOptions& options, int steps)
{
    sim::World w(s, options);
    for (int k = 0; k < steps; ++k)
        w.step();
    return bitsOf(w);
}

}  // namespace throng::test
