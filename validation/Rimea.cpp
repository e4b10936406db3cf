#include "validation/Rimea.h"
#include "validation/RimeaSpeedDensity.h"

#include "simcore/io/SceneIO.h"
#include "simcore/scene/WalkingAge.h"
#include "simcore/world/RunStats.h"
#include "simcore/world/World.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace throng::validation {

std::string format(const char* pattern, double a, double b, double c)
{
    char buf[160];
    std::snprintf(buf, sizeof buf, pattern, a, b, c);
    return buf;
}

namespace {

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

// A run of `scene` until every agent is done (arrived, or out) or limitS has passed, with
// every step of every agent checked against every wall from the positions alone, besides
// the World's own counter.
struct WatchedRun {
    std::size_t agents = 0, done = 0;
    double timeS = 0.0;
    std::uint64_t crossings = 0, worldCounts = 0;  // steps through a wall: recounted, and the World's
    std::string throughWalls() const
    {
        return format(", %.0f steps through a wall (the World counts %.0f)", double(crossings), double(worldCounts));
    }
};

WatchedRun runWatchingWalls(const sim::Scene& scene, double limitS, bool (sim::World::*isDone)(std::size_t) const)
{
    sim::World world(scene);
    WatchedRun run;
    run.agents = world.agentCount();
    auto done = [&] {
        std::size_t n = 0;
        for (std::size_t i = 0; i < world.agentCount(); ++i)
            n += (world.*isDone)(i) ? 1 : 0;
        return n;
    };
    std::vector<glm::vec3> before;
    std::uint64_t steps = 0;
    while (done() < run.agents && world.timeS() < limitS) {
        before.assign(world.positions().begin(), world.positions().end());
        world.step();
        ++steps;
        run.crossings += wallCrossings(scene, before, world.positions());
    }
    run.done = done();
    run.timeS = world.timeS();
    run.worldCounts = sim::RunStats::from(world, steps + 1, 0.0).counters.wallPenetrations;
    return run;
}

// Test 5: every walker stands until its reaction time, drawn between 10 and 100 s, and sets
// off then. When each one first moves (its position first changes: one that waits stands
// exactly still) is read from the positions; its reaction time is the one the World drew.
Outcome reactionTimes(const std::vector<sim::Scene>& scenes)
{
    sim::World world(scenes[0]);
    const std::size_t n = world.agentCount();
    const std::vector<glm::vec3> start(world.positions().begin(), world.positions().end());
    std::vector<double> movedAt(n, -1.0);
    std::size_t out = 0;
    while (out < n && world.timeS() < 180.0) {
        world.step();
        out = 0;
        for (std::size_t i = 0; i < n; ++i) {
            out += world.isOut(i) ? 1 : 0;
            if (movedAt[i] < 0.0 && world.positions()[i] != start[i])
                movedAt[i] = world.timeS();
        }
    }
    std::size_t onTime = 0;
    double first = INFINITY, last = 0.0, worst = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double due = world.startTimeS(i);
        first = std::min(first, due);
        last = std::max(last, due);
        const double late = movedAt[i] - due;  // < 0: moved before its time (or never)
        worst = std::max(worst, std::abs(late));
        onTime += due >= 10.0 && due <= 100.0 && late >= 0.0 && late <= 0.25 ? 1 : 0;
    }
    Outcome result;
    result.measured = format("%.0f of %.0f set off within 0.25 s after their reaction time", double(onTime),
                             double(n)) +
                      format(" (times %.1f to %.1f s; latest start %.2f s after its time)", first, last, worst) +
                      format("; %.0f out", double(out));
    result.pass = n == 10 && onTime == n && out == n;
    return result;
}

// Test 6: every walker reaches the corridor's end past the corner, and none crosses a wall.
Outcome corner(const std::vector<sim::Scene>& scenes)
{
    const WatchedRun run = runWatchingWalls(scenes[0], 120.0, &sim::World::hasArrived);
    Outcome out;
    out.measured = format("%.0f of %.0f round the corner in %.1f s", double(run.done), double(run.agents), run.timeS) +
                   run.throughWalls();
    out.pass = run.done == run.agents && run.agents == 20 && run.crossings == 0 && run.worldCounts == 0;
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

// Test 7: 50 adults, each of an age drawn between 20 and 80 years, walk at Weidmann's speed
// for their age. Each one's speed is measured from its positions at 5 s and 25 s (after it
// has come up to speed, on a straight way to an exit 1 km off) and set against Weidmann's
// speed for its age; by decade of age (20s, ..., 70s), the mean measured speeds fall.
Outcome walkingSpeedByAge(const std::vector<sim::Scene>& scenes)
{
    sim::World world(scenes[0]);
    const std::size_t n = world.agentCount();
    while (world.timeS() < 5.0 - 1e-9)
        world.step();
    const std::vector<glm::vec3> at5(world.positions().begin(), world.positions().end());
    while (world.timeS() < 25.0 - 1e-9)
        world.step();
    std::size_t within = 0, aged = 0;
    double worst = 0.0;
    std::array<double, 6> sum{}, count{};
    for (std::size_t i = 0; i < n; ++i) {
        const float age = world.ageYears(i);
        const double speed = double(glm::distance(world.positions()[i], at5[i])) / 20.0;
        const double off = std::abs(speed - double(sim::weidmannSpeedAtAge(age)));
        worst = std::max(worst, off);
        within += off <= 0.03 ? 1 : 0;
        aged += age >= 20.0f && age <= 80.0f ? 1 : 0;
        const std::size_t decade = std::min(std::size_t((age - 20.0f) / 10.0f), std::size_t(5));
        sum[decade] += speed;
        count[decade] += 1.0;
    }
    Outcome out;
    out.measured = format("%.0f of %.0f within 0.03 m/s of Weidmann's speed for their age", double(within),
                          double(n)) +
                   format(" (at most %.3f m/s off); mean by decade from the 20s:", worst);
    bool falling = true;
    double last = INFINITY;
    for (std::size_t d = 0; d < sum.size(); ++d) {
        const double mean = count[d] > 0.0 ? sum[d] / count[d] : 0.0;
        out.measured += format(" %.2f", mean) + format(d + 1 < sum.size() ? " (%.0f)," : " (%.0f) m/s", count[d]);
        falling = falling && count[d] > 0.0 && mean < last;
        last = mean;
    }
    out.pass = n == 50 && within == n && aged == n && falling;
    return out;
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

// Where each walker of `world` left: the exit goal nearest its position on the step it went
// out, read from the positions alone (-1: still in). Steps until all are out or limitS;
// with `throughWalls`, counts the steps through a wall of `scene` from the positions too.
std::vector<std::int32_t> exitsTaken(const sim::Scene& scene, sim::World& world, double limitS,
                                     std::uint64_t* throughWalls = nullptr)
{
    const std::size_t n = world.agentCount();
    std::vector<std::int32_t> leftBy(n, -1);
    std::vector<glm::vec3> before;
    std::size_t out = 0;
    while (out < n && world.timeS() < limitS) {
        if (throughWalls)
            before.assign(world.positions().begin(), world.positions().end());
        world.step();
        if (throughWalls)
            *throughWalls += wallCrossings(scene, before, world.positions());
        for (std::size_t i = 0; i < n; ++i) {
            if (leftBy[i] >= 0 || !world.isOut(i))
                continue;
            const glm::vec2 p(world.positions()[i].x, world.positions()[i].z);
            float nearest = INFINITY;
            for (std::size_t g = 0; g < world.goals().size(); ++g) {
                const sim::Goal& goal = world.goals()[g];
                if (goal.exit && glm::distance(p, goal.position) < nearest) {
                    nearest = glm::distance(p, goal.position);
                    leftBy[i] = std::int32_t(g);
                }
            }
            ++out;
        }
    }
    return leftBy;
}

// Test 10: every walker leaves by the exit assigned to it. Where a walker left is the exit
// goal nearest its position on the step it went out, read from the positions alone.
Outcome assignedExits(const std::vector<sim::Scene>& scenes)
{
    sim::World world(scenes[0]);
    const std::size_t n = world.agentCount();
    const std::vector<glm::vec3> start(world.positions().begin(), world.positions().end());
    const std::vector<std::int32_t> leftBy = exitsTaken(scenes[0], world, 200.0);
    const std::size_t out =
        std::size_t(std::count_if(leftBy.begin(), leftBy.end(), [](std::int32_t g) { return g >= 0; }));
    std::size_t own = 0, far = 0;
    for (std::size_t i = 0; i < n; ++i) {
        own += leftBy[i] >= 0 && leftBy[i] == world.goalIndex(i) ? 1 : 0;
        // Assigned the exit farther from where it started: the one it would not take by itself.
        const std::int32_t g = world.goalIndex(i);
        if (g < 0)
            continue;
        const glm::vec2 home(start[i].x, start[i].z);
        for (std::size_t k = 0; k < world.goals().size(); ++k)
            if (world.goals()[k].exit && std::int32_t(k) != g &&
                glm::distance(home, world.goals()[k].position) < glm::distance(home, world.goals()[g].position)) {
                ++far;
                break;
            }
    }
    Outcome result;
    result.measured = format("%.0f of %.0f left by their own exit", double(own), double(n)) +
                      format(" (%.0f of them assigned the farther one); %.0f out after %.1f s", double(far),
                             double(out), world.timeS());
    result.pass = n == 24 && own == n && out == n && far == 16;
    return result;
}

// Test 11: 1,000 walkers choose between a near exit and a far one in the same wall. Those
// for whom the far one is farthest (the quarter nearest the west wall) leave by the near
// one (90 % or more), the congestion there sends others to the far one (100 or more), the
// room empties sooner than when every walker takes the near one, and nobody steps through a
// wall (recounted from the positions).
Outcome exitChoice(const std::vector<sim::Scene>& scenes)
{
    sim::World choosing(scenes[0]);
    // The quarter of the crowd for whom the far exit is the farthest: nearest the west wall.
    std::vector<float> startX;
    for (const glm::vec3& p : choosing.positions())
        startX.push_back(p.x);
    std::vector<float> sorted = startX;
    std::sort(sorted.begin(), sorted.end());
    const float westQuarter = sorted.empty() ? 0.0f : sorted[sorted.size() / 4];
    std::uint64_t throughWalls = 0;
    const std::vector<std::int32_t> leftBy = exitsTaken(scenes[0], choosing, 900.0, &throughWalls);
    const double choiceS = choosing.timeS();
    sim::Scene nearest = scenes[0];
    for (sim::SpawnGroup& g : nearest.groups)
        if (!g.exits.empty()) {
            g.goal = g.exits.front();
            g.exits.clear();
        }
    sim::World allNear(nearest);
    const std::vector<std::int32_t> nearOnly = exitsTaken(nearest, allNear, 1800.0, &throughWalls);
    std::size_t near = 0, far = 0, out = 0, outNear = 0, west = 0, westNear = 0;
    for (std::size_t i = 0; i < leftBy.size(); ++i) {
        near += leftBy[i] == 0 ? 1 : 0;
        far += leftBy[i] == 1 ? 1 : 0;
        if (startX[i] < westQuarter) {
            ++west;
            westNear += leftBy[i] == 0 ? 1 : 0;
        }
    }
    for (const std::int32_t g : nearOnly)
        outNear += g >= 0 ? 1 : 0;
    out = near + far;
    Outcome result;
    result.measured = format("%.0f by the near exit, %.0f by the far one", double(near), double(far)) +
                      format("; of the western quarter, %.0f of %.0f by the near one", double(westNear), double(west)) +
                      format("; all %.0f out after %.1f s (%.1f s when every walker takes the near exit)",
                             double(out), choiceS, allNear.timeS()) +
                      format("; %.0f steps through a wall", double(throughWalls));
    result.pass = leftBy.size() == 1000 && out == leftBy.size() && outNear == nearOnly.size() &&
                  10 * westNear >= 9 * west && far >= 100 && choiceS < allNear.timeS() && throughWalls == 0;
    return result;
}

// One run of test 12's room with its passage `widthM` wide: the walls named neck_* and
// front_* moved to the passage's new sides.
struct BottleneckRun {
    double flow = 0.0;          // persons/s across the passage's end, from the 20th to the 120th
    double frontDensity = 0.0;  // P/m^2 in the 2 m x 4 m in front of the passage, over that time
    double behindDensity = 0.0; // P/m^2 in the 2 m x 4 m behind it
    std::size_t walkers = 0, crossed = 0;
};

BottleneckRun bottleneck(sim::Scene scene, float widthM)
{
    const float h = 0.5f * widthM;
    for (sim::Wall& w : scene.walls) {
        const float side = w.name.ends_with("north") ? -h : h;
        if (w.name.starts_with("neck_"))
            w.points = {{10.0f, side}, {12.0f, side}};
        else if (w.name.starts_with("front_"))
            w.points = {{10.0f, side < 0.0f ? -5.0f : 5.0f}, {10.0f, side}};
    }
    sim::World world(scene);
    const std::size_t n = world.agentCount();
    std::vector<float> x(n);
    for (std::size_t i = 0; i < n; ++i)
        x[i] = world.positions()[i].x;
    std::vector<std::uint8_t> through(n, 0);  // crossed the passage's end: each walker counts once
    std::vector<double> crossings;
    struct Densities {
        double timeS, front, behind;  // P/m^2
    };
    std::vector<Densities> density;  // per step
    auto in = [](glm::vec3 p, float x0) { return p.x >= x0 && p.x < x0 + 2.0f && std::abs(p.z) < 2.0f; };
    while (crossings.size() < n && world.timeS() < 600.0) {
        world.step();
        std::size_t front = 0, behind = 0;
        for (std::size_t i = 0; i < n; ++i) {
            const glm::vec3 p = world.positions()[i];
            if (x[i] < 12.0f && p.x >= 12.0f && !through[i]) {
                through[i] = 1;
                crossings.push_back(world.timeS());
            }
            x[i] = p.x;
            if (!world.isOut(i)) {
                front += in(p, 8.0f) ? 1 : 0;
                behind += in(p, 12.0f) ? 1 : 0;
            }
        }
        density.push_back({world.timeS(), double(front) / 8.0, double(behind) / 8.0});
    }
    BottleneckRun run;
    run.walkers = n;
    run.crossed = crossings.size();
    if (crossings.size() < 120)
        return run;
    const double t0 = crossings[19], t1 = crossings[119];
    run.flow = 100.0 / (t1 - t0);
    double front = 0.0, behind = 0.0, steps = 0.0;
    for (const Densities& d : density)
        if (d.timeS > t0 && d.timeS <= t1) {
            front += d.front;
            behind += d.behind;
            steps += 1.0;
        }
    run.frontDensity = front / steps;
    run.behindDensity = behind / steps;
    return run;
}

// Test 12: the flow through a passage grows with its width; a queue forms in front of it and
// none behind it (the density behind stays under half that in front).
Outcome bottleneckWidths(const std::vector<sim::Scene>& scenes)
{
    Outcome out;
    out.pass = true;
    double lastFlow = 0.0;
    for (const float w : {0.8f, 1.0f, 1.2f, 1.6f, 2.0f, 2.4f}) {
        const BottleneckRun r = bottleneck(scenes[0], w);
        out.measured += (out.measured.empty() ? "" : "; ") +
                        format("%.1f m: %.2f /s (%.2f /m/s)", double(w), r.flow, r.flow / double(w)) +
                        format(", %.1f /m2 in front and %.1f behind", r.frontDensity, r.behindDensity) +
                        (r.crossed < r.walkers
                             ? format(", only %.0f of %.0f through in 600 s", double(r.crossed), double(r.walkers))
                             : "");
        out.pass = out.pass && r.walkers == 150 && r.crossed == r.walkers && r.flow > lastFlow &&
                   r.frontDensity >= 2.0 && r.behindDensity < 0.5 * r.frontDensity;
        lastFlow = r.flow;
    }
    return out;
}

// Test 15: 500 walkers round a corner and leave by the corridor's far end, none through a wall.
Outcome largeCrowdCorner(const std::vector<sim::Scene>& scenes)
{
    const WatchedRun run = runWatchingWalls(scenes[0], 300.0, &sim::World::isOut);
    Outcome out;
    out.measured = format("%.0f of %.0f out in %.1f s", double(run.done), double(run.agents), run.timeS) +
                   run.throughWalls();
    out.pass = run.done == run.agents && run.agents == 500 && run.crossings == 0 && run.worldCounts == 0;
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
        {4, "Fundamental diagram", "walkers filling a corridor 5 m wide at 0.5, 1, 2, 3, 4 and 5 persons/m2 walk, "
                                   "in its middle, within 0.15 m/s of Weidmann's speed at the density measured "
                                   "there, slower the denser",
         {"rimea-04-fundamental-diagram.yaml"}, fundamentalDiagram, {}},
        {5, "Reaction times", "10 walkers in a room each stand for a reaction time drawn between 10 and 100 s, "
                              "set off within 0.25 s after it, and leave by the door",
         {"rimea-05-reaction-times.yaml"}, reactionTimes, {}},
        {6, "Corner", "20 walkers round a left corner, none through a wall", {"rimea-06-corner.yaml"}, corner, {}},
        {7, "Walking speed by age", "50 adults aged 20 to 80 each walk within 0.03 m/s of Weidmann's speed for "
                                    "their age, and the mean speed of each decade of age is below the last's",
         {"rimea-07-walking-speed-by-age.yaml"}, walkingSpeedByAge, {}},
        {8, "Parameter analysis", "", {}, nullptr, "a study of a building's parameters, not a test of the simulator"},
        {9, "Four against two exits", "1,000 walkers empty a room about twice as slowly (1.6 to 2.4 times) "
                                      "through two of its four doors",
         {"rimea-09-four-exits.yaml", "rimea-09-two-exits.yaml"}, fourAgainstTwoExits, {}},
        {10, "Assigned exits", "24 walkers in 12 rooms off a corridor each leave by the exit assigned to them, "
                               "16 of them by the farther of the two",
         {"rimea-10-assigned-exits.yaml"}, assignedExits, {}},
        {11, "Exit choice under congestion", "1,000 walkers choose between two exits in one wall: of the quarter "
                                             "farthest from the far exit 90 % or more leave by the near one, at "
                                             "least 100 walkers by the far one, the room empties sooner than "
                                             "when all take the near one, and none steps through a wall",
         {"rimea-11-exit-choice.yaml"}, exitChoice, {}},
        {12, "Bottleneck", "150 walkers leave a room by a passage 2 m long and 0.8 to 2.4 m wide: the flow grows "
                           "with the width, a queue forms in front (2 /m2 or more) and none behind (under half that)",
         {"rimea-12-bottleneck.yaml"}, bottleneckWidths, {}},
        {13, "Stairs with congestion", "", {}, nullptr, "needs levels and stairs (planned: multi-level scenes)"},
        {14, "Route choice", "", {}, nullptr, "needs levels (planned: multi-level scenes)"},
        {15, "500 round a corner", "500 walkers round a left corner of a corridor 6 m wide and all leave by its "
                                   "end, none through a wall",
         {"rimea-15-large-crowd-corner.yaml"}, largeCrowdCorner, {}},
        {16, "Single file", "walkers round a ring corridor 0.8 m wide at 0.5, 1, 1.5 and 2 per metre walk, on "
                            "a straight, within 0.1 m/s of the speed Seyfried et al.'s single-file relation "
                            "gives at the density measured there, slower the denser",
         {"rimea-16-single-file.yaml"}, singleFile, {}},
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
