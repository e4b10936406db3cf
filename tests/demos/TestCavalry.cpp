// The cavalry demo, reduced to 300 riders over the same cone field and the whole (A*-planned) route:
// no rider passes through a cone, the leader is never overtaken and the riders keep up.
#include "DemoRuns.h"
#include "TestRegistry.h"

#include <QTest>

#include <algorithm>
#include <vector>

using namespace throng::sim;
using namespace throng::test::demos;

namespace {

Scene reducedCavalry()
{
    Scene s = demo("cavalry.yaml");
    s.groups.at(0).count = 300;
    s.groups.at(0).min = {-40.0f, -20.0f};
    s.groups.at(0).max = {-10.0f, 20.0f};
    return s;
}

}  // namespace

class TestCavalry : public QObject {
    Q_OBJECT
private slots:
    void ridersChaseTheLeaderToTheEndOfItsRoute()
    {
        const Scene scene = reducedCavalry();
        QVERIFY(scene.obstacles.size() > 500);
        World world(scene, threads(2));
        QCOMPARE(world.agentCount(), std::size_t(301));
        QVERIFY(world.id(0) == 1);  // the leader
        while (!world.hasArrived(0) && world.timeS() < scene.settings.durationS)
            world.step();
        // The leader reaches the end of its planned route (473 m at up to 8.4 m/s: about
        // 56 s), not held up.
        QVERIFY2(world.hasArrived(0) && world.arrivalTimeS(0) < 59.0f,
                 qPrintable(QString::number(world.arrivalTimeS(0))));
        QCOMPARE(world.counters().obstaclePenetrations, std::uint64_t(0));
        QCOMPARE(world.counters().wallPenetrations, std::uint64_t(0));
        QCOMPARE(world.counters().leaderOvertaken, std::uint64_t(0));
        QCOMPARE(world.counters().nonFiniteValues, std::uint64_t(0));
        // They chased: riders are 0.9 to 1.0 times as fast as the leader, so they string out
        // behind it (half of them within about 50 m when it arrives), but none is lost or
        // stuck among the cones, and once it has stopped they all close up within seconds.
        const glm::vec2 leader = ground(world.positions()[0]);
        float farthest = 0.0f;
        std::size_t near = 0;
        for (std::size_t i = 1; i < world.agentCount(); ++i) {
            const float d = glm::distance(ground(world.positions()[i]), leader);
            farthest = std::max(farthest, d);
            near += d < 50.0f;
        }
        while (world.timeS() < world.arrivalTimeS(0) + 5.0)
            world.step();
        std::size_t closedUp = 0;
        for (std::size_t i = 1; i < world.agentCount(); ++i)
            closedUp += glm::distance(ground(world.positions()[i]), ground(world.positions()[0])) < 60.0f;
        qInfo("300 riders, full route: leader arrived at %.1f s, obstacle penetrations %llu, leader overtaken %llu, "
              "%zu riders within 50 m and the last %.1f m behind at its arrival, %zu within 60 m 5 s later",
              double(world.arrivalTimeS(0)), static_cast<unsigned long long>(world.counters().obstaclePenetrations),
              static_cast<unsigned long long>(world.counters().leaderOvertaken), near, double(farthest), closedUp);
        QVERIFY2(near >= 150, qPrintable(QString::number(near)));
        QVERIFY2(farthest < 100.0f, qPrintable(QString::number(double(farthest))));
        QCOMPARE(closedUp, std::size_t(300));
        // Still nobody through a cone, nor past the leader, while they close up round it.
        QCOMPARE(world.counters().obstaclePenetrations, std::uint64_t(0));
        QCOMPARE(world.counters().leaderOvertaken, std::uint64_t(0));
    }

    void overtakesAreCounted()
    {
        // The figure can fail: riders twice as fast as the leader, pursuing a point 10 m
        // ahead of it, get ahead.
        Scene scene = reducedCavalry();
        for (AgentType& t : scene.agentTypes)
            if (t.name == "rider") {
                t.maxSpeed = 16.0f;
                t.behaviours = {{"offset_pursuit", 1.0f, {{"offset", "", {0.0f, 0.0f, 10.0f}}}},
                                {"obstacle_avoidance", 3.0f, {}}};
            }
        World world(scene, threads(1));
        while (world.timeS() < 20.0)
            world.step();
        QVERIFY2(world.counters().leaderOvertaken > 100, qPrintable(QString::number(world.counters().leaderOvertaken)));
    }

    void identicalOnOneAndTwoThreads()
    {
        const Scene s = reducedCavalry();
        QCOMPARE(runHash(s, 2, 240), runHash(s, 1, 240));
    }
};

THRONG_REGISTER_TEST(TestCavalry)
#include "TestCavalry.moc"
