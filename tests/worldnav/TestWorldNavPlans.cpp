// Walkers that navigate by A*: they find the way round a U-shaped wall that direct seek
// cannot leave, a group starting in one cell shares one plan yet turns at different
// points, a walker held back at a door plans again through the other door, and the
// result is the same for 1 and 2 threads.
#include "NavRig.h"
#include "TestRegistry.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <algorithm>

using namespace throng::sim;
using throng::test::parse;
using throng::test::runUntil;

namespace {

// A walker inside a U open to the west, its goal east of the U's closed side.
std::string uWallScene(const char* navigation)
{
    return std::string(R"(throng: 1
settings: {fps: 24, bounds: {min: [-20, -20], max: [20, 20]}}
agent_types:
  - {name: walker, navigation: )") + navigation + R"(, behaviours: {arrival: 1, separation: 1}}
walls:
  - {points: [[-8, -3], [0, -3], [0, 3], [-8, 3]]}
goals:
  - {name: beyond, position: [6, 0], radius: 1}
agents:
  - {type: walker, position: [-3, 0], goal: beyond}
)";
}

}  // namespace

class TestWorldNavPlans : public QObject {
    Q_OBJECT
private slots:
    void aStarLeavesTheUThatDirectSeekCannot()
    {
        World direct(parse(uWallScene("direct")));
        runUntil(direct, 60.0, [](const World& w) { return w.hasArrived(0); });
        QVERIFY(!direct.hasArrived(0));
        const glm::vec3 stuck = direct.positions()[0];
        QVERIFY2(glm::distance(glm::vec2(stuck.x, stuck.z), glm::vec2(6, 0)) > 5.0f, "direct seek stays in the U");

        World planned(parse(uWallScene("astar")));
        QVERIFY(planned.navigation().active);
        runUntil(planned, 60.0, [](const World& w) { return w.hasArrived(0); });
        QVERIFY(planned.hasArrived(0));
        // Round the arm (about 3 + 8 + 3 + 3 + 6 m) at 1.4 m/s or less: well within 30 s.
        QVERIFY2(planned.arrivalTimeS(0) < 30.0f, qPrintable(QString::number(planned.arrivalTimeS(0))));
        QCOMPARE(planned.counters().wallPenetrations, std::uint64_t(0));
    }

    void aGroupSharesOnePlanAndTurnsAtDifferentPoints()
    {
        // Ten walkers in one 0.5 m cell; a box between them and the goal makes a corner.
        std::string yaml = R"(throng: 1
settings: {fps: 24, bounds: {min: [-20, -20], max: [20, 20]}}
agent_types:
  - {name: walker, radius: 0.2, navigation: astar, behaviours: {arrival: 1, separation: 1}}
obstacles:
  - {shape: box, center: [5, 0], size: [2, 8]}
goals:
  - {name: far, position: [12, 0], radius: 2}
agents:
)";
        for (int k = 0; k < 10; ++k)
            yaml += "  - {type: walker, position: [" + std::to_string(0.04 + 0.04 * k) + ", 0.25], goal: far}\n";
        World world(parse(yaml));
        const PlanCache& cache = world.navigation().cache;
        QCOMPARE(cache.misses(), std::size_t(1));
        QCOMPARE(cache.hits(), std::size_t(9));
        const NavPlan& plan = *world.navigation().plan[0];
        QVERIFY(plan.found());
        QVERIFY2(plan.waypoints.size() >= 2, "the box makes at least one corner");
        const glm::vec2 corner = plan.waypoints[0];

        // Where each walker turned for the next waypoint: its distance from the corner.
        std::vector<float> turnedAt(10, -1.0f);
        runUntil(world, 40.0, [&](const World& w) {
            for (std::size_t i = 0; i < 10; ++i)
                if (turnedAt[i] < 0.0f && w.navigation().waypoint[i] > 0)
                    turnedAt[i] = glm::distance(glm::vec2(w.positions()[i].x, w.positions()[i].z), corner);
            return throng::test::arrivedCount(w) == 10;
        });
        QCOMPARE(throng::test::arrivedCount(world), std::size_t(10));
        const auto [lo, hi] = std::minmax_element(turnedAt.begin(), turnedAt.end());
        QVERIFY(*lo >= 0.0f);
        // Each walker's own radius is 0.5..1.5 m: they do not all turn on one line.
        QVERIFY2(*hi - *lo > 0.2f, qPrintable(QString("turned %1..%2 m from the corner").arg(*lo).arg(*hi)));
        QCOMPARE(world.counters().wallPenetrations, std::uint64_t(0));
    }

    void aWalkerHeldAtOneDoorReplansThroughTheOther()
    {
        // Two doors in a wall across the set; a hero standing in the near door pushes
        // everyone out of 1.5 m, which the grid does not know about.
        const Scene scene = parse(R"(throng: 1
settings: {fps: 24, bounds: {min: [-15, -15], max: [15, 15]}}
agent_types:
  - {name: walker, navigation: astar, behaviours: {arrival: 1, separation: 1}}
  - {name: guard, radius: 0.4}
walls:
  - {points: [[0, -15], [0, -1]]}
  - {points: [[0, 1], [0, 6]]}
  - {points: [[0, 8], [0, 15]]}
goals:
  - {name: across, position: [5, 0], radius: 1}
agents:
  - {id: 1, type: walker, position: [-5, 0], goal: across}
heroes:
  - name: doorman
    id: 2
    type: guard
    clearance: 1.5
    keyframes: [{time: 0, position: [0, 0, 0]}, {time: 100, position: [0, 0, 0]}]
)");
        World world(scene);
        // The first plan goes through the near door, 2 m from the straight line.
        const NavPlan& first = *world.navigation().plan[0];
        float farthest = 0.0f;
        for (glm::vec2 w : first.waypoints)
            farthest = std::max(farthest, std::fabs(w.y));
        QVERIFY2(farthest < 2.0f, "the first plan takes the near door");
        runUntil(world, 90.0, [](const World& w) { return w.hasArrived(0); });
        QVERIFY(world.hasArrived(0));
        QVERIFY(world.navigation().counters.replans >= 1);
        QCOMPARE(world.counters().wallPenetrations, std::uint64_t(0));
    }

    void flowFollowersRideTheSketchedStroke()
    {
        // One stroke east along z = 0; the walker starts beside it facing north.
        World world(parse(R"(throng: 1
settings: {fps: 24, bounds: {min: [-20, -20], max: [20, 20]}}
agent_types:
  - {name: walker, behaviours: {flow_field_following: 1}}
flow_strokes:
  - {points: [[-15, 0], [-5, 0], [15, 0]], width: 2}
agents:
  - {type: walker, position: [-10, 0.5], heading: 90}
)"));
        QVERIFY(world.navigation().sketch.has_value());
        for (int s = 0; s < 240; ++s)
            world.step();
        const glm::vec3 p = world.positions()[0], v = world.velocities()[0];
        QVERIFY2(p.x > -4.0f, qPrintable(QString("x %1 after 10 s").arg(p.x)));
        QVERIFY2(std::fabs(p.z) < 2.0f, qPrintable(QString("z %1").arg(p.z)));
        QVERIFY(glm::length(v) > 0.5f);
        QVERIFY2(v.x / glm::length(v) > 0.94f, "heading east along the stroke (within 20 degrees)");
    }

    void sameFramesForOneAndTwoThreads()
    {
        std::string yaml = R"(throng: 1
settings: {fps: 24, bounds: {min: [-20, -20], max: [20, 20]}}
agent_types:
  - {name: planner, navigation: astar, behaviours: {arrival: 1, separation: 1}}
  - {name: follower, navigation: flow_field, behaviours: {arrival: 1, separation: 1}}
walls:
  - {points: [[-8, -3], [0, -3], [0, 3], [-8, 3]]}
goals:
  - {name: beyond, position: [6, 0], radius: 1}
  - {name: door, position: [10, -10], radius: 1.5, exit: true}
groups:
  - {name: a, type: planner, count: 40, rect: {min: [-7, -2], max: [-1, 2]}, goal: beyond}
  - {name: b, type: follower, count: 60, rect: {min: [-15, 5], max: [-5, 15]}, goal: door}
)";
        auto hashFor = [&](int threads) {
            World world(parse(yaml), WorldOptions{0, false, threads});
            FrameCache cache;
            world.startRecording(cache);
            std::vector<AgentFrame> frame;
            for (int s = 0; s < 480; ++s) {
                world.step();
                world.snapshot(frame);
                cache.append(frame);
            }
            return cache.hash();
        };
        QCOMPARE(hashFor(1), hashFor(2));
    }
};

THRONG_REGISTER_TEST(TestWorldNavPlans)
#include "TestWorldNavPlans.moc"
