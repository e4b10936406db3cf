#pragma once
// A World stepped to its end state, and whether two such runs agree bit for bit: for the
// tests that prove a fast path changes nothing (TestCollideShortcut, TestNeighbourSweep).

#include "simcore/world/World.h"

#include <glm/vec3.hpp>

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

// The scene stepped `steps` times with these options.
inline RunBits runToEnd(const sim::Scene& s, const sim::WorldOptions& options, int steps)
{
    sim::World w(s, options);
    for (int k = 0; k < steps; ++k)
        w.step();
    return {{w.positions().begin(), w.positions().end()},
            {w.velocities().begin(), w.velocities().end()},
            {w.ups().begin(), w.ups().end()},
            w.counters().overlappingPairs};
}

}  // namespace throng::test
