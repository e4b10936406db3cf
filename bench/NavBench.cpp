// Navigation figures: A* plans per second on a 200 x 200 grid with obstacles, flow-field
// build time for 500 x 500 cells, and sketched-field (RBF) solve time for 50/100/200
// stroke samples. Prints one JSON object; each figure is the median of a few runs.
// Usage: throng-bench-nav [RUNS]
#include "simcore/nav/AStar.h"
#include "simcore/nav/FlowField.h"
#include "simcore/nav/SketchField.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

using namespace throng::sim;

namespace {

double msSince(std::chrono::steady_clock::time_point t)
{
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t).count();
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

// A field of cones and a few long walls over sizeM x sizeM metres.
Scene obstacleField(float sizeM, int cones, int walls, unsigned seed)
{
    Scene s;
    s.settings.boundsMin = {0.0f, 0.0f};
    s.settings.boundsMax = {sizeM, sizeM};
    std::mt19937 gen(seed);
    std::uniform_real_distribution<float> u(0.0f, sizeM), r(0.3f, 1.5f), len(-0.3f * sizeM, 0.3f * sizeM);
    for (int k = 0; k < cones; ++k)
        s.obstacles.push_back({"cone", ObstacleShape::Circle, {u(gen), u(gen)}, r(gen), {1, 1}, 0.0f});
    for (int k = 0; k < walls; ++k) {
        const glm::vec2 a(u(gen), u(gen));
        s.walls.push_back({"wall", {a, a + glm::vec2(len(gen), 0.0f), a + glm::vec2(len(gen), len(gen) * 0.5f)}});
    }
    return s;
}

}  // namespace

int main(int argc, char** argv)
{
    const int runs = argc > 1 ? std::max(1, std::stoi(argv[1])) : 5;

    // A*: 200 x 200 cells of 0.5 m, 400 cones and 12 walls, 500 random walkable pairs.
    const Scene astarScene = obstacleField(100.0f, 400, 12, 7);
    NavGrid grid;
    grid.build(astarScene, {0.5f, 0.3f});
    std::mt19937 gen(11);
    std::uniform_int_distribution<int> ux(0, grid.cols() - 1), uz(0, grid.rows() - 1);
    std::vector<std::pair<NavCell, NavCell>> pairs;
    while (pairs.size() < 500) {
        const NavCell a{ux(gen), uz(gen)}, b{ux(gen), uz(gen)};
        if (grid.walkable(a) && grid.walkable(b))
            pairs.push_back({a, b});
    }
    AStar astar;
    std::vector<double> plansPerS;
    long expanded = 0, found = 0, corners = 0;
    for (int r = 0; r < runs; ++r) {
        expanded = found = corners = 0;
        const auto t = std::chrono::steady_clock::now();
        for (const auto& [a, b] : pairs) {
            const NavPlan p = astar.plan(grid, a, b);
            expanded += astar.expandedLast();
            found += p.found() ? 1 : 0;
            corners += long(p.waypoints.size());
        }
        plansPerS.push_back(double(pairs.size()) / (msSince(t) / 1000.0));
    }
    int blocked = 0;
    for (int i = 0; i < grid.cellCount(); ++i)
        blocked += grid.walkableIndex(i) ? 0 : 1;

    // Flow field: 500 x 500 cells of 0.5 m, 1500 cones and 30 walls, three exits.
    const Scene flowScene = obstacleField(250.0f, 1500, 30, 9);
    std::vector<double> gridMs, flowMs;
    NavGrid flowGrid;
    FlowField field;
    const FlowGoal exits[3] = {{{2.0f, 125.0f}, 2.0f}, {{248.0f, 60.0f}, 2.0f}, {{125.0f, 248.0f}, 3.0f}};
    for (int r = 0; r < runs; ++r) {
        auto t = std::chrono::steady_clock::now();
        flowGrid.build(flowScene, {0.5f, 0.3f});
        gridMs.push_back(msSince(t));
        t = std::chrono::steady_clock::now();
        field.build(flowGrid, exits);
        flowMs.push_back(msSince(t));
    }

    // Sketched field: a corridor hall 60 x 40 m, strokes resampled to N samples, boundary
    // samples from the walls near them; bake onto a 120 x 80 grid of 0.5 m.
    std::string rbf;
    for (int n : {50, 100, 200}) {
        Scene s;
        s.settings.boundsMin = {0.0f, 0.0f};
        s.settings.boundsMax = {60.0f, 40.0f};
        s.walls.push_back({"hall", {{1, 1}, {59, 1}, {59, 39}, {1, 39}, {1, 1}}});
        s.obstacles.push_back({"pillar", ObstacleShape::Circle, {30, 20}, 2.0f, {1, 1}, 0.0f});
        s.flowStrokes.push_back({{{5, 8}, {30, 6}, {55, 12}, {50, 32}, {10, 34}}, 2.0f});
        SketchParams params;
        float length = 0.0f;
        for (std::size_t k = 1; k < s.flowStrokes[0].points.size(); ++k)
            length += glm::distance(s.flowStrokes[0].points[k - 1], s.flowStrokes[0].points[k]);
        params.sampleSpacingM = length / float(n) * 1.0001f;
        params.boundarySpacingM = 2.0f;
        params.wallReachM = 8.0f;
        const auto strokes = strokeSamples(s.flowStrokes, params.sampleSpacingM);
        const auto boundary = boundarySamples(navShapes(s), params.boundarySpacingM, strokes, params.wallReachM);
        NavGrid hall;
        hall.build(s, {0.5f, 0.3f});
        SketchField sketch;
        std::vector<double> solveMs, bakeMs;
        for (int r = 0; r < runs; ++r) {
            auto t = std::chrono::steady_clock::now();
            if (!sketch.solve(strokes, boundary, params)) {
                std::fprintf(stderr, "%s\n", sketch.error().c_str());
                return 1;
            }
            solveMs.push_back(msSince(t));
            t = std::chrono::steady_clock::now();
            sketch.bake(hall);
            bakeMs.push_back(msSince(t));
        }
        char line[320];
        std::snprintf(line, sizeof line,
                      "%s\n    {\"stroke_samples\": %zu, \"boundary_samples\": %zu, \"unknowns\": %zu, \"solve_ms\": %.2f, "
                      "\"bake_ms\": %.2f, \"bake_cells\": %d}",
                      rbf.empty() ? "" : ",", strokes.size(), boundary.size(), 2 * strokes.size() + boundary.size(),
                      median(solveMs), median(bakeMs), hall.cellCount());
        rbf += line;
    }

    std::printf("{\n  \"runs\": %d,\n", runs);
    std::printf("  \"astar\": {\"cols\": %d, \"rows\": %d, \"blocked_cells\": %d, \"plans\": %zu, \"found\": %ld, "
                "\"plans_per_second\": %.0f, \"expanded_per_plan\": %.0f, \"waypoints_per_plan\": %.1f},\n",
                grid.cols(), grid.rows(), blocked, pairs.size(), found, median(plansPerS),
                double(expanded) / double(pairs.size()), double(corners) / double(std::max(found, 1L)));
    std::printf("  \"flow_field\": {\"cols\": %d, \"rows\": %d, \"exits\": 3, \"grid_build_ms\": %.2f, \"build_ms\": %.2f, "
                "\"settled_cells\": %d},\n",
                flowGrid.cols(), flowGrid.rows(), median(gridMs), median(flowMs), field.settledCells());
    std::printf("  \"sketch_field\": [%s\n  ]\n}\n", rbf.c_str());
    return 0;
}
