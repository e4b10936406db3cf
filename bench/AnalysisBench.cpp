// throng-bench-analysis: how long the analysis of a recorded run takes (what the editor's
// Analyse button and --report do before drawing): 10,000 walkers over 2,400 frames with
// four measurement lines and two areas, each part timed, medians of 3. Prints one JSON
// object. Not a test.
//
// usage: throng-bench-analysis [--agents N] [--frames F]
#include "simcore/analysis/RunAnalysis.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <vector>

using namespace throng;

namespace {

// Walkers on a grid, each crossing the scene east at its own pace, some leaving through
// an exit at x = 200 (out from then on).
void makeRun(std::size_t agents, std::size_t frames, sim::Scene& scene, sim::FrameCache& cache)
{
    constexpr float kFps = 24.0f;
    sim::AgentType walker;
    walker.name = "walker";
    scene.agentTypes = {walker};
    scene.settings.fps = kFps;
    scene.settings.boundsMin = {-10.0f, -110.0f};
    scene.settings.boundsMax = {210.0f, 110.0f};
    scene.goals.push_back({"out", {205.0f, 0.0f}, 100.0f, true});
    for (float x : {40.0f, 80.0f, 120.0f, 160.0f})
        scene.measurements.push_back({"line_" + std::to_string(int(x)), sim::MeasurementShape::Line,
                                      {{x, -100.0f}, {x, 100.0f}}});
    scene.measurements.push_back(
        {"west", sim::MeasurementShape::Area, {{20.0f, -50.0f}, {60.0f, -50.0f}, {60.0f, 50.0f}, {20.0f, 50.0f}}});
    scene.measurements.push_back(
        {"east", sim::MeasurementShape::Area, {{120.0f, -50.0f}, {160.0f, -50.0f}, {160.0f, 50.0f}, {120.0f, 50.0f}}});
    std::vector<sim::AgentInfo> infos;
    for (std::size_t i = 0; i < agents; ++i)
        infos.push_back({static_cast<sim::AgentId>(i + 1), 0});
    cache.reset(infos, kFps);
    const auto side = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(agents))));
    std::vector<sim::AgentFrame> frame(agents);
    for (std::size_t i = 0; i < agents; ++i)
        frame[i].position = {0.5f * static_cast<float>(i % side), 0.0f, -50.0f + 0.5f * static_cast<float>(i / side)};
    for (std::size_t f = 0; f < frames; ++f) {
        for (std::size_t i = 0; i < agents; ++i) {
            sim::AgentFrame& a = frame[i];
            a.speed = 0.8f + 0.1f * static_cast<float>(i % 7);
            if (f > 0 && !a.out) {
                a.position.x += a.speed / kFps;
                a.out = a.position.x > 200.0f;
            }
        }
        cache.append(frame);
    }
}

double seconds(const std::function<void()>& work)
{
    std::vector<double> runs;
    for (int k = 0; k < 3; ++k) {
        const auto start = std::chrono::steady_clock::now();
        work();
        runs.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    std::sort(runs.begin(), runs.end());
    return runs[1];
}

}  // namespace

int main(int argc, char** argv)
{
    std::size_t agents = 10'000, frames = 2'400;
    for (int a = 1; a + 1 < argc; a += 2) {
        if (std::strcmp(argv[a], "--agents") == 0)
            agents = std::strtoull(argv[a + 1], nullptr, 10);
        else if (std::strcmp(argv[a], "--frames") == 0)
            frames = std::strtoull(argv[a + 1], nullptr, 10);
    }
    sim::Scene scene;
    sim::FrameCache cache;
    makeRun(agents, frames, scene, cache);
    sim::RunAnalysis all;
    std::uint64_t crossings = 0;
    const double whole = seconds([&] { all = sim::analyseRun(scene, cache); });
    const double lines = seconds([&] { crossings = sim::countLineCrossings(scene, cache)[0].forward; });
    const double density = seconds([&] { (void)sim::densityMap(scene, cache, 1.0, 0, cache.frameCount()); });
    const double areas = seconds([&] { (void)sim::measureSpeedDensity(scene, cache, 1); });
    const double occupancy = seconds([&] { (void)sim::measureOccupancy(scene, cache); });
    std::printf("{\n  \"agents\": %zu,\n  \"frames\": %zu,\n  \"analysis_s\": %.3f,\n  \"line_crossings_s\": %.3f,\n"
                "  \"density_map_s\": %.3f,\n  \"speed_density_s\": %.3f,\n  \"occupancy_s\": %.3f,\n"
                "  \"crossings_of_first_line\": %llu,\n  \"agents_out\": %u\n}\n",
                agents, frames, whole, lines, density, areas, occupancy, static_cast<unsigned long long>(crossings),
                all.occupancy.out.empty() ? 0u : all.occupancy.out.back());
    return 0;
}
