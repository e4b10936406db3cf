// Sketched-field build on a busy painted plaza: STROKES strokes of 100 m (four 25 m
// segments each, bending by up to 30 degrees) over a 200 x 200 m plaza with a wall round
// it and 40 pillars, baked onto its 0.5 m navigation grid (160,000 cells), as the World
// builds it. Prints one JSON object: the median build time of RUNS builds (samples, solve
// and bake) and the process's peak resident memory.
// Usage: throng-bench-sketch [STROKES=300] [RUNS=3]
#include "simcore/nav/SketchField.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

using namespace throng::sim;

namespace {

Scene plaza(int strokes)
{
    Scene s;
    s.settings.boundsMin = {0.0f, 0.0f};
    s.settings.boundsMax = {200.0f, 200.0f};
    s.walls.push_back({"rim", {{1, 1}, {199, 1}, {199, 199}, {1, 199}, {1, 1}}});
    std::mt19937 gen(7);
    std::uniform_real_distribution<float> u(20.0f, 180.0f), angle(0.0f, 360.0f), bend(-30.0f, 30.0f);
    for (int k = 0; k < 40; ++k)
        s.obstacles.push_back({"pillar", ObstacleShape::Circle, {u(gen), u(gen)}, 1.0f, {1, 1}, 0.0f});
    for (int k = 0; k < strokes; ++k) {
        FlowStroke f;
        glm::vec2 p(u(gen), u(gen));
        float a = angle(gen);
        f.points.push_back(p);
        for (int seg = 0; seg < 4; ++seg) {
            p += 25.0f * glm::vec2(std::cos(glm::radians(a)), std::sin(glm::radians(a)));
            p = glm::clamp(p, glm::vec2(3.0f), glm::vec2(197.0f));  // turn back at the rim
            f.points.push_back(p);
            a += bend(gen);
        }
        s.flowStrokes.push_back(f);
    }
    return s;
}

}  // namespace

int main(int argc, char** argv)
{
    const int strokes = argc > 1 ? std::atoi(argv[1]) : 300;
    const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 3;
    const Scene s = plaza(strokes);
    NavGrid grid;
    grid.build(s, {0.5f, 0.3f});
    std::vector<double> ms;
    SketchField field;
    for (int r = 0; r < runs; ++r) {
        const auto t = std::chrono::steady_clock::now();
        if (!field.build(s, grid)) {
            std::fprintf(stderr, "%s\n", field.error().c_str());
            return 1;
        }
        ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count());
    }
    std::sort(ms.begin(), ms.end());
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    std::printf("{\"strokes\": %d, \"stroke_samples\": %zu, \"boundary_samples\": %zu, \"patches\": %zu, "
                "\"bake_cells\": %d, \"runs\": %d, \"build_ms_median\": %.1f, \"build_ms_min\": %.1f, "
                "\"build_ms_max\": %.1f, \"peak_rss_mb\": %.1f}\n",
                strokes, field.strokeSampleCount(), field.boundarySampleCount(), field.patchCount(), grid.cellCount(), runs,
                ms[ms.size() / 2], ms.front(), ms.back(), double(usage.ru_maxrss) / 1024.0);
    return 0;
}
