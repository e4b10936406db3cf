// What a crowd that has moved gains from being stored in the grid's order again: a bench
// scenario (BenchScenarios.h) stepped WARM times, then copied into a second World whose
// agents are stored in the order of the neighbour grid's cells (rows along z, cells along
// x, then up), with the first World's state carried over (remapState: every agent keeps
// its id and its whole state; only where it is stored changes). Both then step on, in
// ROUNDS alternating rounds of STEPS steps each, so machine noise hits both alike.
// Prints one JSON object: ms per step stored as placed and re-sorted, their ratio, and
// each World's state hash in id order at the end, which must be equal: no result depends
// on the order (TieOrder.h; worldstate.TestStorageOrder). What a World that keeps its own
// order as its agents move would be worth.
// Usage: throng-bench-resort [--scenario flock|cross|cross-brain|army|corridor]
//                            [--agents N=100000] [--warm W=120] [--steps S=10] [--rounds R=3]
//                            [--threads T=2]
#include "bench/StateHash.h"
#include "simcore/scenarios/BenchScenarios.h"
#include "simcore/world/GridOrder.h"
#include "simcore/world/World.h"
#include "simcore/world/WorldState.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <numeric>
#include <string>
#include <tuple>
#include <vector>

using namespace throng::sim;

namespace {

double stepFor(World& world, int steps)
{
    const auto start = std::chrono::steady_clock::now();
    for (int s = 0; s < steps; ++s)
        world.step();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv)
{
    std::string scenario = "flock";
    long agents = 100000, warm = 120, steps = 10, rounds = 3, threads = 2;
    for (int a = 1; a + 1 < argc; a += 2) {
        const std::string key = argv[a], value = argv[a + 1];
        if (key == "--scenario")
            scenario = value;
        else if (key == "--agents")
            agents = std::atol(value.c_str());
        else if (key == "--warm")
            warm = std::atol(value.c_str());
        else if (key == "--steps")
            steps = std::atol(value.c_str());
        else if (key == "--rounds")
            rounds = std::atol(value.c_str());
        else if (key == "--threads")
            threads = std::atol(value.c_str());
        else {
            std::fprintf(stderr, "throng-bench-resort: unknown option %s\n", key.c_str());
            return 2;
        }
    }
    Scene scene;
    if (agents <= 0 || !makeBenchScenario(scenario, std::uint32_t(agents), scene)) {
        std::fprintf(stderr, "throng-bench-resort: no scenario '%s' of %ld agents\n", scenario.c_str(), agents);
        return 2;
    }
    orderPlacedForGrid(scene);  // as throng-cli run and bench store it
    WorldOptions options;
    options.threads = int(threads);
    World placed(scene, options);
    stepFor(placed, int(warm));
    const WorldState state = placed.saveState();
    const std::size_t n = placed.agentCount();
    if (n != scene.agents.size()) {
        std::fprintf(stderr, "throng-bench-resort: '%s' has agents that are not placed\n", scenario.c_str());
        return 2;
    }

    // The grid's order of where they stand now: rows of cells along z, cells along x, up.
    const float cell = placed.neighbourCellM();
    const glm::vec2 min = scene.settings.boundsMin;
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    auto key = [&](std::uint32_t i) {
        const glm::vec3 p = state.pos[i];
        return std::tuple(std::floor((p.z - min.y) / cell), std::floor((p.x - min.x) / cell), p.y, i);
    };
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); });
    Scene sorted = scene;
    for (std::size_t k = 0; k < n; ++k)
        sorted.agents[k] = scene.agents[order[k]];
    World resorted(sorted, options);
    const std::vector<std::int32_t> previous(order.begin(), order.end());
    WorldState carried = remapState(state, resorted.saveState(), previous);
    // Leaders are dense indices (adoptState takes them from the scene; here they move
    // with their agents).
    std::vector<std::int32_t> now(n);
    for (std::size_t k = 0; k < n; ++k)
        now[order[k]] = std::int32_t(k);
    for (std::int32_t& l : carried.leader)
        l = l >= 0 ? now[std::size_t(l)] : l;
    resorted.restoreState(carried);

    double asPlaced = 0.0, asSorted = 0.0;
    for (long r = 0; r < rounds; ++r) {
        asPlaced += stepFor(placed, int(steps));
        asSorted += stepFor(resorted, int(steps));
    }
    const double timed = double(rounds * steps);
    const auto hashPlaced = throng::bench::stateHash(placed, true), hashSorted = throng::bench::stateHash(resorted, true);
    std::printf("{\"bench\": \"resort\", \"scenario\": \"%s\", \"agents\": %zu, \"threads\": %d, \"warm\": %ld, "
                "\"steps\": %ld, \"ms_per_step_as_placed\": %.3f, \"ms_per_step_resorted\": %.3f, "
                "\"ratio\": %.3f, \"state_hash_as_placed\": \"%016llx\", \"state_hash_resorted\": \"%016llx\", "
                "\"same_result\": %s}\n",
                scenario.c_str(), n, placed.threads(), warm, rounds * steps, asPlaced * 1000.0 / timed,
                asSorted * 1000.0 / timed, asSorted > 0.0 ? asPlaced / asSorted : 0.0,
                static_cast<unsigned long long>(hashPlaced), static_cast<unsigned long long>(hashSorted),
                hashPlaced == hashSorted ? "true" : "false");
    return hashPlaced == hashSorted ? 0 : 1;
}
