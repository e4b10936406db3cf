// Crowd behaviour as a user of a crowd library checks it, on the failures reported most
// against DetourCrowd, RVO2, Menge and Godot's avoidance: head-on deadlock and dithering,
// agents pushed through walls, arrived agents shoved about or never settling, jams that
// never dissolve, path followers cutting corners.
#include "CrowdChecks.h"
#include "TestRegistry.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <string>

using namespace throng::sim;
using namespace throng::test::crowd;

namespace {

constexpr int kFps = 24;

// Agent 1 walks 3 m to a 0.3 m goal at the origin; crossers then walk over it northward.
const char* kPostScene = R"(throng: 1
agent_types:
  - {name: walker, radius: 0.3, max_speed: 1.4, max_force: 3}
goals:
  - {name: post, position: [0, 0], radius: 0.3}
  - {name: north, position: [0, -14], radius: 4}
agents:
  - {id: 1, type: walker, position: [-3, 0], heading: 0, goal: post}
)";
// At up to 1.68 m/s from 16 m away: no crosser is near the origin before 9 s.
const char* kCrossersLate =
    "groups: [{name: crossers, type: walker, count: 30, rect: {min: [-1.5, 16], max: [1.5, 22]}, goal: north}]\n";
// From 7 m away: the first arrive around 4 s, as agent 1 settles.
const char* kCrossersEarly =
    "groups: [{name: crossers, type: walker, count: 30, rect: {min: [-1.5, 7], max: [1.5, 13]}, goal: north}]\n";

// Sign changes of x, ignoring values within the dead band (noise, not a swerve).
struct SignChanges {
    float deadBand;
    int last = 0, changes = 0;
    void add(float x)
    {
        const int s = x > deadBand ? 1 : (x < -deadBand ? -1 : 0);
        if (s != 0 && last != 0 && s != last)
            ++changes;
        if (s != 0)
            last = s;
    }
};

}  // namespace

class TestCrowdBehaviour : public QObject {
    Q_OBJECT
private slots:
    void headOnPairPassesWithoutOverlapOrDithering()
    {
        // Same line, opposite goals: RVO2 and DetourCrowd users report the pair stopping
        // nose to nose or dancing left-right ("reciprocal dance").
        const Scene s = parse(R"(throng: 1
agent_types:
  - {name: walker, radius: 0.3, max_speed: 1.4, max_force: 3, variation: {speed: [1, 1]}}
goals:
  - {name: east, position: [10, 0], radius: 0.5}
  - {name: west, position: [-10, 0], radius: 0.5}
agents:
  - {id: 1, type: walker, position: [-10, 0], heading: 0, goal: east}
  - {id: 2, type: walker, position: [10, 0], heading: 180, goal: west}
)");
        World world(s, kSerial);
        float minGap = INFINITY;
        SignChanges lateral[2] = {{0.05f}, {0.05f}};
        for (int step = 0; step < kFps * 30 && !(world.hasArrived(0) && world.hasArrived(1)); ++step) {
            world.step();
            minGap = std::min(minGap, glm::distance(xz(world.positions()[0]), xz(world.positions()[1])) -
                                          (world.radii()[0] + world.radii()[1]));
            for (int a = 0; a < 2; ++a)
                if (!world.hasArrived(std::size_t(a)))
                    lateral[a].add(world.velocities()[std::size_t(a)].z);
        }
        qInfo("head-on: arrival %.2f s / %.2f s, min gap %.3f m, lateral sign changes %d / %d",
              double(world.arrivalTimeS(0)), double(world.arrivalTimeS(1)), double(minGap), lateral[0].changes,
              lateral[1].changes);
        // 19.5 m to the goal's edge at 1.4 m/s is 13.9 s; reaching top speed (3 N on 1 kg)
        // costs 0.25 s and a 0.6 m side-step over ~6 m adds about 0.1 m. 18 s leaves 4 s for
        // braking against the oncoming agent; more means they stalled nose to nose.
        for (std::size_t a = 0; a < 2; ++a) {
            QVERIFY2(world.hasArrived(a), qPrintable(QString("agent %1 never arrived").arg(world.id(a))));
            QVERIFY2(world.arrivalTimeS(a) < 18.0f,
                     qPrintable(QString("agent %1 took %2 s").arg(world.id(a)).arg(world.arrivalTimeS(a))));
        }
        QVERIFY2(minGap > -0.05f, qPrintable(QString("bodies overlapped by %1 m").arg(-minGap)));
        // One swerve out and one back is a single sign change; two allows settling.
        QVERIFY2(lateral[0].changes <= 2 && lateral[1].changes <= 2,
                 qPrintable(QString("lateral velocity changed sign %1 and %2 times")
                                .arg(lateral[0].changes).arg(lateral[1].changes)));
    }

    void squeezedAgentNeverCrossesTheWall_data()
    {
        QTest::addColumn<float>("gapM");
        QTest::newRow("wide gap 0.9 m") << 0.9f;
        QTest::newRow("exact gap 0.6 m") << 0.6f;
        QTest::newRow("narrow gap 0.4 m") << 0.4f;
    }

    void squeezedAgentNeverCrossesTheWall()
    {
        // A wall along z = -1 and a block of agents standing (no goal) `gap` above it;
        // walkers whose goal hugs the wall must pass through the gap or wait, and the
        // collision pass must never shove anyone through the wall.
        QFETCH(float, gapM);
        std::string yaml = R"(throng: 1
agent_types:
  - {name: walker, radius: 0.3, max_speed: 1.4, max_force: 3}
goals:
  - {name: east, position: [10, -0.6], radius: 1}
walls:
  - {points: [[-15, -1], [15, -1]]}
agents:
  - {id: 1, type: walker, position: [-8, -0.6], heading: 0, goal: east}
  - {id: 2, type: walker, position: [-9, -0.3], heading: 0, goal: east}
  - {id: 3, type: walker, position: [-10, -0.6], heading: 0, goal: east}
  - {id: 4, type: walker, position: [-11, 0], heading: 0, goal: east}
)";
        const float zFirstRow = -1.0f + gapM + 0.3f;
        for (int row = 0; row < 4; ++row)
            for (int col = 0; col < 7; ++col)
                yaml += "  - {type: walker, position: [" + std::to_string(-2.0f + 0.65f * float(col)) + ", " +
                        std::to_string(zFirstRow + 0.65f * float(row)) + "]}\n";
        const Scene s = parse(yaml);
        const std::vector<WallSegment2> walls = wallSegments(s);
        World world(s, kSerial);
        std::size_t crossings = 0;
        float deepest = INFINITY;  // least centre-to-wall distance seen, any agent
        for (int step = 0; step < kFps * 40; ++step) {
            const std::vector<glm::vec3> before = copyPositions(world);
            world.step();
            crossings += wallCrossings(before, world, walls);
            for (std::size_t i = 0; i < world.agentCount(); ++i)
                deepest = std::min(deepest, world.positions()[i].z + 1.0f);
        }
        // Through: past the standing block's far edge (x = 1.9 + 0.3).
        int through = 0;
        for (std::size_t i = 0; i < 4; ++i)
            through += world.positions()[i].x > 2.2f;
        qInfo("gap %.2f m: %d of 4 walkers through, least centre-wall distance %.4f m, crossings %zu / %llu",
              double(gapM), through, double(deepest), crossings,
              static_cast<unsigned long long>(world.counters().wallPenetrations));
        QCOMPARE(crossings, std::size_t(0));
        QCOMPARE(world.counters().wallPenetrations, 0u);
        // On the walkers' side, and no body sunk into the wall by more than 1 mm.
        QVERIFY2(deepest > 0.3f - 1e-3f, qPrintable(QString("a body reached %1 m from the wall line").arg(deepest)));
        // A gap as wide as a body lets them through; a narrower one may hold them back.
        if (gapM >= 0.6f)
            QVERIFY2(through == 4, qPrintable(QString("only %1 of 4 walkers got through a %2 m gap").arg(through).arg(gapM)));
    }

    void arrivedAgentStaysPutWhileACrowdPasses()
    {
        // Agent 1 stops on a small goal at the origin; then 30 walkers cross straight over
        // it. Users of DetourCrowd and Godot report arrived agents being shoved away.
        World world(parse(std::string(kPostScene) + kCrossersLate), kSerial);
        float stopTimeS = -1.0f, firstContactS = -1.0f, maxDrift = 0.0f, nearestCrosser = INFINITY;
        glm::vec3 stopPos(0.0f);
        for (int step = 0; step < kFps * 30; ++step) {
            world.step();
            const glm::vec3 p = world.positions()[0];
            if (stopTimeS < 0.0f && world.hasArrived(0) && glm::length(world.velocities()[0]) == 0.0f) {
                stopTimeS = float(world.timeS());
                stopPos = p;
            }
            for (std::size_t i = 1; i < world.agentCount(); ++i) {
                const float d = glm::distance(xz(world.positions()[i]), xz(p));
                nearestCrosser = std::min(nearestCrosser, d);
                if (firstContactS < 0.0f && d < 0.7f)
                    firstContactS = float(world.timeS());
            }
            if (stopTimeS >= 0.0f)
                maxDrift = std::max(maxDrift, glm::distance(p, stopPos));
        }
        std::size_t crossed = 0;
        for (std::size_t i = 1; i < world.agentCount(); ++i)
            crossed += world.hasArrived(i);
        qInfo("stay put: stopped at %.2f s, first crosser within 0.7 m at %.2f s, drift %.5f m, nearest crosser "
              "%.3f m, %zu of 30 crossed",
              double(stopTimeS), double(firstContactS), double(maxDrift), double(nearestCrosser), crossed);
        QVERIFY2(stopTimeS >= 0.0f, "agent 1 never stopped");
        // The crowd really came past after it stopped: someone brushed it (contact at 0.6 m).
        QVERIFY2(firstContactS > stopTimeS, qPrintable(QString("the crowd reached it at %1 s, before it stopped at %2 s")
                                                           .arg(firstContactS).arg(stopTimeS)));
        QVERIFY2(maxDrift <= 1e-3f, qPrintable(QString("the arrived agent was moved %1 m").arg(maxDrift)));
        // And it did not wall the crossing off.
        QVERIFY2(crossed >= 27, qPrintable(QString("only %1 of 30 crossers arrived in 30 s").arg(crossed)));
    }

    void arrivedAgentIsNotShovedOutOfItsGoal()
    {
        // The same crossing, timed to reach agent 1 just after it has entered its goal
        // (hasArrived) and while it is still settling onto its own spot in it.
        World world(parse(std::string(kPostScene) + kCrossersEarly), kSerial);
        float arrivedS = -1.0f, stopS = -1.0f, farthest = 0.0f;
        for (int step = 0; step < kFps * 30; ++step) {
            world.step();
            if (!world.hasArrived(0))
                continue;
            if (arrivedS < 0.0f)
                arrivedS = float(world.timeS());
            if (stopS < 0.0f && glm::length(world.velocities()[0]) == 0.0f)
                stopS = float(world.timeS());
            farthest = std::max(farthest, glm::length(xz(world.positions()[0])));
        }
        qInfo("shove: arrived at %.2f s, stopped at %.2f s, farthest from the goal after arriving %.3f m",
              double(arrivedS), double(stopS), double(farthest));
        QVERIFY2(arrivedS >= 0.0f && arrivedS < 5.0f, "agent 1 did not arrive before the crowd came");
        // An agent reported as arrived is inside its goal (radius 0.3 m).
        QVERIFY2(farthest <= 0.3f + 0.01f,
                 qPrintable(QString("an arrived agent was pushed %1 m from its goal (radius 0.3 m)").arg(farthest)));
    }

    void agentsSharingAGoalAllSettle()
    {
        // 12 walkers for a 2 m goal: their bodies cover 3.4 of its 12.6 square metres, so
        // every one has room to stop. Agents that never settle but jitter on the spot are a
        // common DetourCrowd and RVO2 complaint.
        World world(parse(R"(throng: 1
settings: {fps: 24, seed: 2}
agent_types:
  - {name: walker, radius: 0.3, max_speed: 1.4, max_force: 3}
goals:
  - {name: plaza, position: [0, 0], radius: 2}
groups:
  - {name: visitors, type: walker, count: 12, rect: {min: [-14, -4], max: [-8, 4]}, goal: plaza}
)"), kSerial);
        std::vector<glm::vec3> at40;
        std::vector<float> walkedLate(world.agentCount(), 0.0f);
        float lateSpeed = 0.0f;
        for (int step = 0; step < kFps * 60; ++step) {
            const std::vector<glm::vec3> before = copyPositions(world);
            world.step();
            if (world.timeS() > 40.0)
                for (std::size_t i = 0; i < world.agentCount(); ++i) {
                    lateSpeed = std::max(lateSpeed, glm::length(world.velocities()[i]));
                    walkedLate[i] += glm::distance(before[i], world.positions()[i]);
                }
            if (step == kFps * 40 - 1)
                at40 = copyPositions(world);
        }
        std::size_t arrived = 0, stopped = 0;
        float lateDrift = 0.0f;
        for (std::size_t i = 0; i < world.agentCount(); ++i) {
            arrived += world.hasArrived(i);
            stopped += glm::length(world.velocities()[i]) == 0.0f;
            lateDrift = std::max(lateDrift, glm::distance(at40[i], world.positions()[i]));
        }
        const float walked = *std::max_element(walkedLate.begin(), walkedLate.end());
        qInfo("settle: %zu arrived, %zu stopped at 60 s; in the last 20 s max speed %.3f m/s, net drift %.3f m, "
              "distance walked %.3f m",
              arrived, stopped, double(lateSpeed), double(lateDrift), double(walked));
        QCOMPARE(arrived, std::size_t(12));
        // 14 m at 1.4 m/s is 10 s; from 40 s on everyone has had 30 s to settle, so nobody
        // should walk more than a few centimetres, back and forth or not.
        QVERIFY2(walked <= 0.05f, qPrintable(QString("an arrived agent walked %1 m on the spot in the last 20 s "
                                                     "(net %2 m)").arg(walked).arg(lateDrift)));
        QVERIFY2(stopped == 12, qPrintable(QString("only %1 of 12 stopped in 60 s; the rest still move at up to %2 m/s")
                                               .arg(stopped).arg(lateSpeed)));
    }

    void agentsCrowdingASmallGoalAllSettle()
    {
        // 16 walkers that keep their distance (the crossroads' walkers: separation 1.5 with
        // its 0.5 m range) for a 1.5 m goal, which their bodies alone would fill to 64 %.
        // Those that cannot reach their spots must stop at the pile; with bodies that no
        // longer press through each other (issue 23), separation held the late-comers at
        // arm's length from it and they walked on the spot for good: 14 arrived and 5
        // stopped in 60 s. Now the pile is joined within the personal space separation
        // keeps (a queue back along the way they came, up to 5 m from the goal's centre),
        // and a walker held to a crawl inside its goal stops there.
        for (const int seed : {1, 2, 3}) {
            World world(parse(R"(throng: 1
settings: {fps: 24, seed: )" + std::to_string(seed) + R"(}
agent_types:
  - {name: walker, radius: 0.3, max_speed: 1.4, max_force: 3, behaviours: {arrival: 1, separation: 1.5}}
goals:
  - {name: corner, position: [0, 0], radius: 1.5}
groups:
  - {name: visitors, type: walker, count: 16, rect: {min: [-14, -1], max: [-12, 1]}, goal: corner}
)"), kSerial);
            for (int step = 0; step < kFps * 60; ++step)
                world.step();
            std::size_t arrived = 0, stopped = 0;
            float farthest = 0.0f;
            for (std::size_t i = 0; i < world.agentCount(); ++i) {
                arrived += world.hasArrived(i);
                stopped += glm::length(world.velocities()[i]) == 0.0f;
                farthest = std::max(farthest, glm::length(world.positions()[i]));
            }
            qInfo("small goal, seed %d: %zu arrived, %zu stopped at 60 s, the farthest %.2f m from its centre", seed,
                  arrived, stopped, double(farthest));
            QCOMPARE(arrived, std::size_t(16));
            QCOMPARE(stopped, std::size_t(16));
        }
    }

    void denseCounterflowJamDissolves()
    {
        // 1,000 agents in a 20 m x 20 m square (2.5 per square metre, bodies covering 71 %
        // of it), half bound for an exit 15 m east of the square and half for one 15 m west:
        // everyone starts inside the opposite stream. The exits are wide (20 m) so the
        // figures measure the jam, not queueing at the exits.
        World world(parse(R"(throng: 1
settings: {fps: 24, seed: 11, bounds: {min: [-70, -40], max: [70, 40]}}
agent_types:
  - {name: walker, radius: 0.3, max_speed: 1.4, max_force: 3}
goals:
  - {name: east, position: [45, 0], radius: 20}
  - {name: west, position: [-45, 0], radius: 20}
groups:
  - {name: eastbound, type: walker, count: 500, rect: {min: [-10, -10], max: [10, 10]}, goal: east}
  - {name: westbound, type: walker, count: 500, rect: {min: [-10, -10], max: [10, 10]}, goal: west}
)"), kSerial);
        QCOMPARE(world.agentCount(), std::size_t(1000));
        const int totalSteps = kFps * 100, window = kFps * 5;
        std::uint64_t overlapsBeforeWindow = 0, overlapsAt40 = 0;
        for (int step = 0; step < totalSteps; ++step) {
            world.step();
            if (step == kFps * 40 - 1)
                overlapsAt40 = world.counters().overlappingPairs;
            if (step == totalSteps - window - 1)
                overlapsBeforeWindow = world.counters().overlappingPairs;
        }
        std::size_t arrived = 0;
        for (std::size_t i = 0; i < world.agentCount(); ++i)
            arrived += world.hasArrived(i);
        const double fraction = double(arrived) / 1000.0;
        const double early = double(overlapsAt40) / (kFps * 40);
        const double late = double(world.counters().overlappingPairs - overlapsBeforeWindow) / window;
        qInfo("jam: %.3f arrived in 100 s; overlapping pairs per step %.1f over the first 40 s, %.1f over the last 5 s",
              fraction, early, late);
        // Measured (seed 11): 0.923 arrived by 100 s (walking freely, 15 to 35 m at 1.1 to
        // 1.7 m/s, takes 9 to 31 s; the last ones are walking round the settled pile at the
        // exit's edge toward their own spots), overlapping pairs per step 63 over the first
        // 40 s and 3 over the last 5 s. Bounds: a jam that does not dissolve fails both.
        QVERIFY2(fraction >= 0.9, qPrintable(QString("only %1 of the crowd arrived in 100 s").arg(fraction)));
        QVERIFY2(late < 10.0, qPrintable(QString("%1 overlapping pairs per step after the jam").arg(late)));
        QCOMPARE(world.counters().nonFiniteValues, 0u);
    }

    void pathFollowersStayInsideAZigZagPath()
    {
        // 50 walkers on a 1.5 m-radius path whose zig-zag legs turn by 90 degrees.
        const Scene s = parse(R"(throng: 1
settings: {fps: 24, seed: 3, bounds: {min: [-60, -20], max: [130, 20]}}
agent_types:
  - {name: walker, radius: 0.3, max_speed: 1.4, max_force: 3}
paths:
  - name: zigzag
    radius: 1.5
    points: [[-45, 0], [-20, 0], [-15, 5], [-10, 0], [-5, 5], [0, 0], [5, 5], [10, 0], [15, 5], [20, 0], [120, 0]]
groups:
  - {name: crowd, type: walker, count: 50, rect: {min: [-40, -1], max: [-24, 1]}, path: zigzag}
)");
        const std::vector<glm::vec2> spine = s.paths[0].points;
        World world(s, kSerial);
        std::size_t inside = 0, total = 0;
        float worst = 0.0f;
        // 85 s: the last walker (0.8 x 1.4 m/s, 77 m to go) has left the zig-zag, and the
        // first (1.2 x) has not reached the end, where 50 bodies could not fit inside the radius.
        for (int step = 0; step < kFps * 85; ++step) {
            world.step();
            for (std::size_t i = 0; i < world.agentCount(); ++i) {
                const float d = distanceToPolyline(xz(world.positions()[i]), spine);
                worst = std::max(worst, d);
                inside += d <= 1.5f;
                ++total;
            }
        }
        float minX = INFINITY, maxX = -INFINITY;
        for (std::size_t i = 0; i < world.agentCount(); ++i) {
            minX = std::min(minX, world.positions()[i].x);
            maxX = std::max(maxX, world.positions()[i].x);
        }
        const double fraction = double(inside) / double(total);
        qInfo("zig-zag: %.4f of %zu agent-steps inside, worst %.3f m from the spine, crowd x %.1f..%.1f", fraction,
              total, double(worst), double(minX), double(maxX));
        QVERIFY2(minX > 20.0f, qPrintable(QString("the crowd has not cleared the zig-zag (last at x = %1)").arg(minX)));
        QVERIFY2(fraction >= 0.99, qPrintable(QString("inside the path radius on only %1 of agent-steps").arg(fraction)));
    }
};

THRONG_REGISTER_TEST(TestCrowdBehaviour)
#include "TestCrowdBehaviour.moc"
