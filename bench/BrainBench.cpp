// Brain evaluation throughput: a 40-node pedestrian-style brain (fuzz, rules, defuzz,
// per-neighbour logic and a filter, state, outputs) over N agents with random sensor
// values, for 1 and 2 threads, next to the World step of a built-in scenario of the same
// size, and that World step again with every agent driven by the brain (sensors gathered
// from the World): the brain's share of the step is the time it adds. Then every agent
// emits on a sound channel (4 m) and runs a 5-node brain that turns to the loudest one it
// hears: "sound_share_of_step" is the time hearing and that brain add. Prints one JSON
// object. Usage: throng-bench-brain [AGENTS] [SCENARIO]
#include "simcore/brain/BrainCompiler.h"
#include "simcore/brain/BrainEvaluator.h"
#include "simcore/brain/NodeCatalogue.h"
#include "simcore/scenarios/BenchBrains.h"
#include "simcore/scenarios/BenchScenarios.h"
#include "simcore/world/World.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

using namespace throng::sim;

namespace {

// Median of 5 steps after a first one (which builds what the first step builds).
double stepMedianMs(const Scene& scene, int threads)
{
    WorldOptions options;
    options.threads = threads;
    World world(scene, options);
    if (!world.brainErrors().empty()) {
        std::fprintf(stderr, "%s\n", world.brainErrors()[0].c_str());
        std::exit(1);
    }
    world.step();
    std::vector<double> times;
    for (int s = 0; s < 5; ++s) {
        const auto t0 = std::chrono::steady_clock::now();
        world.step();
        times.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    }
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
}

double since(std::chrono::steady_clock::time_point t0)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv)
{
    const std::size_t agents = argc > 1 ? std::stoul(argv[1]) : 100'000;
    const std::string scenario = argc > 2 ? argv[2] : "corridor";
    const BrainGraph graph = benchPedestrianBrain();
    const BrainCompileResult compiled = compileBrain(graph);
    if (!compiled.ok()) {
        for (const BrainError& e : compiled.errors)
            std::fprintf(stderr, "%s\n", e.format().c_str());
        return 1;
    }
    const BrainProgram& program = *compiled.program;

    std::mt19937 gen(7);
    std::uniform_real_distribution<float> u(-5.0f, 30.0f);
    std::vector<std::vector<float>> columns;
    BrainInputs in;
    for (const BrainSensorUse& s : program.sensors) {
        columns.emplace_back(agents * (s.perNeighbour ? kBrainNeighbours : 1));
        for (float& v : columns.back())
            v = u(gen);
    }
    for (const std::vector<float>& c : columns)
        in.sensors.push_back(c.data());
    std::vector<std::uint8_t> counts(agents);
    std::vector<std::uint64_t> keys(agents);
    for (std::size_t i = 0; i < agents; ++i) {
        counts[i] = std::uint8_t(gen() % (kBrainNeighbours + 1));
        keys[i] = gen();
    }
    for (std::size_t s = 0; s < program.itemSets.size(); ++s)
        in.itemCounts.push_back(counts.data());
    in.agentKey = keys.data();
    in.dtS = 1.0f / 24.0f;

    double brainMs[2] = {0, 0}, stepMs[2] = {0, 0}, brainStepMs[2] = {0, 0}, soundStepMs[2] = {0, 0};
    for (int threads = 1; threads <= 2; ++threads) {
        const ThreadTeam team(threads);
        BrainEvaluator eval(compiled.program);
        eval.resize(agents);
        std::vector<double> times;
        for (int s = 0; s < 23; ++s) {
            in.timeS = float(s) * in.dtS;
            const auto t0 = std::chrono::steady_clock::now();
            eval.evaluate(in, nullptr, &team);
            if (s >= 3)
                times.push_back(since(t0));
        }
        brainMs[threads - 1] = median(times);

        Scene scene;
        if (!makeBenchScenario(scenario, std::uint32_t(agents), scene)) {
            std::fprintf(stderr, "unknown scenario '%s'\n", scenario.c_str());
            return 2;
        }
        stepMs[threads - 1] = stepMedianMs(scene, threads);
        BrainGraph named = graph;
        named.name = "bench40";
        scene.brains.push_back(named);
        for (AgentType& type : scene.agentTypes)
            type.brain = "bench40";
        brainStepMs[threads - 1] = stepMedianMs(scene, threads);
        scene.brains.push_back(benchListenerBrain());
        for (AgentType& type : scene.agentTypes) {
            type.brain = "listen";
            type.emits = {"chat", 1.0f, 4.0f};
        }
        soundStepMs[threads - 1] = stepMedianMs(scene, threads);
    }
    const double nodes = double(program.graphNodes);
    std::printf("{\"agents\": %zu, \"brain_nodes\": %u, \"instructions\": %zu, \"scenario\": \"%s\",\n", agents,
                program.graphNodes, program.code.size(), scenario.c_str());
    for (int t = 0; t < 2; ++t)
        std::printf(" \"threads_%d\": {\"brain_ms_per_step\": %.3f, \"node_evaluations_per_second\": %.4g, "
                    "\"world_step_ms\": %.3f, \"brain_share_of_step\": %.3f, "
                    "\"world_step_with_brain_ms\": %.3f, \"brain_in_world_share_of_step\": %.3f, "
                    "\"world_step_with_sound_ms\": %.3f, \"sound_share_of_step\": %.3f}%s\n",
                    t + 1, brainMs[t], nodes * double(agents) / (brainMs[t] / 1000.0), stepMs[t],
                    brainMs[t] / (brainMs[t] + stepMs[t]), brainStepMs[t],
                    (brainStepMs[t] - stepMs[t]) / brainStepMs[t], soundStepMs[t],
                    (soundStepMs[t] - stepMs[t]) / soundStepMs[t], t == 0 ? "," : "}");
    return 0;
}
