// `flock` with the boids kernel's switches: the built-in flock scenario (BenchScenarios.h,
// the same scene as `throng-cli bench --scenario flock`) stepped a fixed number of times,
// with the kernel, the collide pass's shortcut, the neighbour sweep and the eight-wide
// steering (AVX2, where the CPU has it; "lanes" says which ran) on or off, so a
// change can be measured against the path it replaces in one build (under callgrind:
// instructions per agent-step).
// Prints one JSON object: agents, steps, seconds, agent_steps_per_second, overlapping
// pairs per step, and "state_hash" (FNV-1a over the bits of every position and velocity
// at the end: whether a switch left the trajectories bit-identical; "state_hash_by_id"
// takes the birds in id order, for --by-column).
// --warmup W steps W times before the clock starts, to measure the flock once it has
// gathered (it grows denser over its first few hundred steps). Under callgrind,
// --toggle-collect='*measuredStep*' counts only the timed steps. --by-column numbers the
// same birds up each column first (FlockNumbering::ByColumn), so the World stores them in
// the order its grid visits them: what memory order alone is worth ("numbering").
// Usage: throng-bench-flock [AGENTS=100000] [STEPS=60] [THREADS=0] [--warmup W] [--no-kernel]
//                           [--no-shortcut] [--no-sweep] [--four-lanes] [--by-column]
#include "bench/StateHash.h"
#include "simcore/scenarios/BenchScenarios.h"
#include "simcore/world/World.h"

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

using namespace throng::sim;

namespace {
// One timed step, out of line so a profiler can single it out.
[[gnu::noinline]] void measuredStep(World& world)
{
    world.step();
}
}  // namespace

int main(int argc, char** argv)
{
    std::vector<std::string> numbers;
    WorldOptions options;
    int warmup = 0;
    FlockNumbering numbering = FlockNumbering::RowByRow;
    for (int a = 1; a < argc; ++a) {
        const std::string arg = argv[a];
        if (arg == "--no-kernel") {
            options.boidKernel = false;
        } else if (arg == "--warmup" && a + 1 < argc) {
            warmup = std::stoi(argv[++a]);
        } else if (arg == "--no-sweep") {
            options.neighbourSweep = false;
        } else if (arg == "--no-shortcut") {
            options.collideShortcut = false;
        } else if (arg == "--four-lanes") {
            options.steerEight = false;
        } else if (arg == "--by-column") {
            numbering = FlockNumbering::ByColumn;
        } else if (!arg.empty() && arg[0] != '-') {
            numbers.push_back(arg);
        } else {
            std::fprintf(stderr,
                         "usage: throng-bench-flock [AGENTS] [STEPS] [THREADS] [--warmup W] [--no-kernel] "
                         "[--no-shortcut] [--no-sweep] [--four-lanes] [--by-column]\n");
            return 2;
        }
    }
    const auto agents = std::uint32_t(numbers.size() > 0 ? std::stoul(numbers[0]) : 100000);
    const int steps = numbers.size() > 1 ? std::stoi(numbers[1]) : 60;
    options.threads = numbers.size() > 2 ? std::stoi(numbers[2]) : 0;
    World world(makeFlockScenario(agents, 1, numbering), options);
    for (int k = 0; k < warmup; ++k)
        world.step();
    const auto overlapsBefore = world.counters().overlappingPairs;
    const auto t0 = std::chrono::steady_clock::now();
    for (int k = 0; k < steps; ++k)
        measuredStep(world);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double agentSteps = double(world.agentCount()) * double(steps);
    std::printf("{\"agents\": %zu, \"warmup\": %d, \"steps\": %d, \"kernel\": %s, \"shortcut\": %s, \"sweep\": %s, "
                "\"lanes\": %d, \"numbering\": \"%s\", \"seconds\": %.4f, "
                "\"agent_steps_per_second\": %.0f, \"overlapping_pairs_per_step\": %.3f, "
                "\"state_hash\": \"%016llx\", \"state_hash_by_id\": \"%016llx\"}\n",
                world.agentCount(), warmup, steps, options.boidKernel ? "true" : "false",
                options.collideShortcut ? "true" : "false", options.neighbourSweep ? "true" : "false",
                world.boidLanes(), numbering == FlockNumbering::ByColumn ? "by column" : "row by row", seconds,
                seconds > 0.0 ? agentSteps / seconds : 0.0,
                double(world.counters().overlappingPairs - overlapsBefore) / double(steps > 0 ? steps : 1),
                static_cast<unsigned long long>(throng::bench::stateHash(world)),
                static_cast<unsigned long long>(throng::bench::stateHash(world, true)));
    return 0;
}
