#include "validation/Rimea.h"

#include "simcore/io/SceneIO.h"
#include "simcore/world/RunStats.h"
#include "simcore/world/World.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace throng::validation {

namespace {

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0)
{
    char buf[160];
    std::snprintf(buf, sizeof buf, pattern, a, b, c);
    return buf;
}

// Whether the step from p to q crosses segment [a, b] (touching counts).
bool crosses(glm::vec2 p, glm::vec2 q, glm::vec2 a, glm::vec2 b)
{
    auto cross = [](glm::vec2 u, glm::vec2 v) { return double(u.x) * v.y - double(u.y) * v.x; };
    const double d1 = cross(b - a, p - a), d2 = cross(b - a, q - a);
    const double d3 = cross(q - p, a - p), d4 = cross(q - p, b - p);
    return ((d1 <= 0 && d2 >= 0) || (d1 >= 0 && d2 <= 0)) && ((d3 <= 0 && d4 >= 0) || (d3 >= 0 && d4 <= 0)) &&
           !(d1 == 0 && d2 == 0);
}

// Steps of any agent across a wall of the scene, counted from the positions alone (not the
// World's own counter).
std::uint64_t wallCrossings(const sim::Scene& scene, std::span<const glm::vec3> before,
                            std::span<const glm::vec3> after)
{
    std::uint64_t n = 0;
    for (std::size_t i = 0; i < before.size() && i < after.size(); ++i) {
        const glm::vec2 p(before[i].x, before[i].z), q(after[i].x, after[i].z);
        if (p == q)
            continue;
        for (const sim::Wall& w : scene.walls)
            for (std::size_t k = 0; k + 1 < w.points.size(); ++k)
                n += crosses(p, q, w.points[k], w.points[k + 1]) ? 1 : 0;
    }
    return n;
}

// Test 1: the time one walker takes for 40 m of corridor, from where it starts to the line
// 40 m on (interpolated within the step that crosses it).
Outcome corridor(const std::vector<sim::Scene>& scenes)
{
    sim::World world(scenes[0]);
    const float startX = world.positions()[0].x, endX = startX + 40.0f;
    double crossedAt = -1.0;
    while (crossedAt < 0.0 && world.timeS() < 120.0) {
        const float x0 = world.positions()[0].x;
        const double t0 = world.timeS();
        world.step();
        const float x1 = world.positions()[0].x;
        if (x1 >= endX)
            crossedAt = t0 + (world.timeS() - t0) * double(endX - x0) / double(x1 - x0);
    }
    Outcome out;
    if (crossedAt < 0.0) {
        out.measured = "did not cover 40 m in 120 s";
        return out;
    }
    out.measured = format("%.2f s", crossedAt);
    out.pass = crossedAt >= 26.0 && crossedAt <= 34.0;
    return out;
}

// Test 6: every walker reaches the corridor's end past the corner, and none crosses a wall
// (counted from the positions, step by step, and by the World's own counter).
Outcome corner(const std::vector<sim::Scene>& scenes)
{
    sim::World world(scenes[0]);
    std::vector<glm::vec3> before;
    std::uint64_t crossings = 0, steps = 0;
    auto arrived = [&] {
        std::size_t n = 0;
        for (std::size_t i = 0; i < world.agentCount(); ++i)
            n += world.hasArrived(i) ? 1 : 0;
        return n;
    };
    while (arrived() < world.agentCount() && world.timeS() < 120.0) {
        before.assign(world.positions().begin(), world.positions().end());
        world.step();
        ++steps;
        crossings += wallCrossings(scenes[0], before, world.positions());
    }
    const sim::RunStats stats = sim::RunStats::from(world, steps + 1, 0.0);
    Outcome out;
    out.measured = format("%.0f of %.0f round the corner in %.1f s", double(arrived()), double(world.agentCount()),
                          world.timeS()) +
                   format(", %.0f steps through a wall (the World counts %.0f)", double(crossings),
                          double(stats.counters.wallPenetrations));
    out.pass = arrived() == world.agentCount() && world.agentCount() == 20 && crossings == 0 &&
               stats.counters.wallPenetrations == 0;
    return out;
}

// The time until every agent of `scene` has left through an exit; < 0 if not within limitS.
double timeToEmpty(const sim::Scene& scene, double limitS, std::size_t& left)
{
    sim::World world(scene);
    auto out = [&] {
        std::size_t n = 0;
        for (std::size_t i = 0; i < world.agentCount(); ++i)
            n += world.isOut(i) ? 1 : 0;
        return n;
    };
    while (out() < world.agentCount() && world.timeS() < limitS)
        world.step();
    left = out();
    return left == world.agentCount() ? world.timeS() : -1.0;
}

// Test 9: 1,000 walkers leave a room by four doors, then by two: the second takes about
// twice as long (a ratio of 1.6 to 2.4).
Outcome fourAgainstTwoExits(const std::vector<sim::Scene>& scenes)
{
    std::size_t leftFour = 0, leftTwo = 0;
    const double four = timeToEmpty(scenes[0], 900.0, leftFour), two = timeToEmpty(scenes[1], 900.0, leftTwo);
    Outcome out;
    if (four < 0.0 || two < 0.0) {
        out.measured = format("not all out within 900 s: %.0f and %.0f of 1000", double(leftFour), double(leftTwo));
        return out;
    }
    const double ratio = two / four;
    out.measured = format("%.1f s with four doors, %.1f s with two: %.2f times as long", four, two, ratio);
    out.pass = leftFour == 1000 && leftTwo == 1000 && ratio >= 1.6 && ratio <= 2.4;
    return out;
}

}  // namespace

const std::vector<RimeaTest>& rimeaTests()
{
    static const std::vector<RimeaTest> tests{
        {1, "Corridor: walking speed kept", "one walker at 1.33 m/s covers 40 m of a 2 m corridor in 26 to 34 s",
         {"rimea-01-corridor.yaml"}, corridor, {}},
        {2, "Stairs up: walking speed kept", "", {}, nullptr, "needs levels and stairs (planned: multi-level scenes)"},
        {3, "Stairs down: walking speed kept", "", {}, nullptr, "needs levels and stairs (planned: multi-level scenes)"},
        {4, "Fundamental diagram", "speed against density along Weidmann's curve", {}, nullptr,
         "planned: measurement areas and the speed-density report (issue 26, analysis)"},
        {5, "Reaction times", "each walker starts at its own reaction time", {}, nullptr,
         "planned: per-walker reaction times"},
        {6, "Corner", "20 walkers round a left corner, none through a wall", {"rimea-06-corner.yaml"}, corner, {}},
        {7, "Walking speed by age", "speeds by age group as the guideline's population", {}, nullptr,
         "planned: age groups as a variation"},
        {8, "Parameter analysis", "", {}, nullptr, "a study of a building's parameters, not a test of the simulator"},
        {9, "Four against two exits", "1,000 walkers empty a room about twice as slowly (1.6 to 2.4 times) "
                                      "through two of its four doors",
         {"rimea-09-four-exits.yaml", "rimea-09-two-exits.yaml"}, fourAgainstTwoExits, {}},
        {10, "Assigned exits", "walkers leave by the exits assigned to them", {}, nullptr, "planned"},
        {11, "Exit choice under congestion", "walkers also use a farther exit when the near one is congested", {},
         nullptr, "planned: exit choice"},
        {12, "Bottleneck", "flow through a bottleneck grows with its width", {}, nullptr, "planned"},
        {13, "Stairs with congestion", "", {}, nullptr, "needs levels and stairs (planned: multi-level scenes)"},
        {14, "Route choice", "", {}, nullptr, "needs levels (planned: multi-level scenes)"},
        {15, "500 round a corner", "a crowd rounds a corner without passing through its walls", {}, nullptr,
         "planned"},
        {16, "Single file", "speed against density in single file", {}, nullptr, "planned"},
    };
    return tests;
}

Outcome runRimeaTest(const RimeaTest& test, const std::string& directory)
{
    Outcome out;
    if (!test.run) {
        out.error = test.notRunBecause;
        return out;
    }
    std::vector<sim::Scene> scenes;
    for (const std::string& file : test.scenes) {
        const std::string path = (std::filesystem::path(directory) / file).string();
        const sim::LoadResult loaded = sim::loadScene(path);
        for (const sim::Diagnostic& d : loaded.diagnostics)
            if (d.severity == sim::Severity::Error) {
                out.error = d.format();
                return out;
            }
        if (!loaded.ok()) {
            out.error = path + ": does not load";
            return out;
        }
        scenes.push_back(loaded.scene);
    }
    return test.run(scenes);
}

}  // namespace throng::validation
