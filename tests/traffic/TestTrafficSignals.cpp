// Signals as a driver and a walker meet them: a queue forms at red and leaves on green
// one car after another; on yellow a car that can stop stops and one that cannot goes,
// counted only if it crossed on red; walkers get the right answer for each colour; cars
// wait for a walker on the crosswalk.
#include "TestRegistry.h"

#include "TrafficHarness.h"
#include "simcore/traffic/TrafficSystem.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace throng::sim;

namespace {
// One straight open lane from (0, 0) east, a stop line `lineAt` m along it.
Scene straightRoad(float length, float lineAt, TrafficLight light, std::vector<std::pair<float, float>> cars)
{
    Scene scene;
    AgentType car;
    car.name = "car";
    car.kind = AgentKind::Vehicle;
    car.radiusM = 1.1f;
    car.maxSpeed = 13.9f;
    scene.agentTypes.push_back(car);
    scene.lanes.push_back({"main", {{0, 0}, {length, 0}}, 3.5f, 13.9f, false});
    light.stopLines = {{"main", lineAt, ""}};
    scene.trafficLights.push_back(light);
    std::uint32_t id = 1;
    for (auto [at, speed] : cars)
        scene.vehicles.push_back({id++, "car", "main", at, speed});
    return scene;
}

TrafficOptions noReturn()
{
    TrafficOptions opt;
    opt.respawnDelayMinS = opt.respawnDelayMaxS = 1e6f;  // cars that leave stay gone
    return opt;
}

void runUntil(TrafficSystem& t, double timeS)
{
    while (t.timeS() < timeS - 1e-9)
        t.step({});
}
}  // namespace

class TestTrafficSignals : public QObject {
    Q_OBJECT
private slots:
    void queueFormsAtRedAndLeavesOneByOneOnGreen()
    {
        // Red for the first 40 s (the cycle starts 23 s in), then 20 s of green.
        const TrafficLight light{"signal", 20, 3, 40, 23, {}, {}};
        const Scene scene = straightRoad(300, 150, light, {{75, 8}, {60, 8}, {45, 8}, {30, 8}, {15, 8}, {0, 8}});
        TrafficSystem t(scene, noReturn());
        QCOMPARE(t.lightPhase(0), LightPhase::Red);
        runUntil(t, 39.9);
        // The queue: everyone standing, first car at the line, bumper gaps near the IDM's 2 m.
        QCOMPARE(t.lightPhase(0), LightPhase::Red);
        const float front0 = t.s(0) + t.radius(0);
        qInfo("queue at red: first front %.2f m before the line", 150.0 - front0);
        QVERIFY(front0 <= 150.0f && front0 >= 150.0f - 1.5f);
        for (std::size_t i = 0; i < 6; ++i) {
            QVERIFY2(t.speed(i) < 0.05f, "every car of the queue stands");
            if (i > 0) {
                const float gap = t.s(i - 1) - t.radius(i - 1) - t.s(i) - t.radius(i);
                QVERIFY2(gap > 1.0f && gap < 3.5f, "a compact queue with a safe gap");
            }
        }
        // Green at t = 40: each car moves off at its own moment, front to back.
        std::vector<double> start(6, -1.0);
        while (t.timeS() < 60.0) {
            t.step({});
            for (std::size_t i = 0; i < 6; ++i)
                if (start[i] < 0.0 && t.speed(i) > 0.3f)
                    start[i] = t.timeS();
        }
        std::vector<double> gaps;
        for (std::size_t i = 0; i < 6; ++i) {
            QVERIFY2(start[i] > 0.0, "every car of the queue left");
            if (i > 0) {
                QVERIFY2(start[i] > start[i - 1] + 0.25, "a follower moves off after its leader, not with it");
                gaps.push_back(start[i] - start[i - 1]);
            }
        }
        qInfo("start after green %.2f s; start intervals %.2f %.2f %.2f %.2f %.2f s", start[0] - 40.0, gaps[0], gaps[1],
              gaps[2], gaps[3], gaps[4]);
        QVERIFY(start[0] - 40.0 >= 0.3 && start[0] - 40.0 <= 1.5 + 2.0 * double(t.dt()));
        const auto [lo, hi] = std::minmax_element(gaps.begin(), gaps.end());
        QVERIFY2(*hi - *lo > 0.1, "staggered starts, not one line");
        QCOMPARE(t.throughput()[0].crossings, std::uint64_t(6));  // the queue dissolved within one green
        QCOMPARE(t.counters().vehicleRedLightViolations, std::uint64_t(0));
        QCOMPARE(t.counters().vehicleCollisions, std::uint64_t(0));
    }

    void yellowStopsThoseWhoCanAndLetsTheOthersGo()
    {
        // Green until 2 s, yellow until 5 s, then red. At 2 s car A is 15 m from the line
        // at 50 km/h (stopping would need 6.4 m/s^2), car B 60 m away (1.6 m/s^2).
        const TrafficLight light{"signal", 2, 3, 40, 0, {}, {}};
        const float line = 200.0f, v = 13.9f;
        const Scene scene = straightRoad(400, line, light, {{line - 15 - 2 * v - 1.1f, v}, {line - 60 - 2 * v - 1.1f, v}});
        TrafficSystem t(scene, noReturn());
        double crossedA = -1.0;
        while (t.timeS() < 40.0) {
            t.step({});
            if (crossedA < 0.0 && t.s(0) + t.radius(0) >= line)
                crossedA = t.timeS();
            QVERIFY2(t.s(1) + t.radius(1) < line, "car B stops before the line");
        }
        qInfo("car A crossed at %.2f s (yellow ends at 5 s); car B waits %.2f m before the line", crossedA,
              double(line - t.s(1) - t.radius(1)));
        QVERIFY(crossedA > 2.0 && crossedA < 5.0);
        QCOMPARE(t.speed(1), 0.0f);
        QCOMPARE(t.counters().vehicleRedLightViolations, std::uint64_t(0));
        QCOMPARE(t.throughput()[0].crossings, std::uint64_t(1));
    }

    void aCarThatCannotStopOnAShortYellowIsCountedWhenItCrossesOnRed()
    {
        // The same car A, but yellow lasts 0.5 s: it cannot stop, goes on and crosses ~1.1 s
        // after the yellow began, on red: one violation.
        const TrafficLight light{"signal", 2, 0.5f, 40, 0, {}, {}};
        const float line = 200.0f, v = 13.9f;
        const Scene scene = straightRoad(400, line, light, {{line - 15 - 2 * v - 1.1f, v}});
        TrafficSystem t(scene, noReturn());
        runUntil(t, 10.0);
        QVERIFY(t.s(0) + t.radius(0) > line);
        QCOMPARE(t.counters().vehicleRedLightViolations, std::uint64_t(1));
    }

    void pedestrianAnswerForEachColour()
    {
        throng::test::CrossingSetup setup;
        setup.carsPerLane = 0;
        const Scene scene = throng::test::crossingScene(setup);
        TrafficSystem t(scene);
        // The north crosswalk runs from (-5.5, -6) to (5.5, -6) under light "ew": green
        // [0, 20), yellow [20, 23), red [23, 50) s. A walker waits west of it, heading east.
        const glm::vec2 kerb{-7.0f, -6.2f}, east{1, 0};
        runUntil(t, 10.0);
        PedestrianSignal sig = t.pedestrianSignal(kerb, east, 0.0f, 0.3f, 1);
        QCOMPARE(scene.crosswalks[std::size_t(sig.crosswalk)].name, std::string("north"));
        QCOMPARE(sig.phase, LightPhase::Green);
        QVERIFY2(!sig.mustStop, "green, long after any reaction delay: walk");
        // Measured to the kerb line (x = -3.5, the southbound lane's edge; 2 cm nearer for
        // the road part's sampling), not to the strip's end at x = -5.5 on the pavement.
        QVERIFY(std::abs(sig.distanceToLineM - 3.48f) < 1e-3f);

        runUntil(t, 21.0);
        sig = t.pedestrianSignal(kerb, east, 0.0f, 0.3f, 1);
        QCOMPARE(sig.phase, LightPhase::Yellow);
        QVERIFY2(sig.mustStop, "yellow: a standing walker does not start");
        // 0.3 m before the kerb line (the strip's end lies 2 m further back on the pavement).
        sig = t.pedestrianSignal({-3.8f, -6.2f}, east, 1.4f, 0.3f, 1);
        QVERIFY2(!sig.mustStop, "yellow: a walker at the kerb edge at full pace goes on");

        runUntil(t, 30.0);
        sig = t.pedestrianSignal(kerb, east, 1.3f, 0.3f, 1);
        QCOMPARE(sig.phase, LightPhase::Red);
        QVERIFY(sig.mustStop);
        // The line is the kerb (x = -3.5, sampled 2 cm out), not the strip's end.
        QVERIFY2(glm::distance(sig.stopPoint, glm::vec2(-3.92f, -6.2f)) < 1e-3f,
                 "waits a body radius and 0.1 m before the line, on its own side offset");
        sig = t.pedestrianSignal({7.5f, -6.2f}, -east, 1.3f, 0.3f, 2);  // from the other end
        QVERIFY(sig.mustStop);
        QVERIFY(glm::distance(sig.stopPoint, glm::vec2(3.92f, -6.2f)) < 1e-3f);
        // Pushed about by the crowd while it waits: nudged sideways or back, never over the line.
        {
            std::mt19937 gen(2);
            std::uniform_real_distribution<float> push(-0.15f, 0.15f);
            const PedestrianSignal waiting = t.pedestrianSignal(kerb, east, 0.0f, 0.3f, 1);
            glm::vec2 p = waiting.stopPoint;
            float sideways = 0.0f;
            for (int k = 0; k < 2000; ++k) {
                const PedestrianSignal here = t.pedestrianSignal(p, east, 0.0f, 0.3f, 1);
                // The crowd leans toward the road; the walker keeps near its own spot sideways.
                const glm::vec2 to = p + glm::vec2(push(gen) + 0.05f, push(gen) - 0.2f * (p.y - waiting.stopPoint.y));
                const glm::vec2 held = holdBehindStopLine(here, to);
                QVERIFY2(held.x <= waiting.stopPoint.x + 1e-5f, "never past the stop point");
                QVERIFY(held.y == to.y);  // sideways part of the push kept
                sideways = std::max(sideways, std::abs(held.y - p.y));
                p = held;
            }
            QVERIFY(sideways > 0.1f);
        }
        sig = t.pedestrianSignal({0.0f, -6.0f}, east, 1.3f, 0.3f, 1);
        QVERIFY2(sig.onCrosswalk && !sig.mustStop, "on the crosswalk at red: keep going");
        sig = t.pedestrianSignal(kerb, -east, 1.3f, 0.3f, 1);
        QCOMPARE(sig.crosswalk, -1);  // walking away from it: no crosswalk to stop at

        // Next green at 50 s: each walker steps off after its own delay in [0, 2] s.
        runUntil(t, 49.99);
        std::vector<double> go(100, -1.0);
        while (t.timeS() < 53.0) {
            t.step({});
            for (std::uint32_t id = 0; id < 100; ++id)
                if (go[id] < 0.0 && !t.pedestrianSignal(kerb, east, 0.0f, 0.3f, id + 1).mustStop)
                    go[id] = t.timeS() - 50.0;
        }
        const auto [lo, hi] = std::minmax_element(go.begin(), go.end());
        qInfo("walkers step off %.2f to %.2f s after green", *lo, *hi);
        QVERIFY(*lo >= 0.0 && *hi <= 2.0 + double(t.dt()));
        QVERIFY2(*hi - *lo > 1.5, "reaction delays are spread, not one line");
    }

    void walkersWaitForAVehicleOnTheCrosswalk()
    {
        throng::test::CrossingSetup setup;
        setup.carsPerLane = 0;
        Scene scene = throng::test::crossingScene(setup);
        // A car standing on the north crosswalk (the southbound lane covers it at s 92.5..95.5).
        scene.vehicles.push_back({1, "car", "southbound", 94.0f, 0.0f});
        TrafficSystem t(scene);
        runUntil(t, 0.2);  // walkers' green
        PedestrianSignal sig = t.pedestrianSignal({-7.0f, -6.2f}, {1, 0}, 0.0f, 0.3f, 1);
        QVERIFY(t.s(0) < 95.5f + 2.2f);  // still on the strip: it moves off after its reaction delay
        QCOMPARE(sig.phase, LightPhase::Green);
        QVERIFY(sig.vehicleCrossing && sig.mustStop);
        // Past its stop line, the car drives off the strip; then the walker may go.
        runUntil(t, 15.0);
        sig = t.pedestrianSignal({-7.0f, -6.2f}, {1, 0}, 0.0f, 0.3f, 1);
        QVERIFY(t.s(0) > 95.5f + 2.2f);
        QVERIFY(!sig.vehicleCrossing && !sig.mustStop);
    }

    void carsYieldToAWalkerOnTheCrosswalk()
    {
        // A walker stands on the west crosswalk in the eastbound lane while the cars have
        // green; the car stops before the strip and goes once the walker has left.
        throng::test::CrossingSetup setup;
        setup.carsPerLane = 0;
        Scene scene = throng::test::crossingScene(setup);
        scene.vehicles.push_back({1, "car", "eastbound", 40.0f, 10.0f});
        TrafficOptions opt;
        opt.respawnDelayMinS = opt.respawnDelayMaxS = 1e6f;
        TrafficSystem t(scene, opt);
        std::vector<PedestrianView> walker{{{-6.0f, 1.5f}, {0, 0}, 0.3f}};
        float minDistance = 1e9f;
        while (t.timeS() < 15.0) {
            t.step(walker);
            t.observePedestrians(walker, walker);
            minDistance = std::min(minDistance, glm::distance(t.position(0), walker[0].position));
        }
        const float front = t.s(0) + t.radius(0);
        qInfo("car waits with its front %.2f m before the crosswalk (closest %.2f m to the walker)", 92.5 - front,
              double(minDistance));
        QCOMPARE(t.speed(0), 0.0f);
        QVERIFY(front < 92.5f && front > 92.5f - 2.0f);
        QCOMPARE(t.counters().carPedestrianCollisions, std::uint64_t(0));
        // The walker leaves (off the strip, north side); the car drives on.
        const std::vector<PedestrianView> gone{{{-6.0f, -9.0f}, {0, 0}, 0.3f}};
        while (t.timeS() < 19.5)
            t.step(gone);
        QVERIFY2(t.s(0) + t.radius(0) > 95.5f, "the car drove on over the crosswalk");
        QCOMPARE(t.counters().vehicleRedLightViolations, std::uint64_t(0));
    }

    void contactCountersSeeContacts()
    {
        // The zero counts above mean something only if a contact is counted when it
        // happens: a walker stands in the lane 8 m ahead of a car at 50 km/h (it needs
        // 12 m to stop), and two cars on crossing lanes meet in the junction.
        throng::test::CrossingSetup setup;
        setup.carsPerLane = 0;
        Scene scene = throng::test::crossingScene(setup);
        scene.vehicles.push_back({1, "car", "eastbound", 60.0f, 13.9f});
        scene.vehicles.push_back({2, "car", "southbound", 101.75f, 0.0f});  // at (-1.75, 1.75)
        scene.vehicles.push_back({3, "car", "eastbound", 98.25f, 0.0f});    // at (-1.75, 1.75) too
        TrafficSystem t(scene);
        const std::vector<PedestrianView> walker{{{-40.0f + 1.1f + 8.0f + 0.3f, 1.75f}, {0, 0}, 0.3f}};
        t.step(walker);
        t.observePedestrians(walker, walker);
        QVERIFY2(t.counters().vehicleCollisions > 0, "two cars in one place are counted");
        while (t.timeS() < 3.0) {
            t.step(walker);
            t.observePedestrians(walker, walker);
        }
        qInfo("car-walker contact steps: %llu", (unsigned long long)t.counters().carPedestrianCollisions);
        QVERIFY2(t.counters().carPedestrianCollisions > 0, "a car that cannot stop for a walker is counted");
    }
};

THRONG_REGISTER_TEST(TestTrafficSignals)
#include "TestTrafficSignals.moc"
