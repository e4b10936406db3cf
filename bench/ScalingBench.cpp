// Step time against crowd size: the built-in `cross` scenario (BenchScenarios.h) at each
// agent count given, its steps timed one by one. Each step's time over its agents is a
// step's cost per agent; a round builds every size once, in turn, and times STEPS steps
// after the first (which warms the neighbour lists); ROUNDS rounds alternate the sizes so
// machine noise hits all alike. Prints one JSON object: per size the median over rounds of
// each round's median ns per agent-step, the spread (largest over smallest: 1 is exactly
// linear in N), and the final state hash of each size (the same for any --grid).
// --grid fine|coarse|crowd fixes the neighbour grid's cells (WorldOptions::gridCells;
// default crowd, the World's own choice), so a change can be timed against the old cells.
// --ground M makes the ground a square of half-size M metres (default: the scenario's,
// just round the rings): a few walkers on a wide ground.
// Usage: throng-bench-scaling [--agents N,N,...] [--steps S=10] [--rounds R=3]
//                             [--threads T=2] [--grid fine|coarse|crowd] [--ground M] [--brain]
#include "bench/StateHash.h"
#include "simcore/scenarios/BenchScenarios.h"
#include "simcore/world/World.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

using namespace throng::sim;

namespace {

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

struct Round {
    double nsPerAgentStep;
    std::uint64_t hash;
};

Round timeSize(std::uint32_t agents, int steps, const WorldOptions& options, bool brain, float ground)
{
    Scene scene = brain ? makeCrossBrainScenario(agents) : makeCrossScenario(agents);
    if (ground > 0.0f) {
        scene.settings.boundsMin = glm::vec2(-ground);
        scene.settings.boundsMax = glm::vec2(ground);
    }
    World world(scene, options);
    world.step();
    std::vector<double> perAgent;
    for (int k = 0; k < steps; ++k) {
        const auto t0 = std::chrono::steady_clock::now();
        world.step();
        const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t0).count();
        perAgent.push_back(ns / double(world.agentCount()));
    }
    return {median(perAgent), throng::bench::stateHash(world)};
}

}  // namespace

int main(int argc, char** argv)
{
    std::vector<std::uint32_t> sizes{10000, 100000, 1000000};
    int steps = 10, rounds = 3;
    bool brain = false;
    float ground = 0.0f;
    std::string grid = "crowd";
    WorldOptions options;
    options.threads = 2;
    for (int a = 1; a < argc; ++a) {
        const std::string arg = argv[a];
        const bool more = a + 1 < argc;
        if (arg == "--agents" && more) {
            sizes.clear();
            std::stringstream list(argv[++a]);
            for (std::string item; std::getline(list, item, ',');)
                sizes.push_back(std::uint32_t(std::stoul(item)));
        } else if (arg == "--steps" && more) {
            steps = std::max(1, std::stoi(argv[++a]));
        } else if (arg == "--rounds" && more) {
            rounds = std::max(1, std::stoi(argv[++a]));
        } else if (arg == "--threads" && more) {
            options.threads = std::stoi(argv[++a]);
        } else if (arg == "--grid" && more && (std::string(argv[a + 1]) == "fine" ||
                                              std::string(argv[a + 1]) == "coarse" ||
                                              std::string(argv[a + 1]) == "crowd")) {
            grid = argv[++a];
        } else if (arg == "--ground" && more) {
            ground = std::max(0.0f, std::stof(argv[++a]));
        } else if (arg == "--brain") {
            brain = true;
        } else {
            std::fprintf(stderr, "usage: throng-bench-scaling [--agents N,N,...] [--steps S] [--rounds R] "
                                 "[--threads T] [--grid fine|coarse|crowd] [--ground M] [--brain]\n");
            return 2;
        }
    }
    if (sizes.empty()) {
        std::fprintf(stderr, "throng-bench-scaling: --agents names no size\n");
        return 2;
    }
    options.gridCells = grid == "fine" ? GridCells::Fine : grid == "coarse" ? GridCells::Coarse : GridCells::ByCrowd;
    std::vector<std::vector<double>> ns(sizes.size());
    std::vector<std::uint64_t> hashes(sizes.size());
    for (int r = 0; r < rounds; ++r)
        for (std::size_t s = 0; s < sizes.size(); ++s) {
            const Round round = timeSize(sizes[s], steps, options, brain, ground);
            ns[s].push_back(round.nsPerAgentStep);
            hashes[s] = round.hash;
        }
    std::printf("{\"bench\": \"scaling\", \"scenario\": \"%s\", \"steps\": %d, \"rounds\": %d, \"threads\": %d, "
                "\"grid\": \"%s\", \"ground_half_m\": %.0f, \"sizes\": [",
                brain ? "cross-brain" : "cross", steps, rounds, options.threads, grid.c_str(), double(ground));
    double lo = 0.0, hi = 0.0;
    for (std::size_t s = 0; s < sizes.size(); ++s) {
        const double m = median(ns[s]);
        lo = s == 0 ? m : std::min(lo, m);
        hi = s == 0 ? m : std::max(hi, m);
        std::printf("%s{\"agents\": %u, \"ns_per_agent_step\": %.1f, \"rounds_ns\": [", s ? ", " : "", sizes[s], m);
        for (std::size_t r = 0; r < ns[s].size(); ++r)
            std::printf("%s%.1f", r ? ", " : "", ns[s][r]);
        std::printf("], \"state_hash\": \"%016llx\"}", static_cast<unsigned long long>(hashes[s]));
    }
    std::printf("], \"spread\": %.3f}\n", lo > 0.0 ? hi / lo : 0.0);
    return 0;
}
