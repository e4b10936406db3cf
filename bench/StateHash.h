#pragma once
// The benches' fingerprint of a run: FNV-1a over the bits of every agent's final
// position and velocity. Equal hashes = bit-identical trajectories' ends (1 and 2
// threads, a kernel against the general path, before and after a change).

#include "simcore/world/World.h"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

namespace throng::bench {

inline std::uint64_t stateHash(const sim::World& world, bool byId = false)
{
    std::vector<std::size_t> order(world.agentCount());
    std::iota(order.begin(), order.end(), std::size_t(0));
    if (byId)
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return world.id(a) < world.id(b); });
    std::uint64_t h = 1469598103934665603ull;
    auto add = [&](float v) {
        h ^= std::bit_cast<std::uint32_t>(v);
        h *= 1099511628211ull;
    };
    for (const std::size_t i : order)
        for (int c = 0; c < 3; ++c) {
            add(world.positions()[i][c]);
            add(world.velocities()[i][c]);
        }
    return h;
}

}  // namespace throng::bench
