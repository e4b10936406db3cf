// `cross` run to its end: the built-in cross scenario (BenchScenarios.h, the layout the
// DetourCrowd peer gets too) stepped until every agent has arrived or the scenario's
// duration is over. Prints one JSON object with the quality figures of issue 3: fraction
// arrived, time until 95 % and until all arrived, overlapping pairs per step (also as a
// fraction of the agents), and agent-steps per second.
// Usage: throng-bench-cross [AGENTS=10000] [THREADS=0] [MAX_STEPS=0 (= the scene's duration)]
//        throng-bench-cross --write-layout FILE [AGENTS] (for the DetourCrowd peer)
// CROSS_SPACING_M, CROSS_INNER_M, CROSS_GAP_M in the environment change the layout;
// CROSS_PROFILE prints the walkers' mean speed by distance from the centre (where time goes);
// CROSS_DUMP lists the agents that did not arrive. "state_hash" (FNV-1a over the bits of
// every position and velocity at the end) tells whether a change left the trajectories
// bit-identical, and whether 1 and 2 threads agree.
#include "bench/StateHash.h"
#include "simcore/scenarios/BenchScenarios.h"
#include "simcore/world/World.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace throng::sim;

namespace {

// The layout for the DetourCrowd peer: one "x z goal_x goal_z" line per agent.
int writeLayout(const Scene& scene, const char* path)
{
    FILE* f = std::fopen(path, "w");
    if (!f) {
        std::fprintf(stderr, "throng-bench-cross: cannot write %s\n", path);
        return 1;
    }
    for (std::size_t i = 0; i < scene.agents.size(); ++i)
        std::fprintf(f, "%.9g %.9g %.9g %.9g\n", double(scene.agents[i].position.x), double(scene.agents[i].position.z),
                     double(scene.goals[i].position.x), double(scene.goals[i].position.y));
    return std::fclose(f) == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc > 1 && std::string(argv[1]) == "--write-layout") {
        if (argc < 3) {
            std::fprintf(stderr, "usage: throng-bench-cross --write-layout FILE [AGENTS=10000]\n");
            return 2;
        }
        return writeLayout(makeCrossScenario(argc > 3 ? std::uint32_t(std::stoul(argv[3])) : 10000), argv[2]);
    }
    const auto agents = std::uint32_t(argc > 1 ? std::stoul(argv[1]) : 10000);
    WorldOptions options;
    options.threads = argc > 2 ? std::stoi(argv[2]) : 0;
    // Layout overrides for exploring (the defaults are the benchmark's layout).
    CrossLayout layout;
    if (const char* v = std::getenv("CROSS_SPACING_M"))
        layout.spacingM = std::stof(v);
    if (const char* v = std::getenv("CROSS_INNER_M"))
        layout.innerRadiusM = std::stof(v);
    if (const char* v = std::getenv("CROSS_GAP_M"))
        layout.ringGapM = std::stof(v);
    const Scene scene = makeCrossScenario(agents, 1, layout);
    World world(scene, options);
    const auto maxSteps = argc > 3 && std::stoull(argv[3]) > 0
                              ? std::stoull(argv[3])
                              : std::uint64_t(double(scene.settings.durationS) * double(scene.settings.fps));
    const auto start = std::chrono::steady_clock::now();
    std::uint64_t steps = 0;
    std::size_t arrived = 0;
    double t95 = -1.0;
    const std::size_t n = world.agentCount();
    std::vector<double> speedSum(40, 0.0), speedCount(40, 0.0);
    const bool profile = std::getenv("CROSS_PROFILE") != nullptr;
    for (; steps < maxSteps; ++steps) {
        world.step();
        if (profile)
            for (std::size_t i = 0; i < world.agentCount(); ++i)
                if (!world.hasArrived(i)) {
                    const glm::vec3 p = world.positions()[i], v = world.velocities()[i];
                    const auto bin = std::min<std::size_t>(39, std::size_t(std::hypot(p.x, p.z) / 5.0f));
                    speedSum[bin] += double(std::hypot(v.x, v.z));
                    speedCount[bin] += 1.0;
                }
        if (steps % 24 == 23 || steps + 1 == maxSteps) {
            arrived = 0;
            for (std::size_t i = 0; i < n; ++i)
                arrived += world.hasArrived(i) ? 1 : 0;
            if (t95 < 0.0 && double(arrived) >= 0.95 * double(n))
                t95 = world.timeS();
            if (arrived == n) {
                ++steps;
                break;
            }
        }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    float last = -1.0f;
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i)
        if (world.hasArrived(i)) {
            last = std::max(last, world.arrivalTimeS(i));
            sum += double(world.arrivalTimeS(i));
        }
    if (std::getenv("CROSS_DUMP"))  // where the ones that did not arrive are
        for (std::size_t i = 0; i < n; ++i)
            if (!world.hasArrived(i)) {
                const glm::vec3 p = world.positions()[i];
                const glm::vec2 g2 = world.goals()[std::size_t(world.goalIndex(i))].position;
                const glm::vec3 g(g2.x, 0.0f, g2.y);
                std::fprintf(stderr, "left %zu at (%.1f, %.1f) r %.1f, goal (%.1f, %.1f) r %.1f, %.1f m away\n", i,
                             double(p.x), double(p.z), double(std::hypot(p.x, p.z)), double(g.x), double(g.z),
                             double(std::hypot(g.x, g.z)), double(std::hypot(p.x - g.x, p.z - g.z)));
            }
    if (profile)
        for (std::size_t b = 0; b < 40; ++b)
            if (speedCount[b] > 0)
                std::fprintf(stderr, "r %3zu-%3zu m: %8.0f agent-steps, mean speed %.2f m/s\n", 5 * b, 5 * b + 5,
                             speedCount[b], speedSum[b] / speedCount[b]);
    const double perAgent = 1.0 / double(std::max<std::size_t>(n, 1));
    const double overlaps = double(world.counters().overlappingPairs) / double(std::max<std::uint64_t>(steps, 1));
    std::printf("{\"scenario\": \"cross\", \"layout\": \"%s\", \"agents\": %zu, \"threads\": %d, \"steps\": %llu, "
                "\"simulated_seconds\": %.1f, \"seconds\": %.2f, \"agent_steps_per_second\": %.4g, "
                "\"fraction_arrived\": %.4f, \"time_to_95_percent_s\": %.1f, \"time_to_last_arrival_s\": %.1f, "
                "\"mean_arrival_time_s\": %.1f, \"overlapping_pairs_per_step\": %.3f, "
                "\"overlapping_pairs_per_agent\": %.6f, \"non_finite_values\": %llu, \"state_hash\": \"%016llx\"}\n",
                crossLayoutDescription(layout).c_str(), n, world.threads(), (unsigned long long)steps, world.timeS(),
                seconds, double(steps) * double(n) / std::max(seconds, 1e-9), double(arrived) * perAgent, t95,
                double(last), arrived ? sum / double(arrived) : -1.0, overlaps, overlaps * perAgent,
                (unsigned long long)world.counters().nonFiniteValues, (unsigned long long)throng::bench::stateHash(world));
    return 0;
}
