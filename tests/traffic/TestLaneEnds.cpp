// What happens at a lane's end: on a looping lane vehicles go round and round without a
// jump or a collision across the seam; on an open lane they leave, wait off stage for a
// random while, and come back at the start only when there is room.
#include "TestRegistry.h"

#include "simcore/traffic/TrafficSystem.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <algorithm>
#include <cmath>

using namespace throng::sim;

namespace {
Scene laneScene(std::vector<glm::vec2> points, bool loop, int cars, float spacingM)
{
    Scene scene;
    scene.settings.seed = 5;
    AgentType car;
    car.name = "car";
    car.kind = AgentKind::Vehicle;
    car.radiusM = 1.1f;
    car.maxSpeed = 13.9f;
    scene.agentTypes.push_back(car);
    scene.lanes.push_back({"road", std::move(points), 3.5f, 13.9f, loop});
    for (int k = 0; k < cars; ++k)
        scene.vehicles.push_back({std::uint32_t(k + 1), "car", "road", float(k) * spacingM, float(k % 4) * 3.0f});
    return scene;
}
}  // namespace

class TestLaneEnds : public QObject {
    Q_OBJECT
private slots:
    void loopingLaneGoesRoundWithoutJumpsOrCollisions()
    {
        // A closed 40 m square, 160 m round, with ten cars.
        const Scene scene = laneScene({{0, 0}, {40, 0}, {40, 40}, {0, 40}, {0, 0}}, true, 10, 16.0f);
        TrafficSystem t(scene);
        const float len = t.lanes().length(0);
        std::vector<double> travelled(10, 0.0);
        float minGap = 1e9f, maxJump = 0.0f;
        while (t.timeS() < 600.0) {
            std::vector<glm::vec2> before(10);
            std::vector<float> s0(10);
            for (std::size_t i = 0; i < 10; ++i) {
                before[i] = t.position(i);
                s0[i] = t.s(i);
            }
            t.step({});
            for (std::size_t i = 0; i < 10; ++i) {
                QVERIFY(t.s(i) >= 0.0f && t.s(i) < len);
                float ds = t.s(i) - s0[i];
                if (ds < 0.0f)
                    ds += len;  // went over the seam
                travelled[i] += double(ds);
                // Never further than the arc it drove: no jump at the seam.
                maxJump = std::max(maxJump, glm::distance(before[i], t.position(i)) - ds);
            }
            std::vector<std::size_t> order(10);
            for (std::size_t i = 0; i < 10; ++i)
                order[i] = i;
            std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return t.s(a) < t.s(b); });
            for (std::size_t k = 0; k < 10; ++k) {
                const std::size_t a = order[k], b = order[(k + 1) % 10];
                float d = t.s(b) - t.s(a);
                if (d <= 0.0f)
                    d += len;
                minGap = std::min(minGap, d - t.radius(a) - t.radius(b));
            }
        }
        const auto [lo, hi] = std::minmax_element(travelled.begin(), travelled.end());
        qInfo("10 cars, 10 min on a 160 m loop: %.1f to %.1f laps each, smallest bumper gap %.2f m", *lo / double(len),
              *hi / double(len), double(minGap));
        QVERIFY(maxJump < 1e-3f);
        QVERIFY(*lo / double(len) > 10.0);
        QVERIFY2(minGap > 1.0f, "followers keep their gap across the seam");
        QCOMPARE(t.counters().vehicleCollisions, std::uint64_t(0));
        QCOMPARE(t.counters().nonFiniteValues, std::uint64_t(0));
    }

    void aLoneCarOnALoopReachesTheSpeedLimit()
    {
        const Scene scene = laneScene({{0, 0}, {200, 0}, {200, 200}, {0, 200}, {0, 0}}, true, 1, 0.0f);
        TrafficSystem t(scene);
        while (t.timeS() < 60.0)
            t.step({});
        QVERIFY(t.speed(0) > 13.5f && t.speed(0) <= 13.9f);
    }

    void openLaneVehiclesLeaveAndComeBackWithRoom()
    {
        // A 120 m open lane, five cars; off-stage waits 0.5 to 6 s.
        const Scene scene = laneScene({{0, 0}, {120, 0}}, false, 5, 20.0f);
        TrafficSystem t(scene);
        std::vector<double> leftAt(5, -1.0);
        std::size_t mostOffStage = 0;
        double shortestWait = 1e9;
        while (t.timeS() < 300.0) {
            std::vector<bool> wasActive(5);
            for (std::size_t i = 0; i < 5; ++i)
                wasActive[i] = t.active(i);
            t.step({});
            std::size_t off = 0;
            for (std::size_t i = 0; i < 5; ++i) {
                off += t.active(i) ? 0 : 1;
                if (wasActive[i] && !t.active(i))
                    leftAt[i] = t.timeS();
                if (!wasActive[i] && t.active(i)) {
                    QVERIFY2(t.s(i) == 0.0f, "re-enters at the lane's start");
                    shortestWait = std::min(shortestWait, t.timeS() - leftAt[i]);
                    for (std::size_t j = 0; j < 5; ++j)
                        if (j != i && t.active(j))
                            QVERIFY2(t.s(j) - t.radius(j) - t.radius(i) >= 2.0f, "enters only with room ahead");
                }
            }
            mostOffStage = std::max(mostOffStage, off);
        }
        std::uint32_t fewest = ~0u;
        for (std::size_t i = 0; i < 5; ++i)
            fewest = std::min(fewest, t.respawns(i));
        qInfo("5 cars, 5 min on a 120 m open lane: each re-entered at least %u times; shortest off-stage wait %.2f s, "
              "up to %zu off stage at once",
              fewest, shortestWait, mostOffStage);
        QVERIFY(fewest >= 10);
        QVERIFY(shortestWait >= 0.5 - 1e-6);
        QVERIFY(mostOffStage >= 1);
        QCOMPARE(t.counters().vehicleCollisions, std::uint64_t(0));
    }
};

THRONG_REGISTER_TEST(TestLaneEnds)
#include "TestLaneEnds.moc"
