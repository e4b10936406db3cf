// Path followers at sharp turns (issue 23, finding 7): on a path that turns back by about
// 173 degrees, 4 of 15 walkers turned round past the turn and walked the previous leg
// again (the nearest point of the spine lay on the leg they had just walked), and one was
// still short of the end long after the others. Whatever the turn angle and the path's
// width, a follower must go round once and on to the end, never back down a leg.
#include "TestRegistry.h"

#include "simcore/io/SceneIO.h"
#include "simcore/steering/PathFollowing.h"
#include "simcore/world/World.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <QTest>

#include <cmath>
#include <cstdio>
#include <vector>

using namespace throng::sim;

namespace {

constexpr float kFirstLegM = 12.0f, kSecondLegM = 9.0f;

// Two legs meeting at (0, 0): the first along +x, the second turned by turnDeg
// (counter-clockwise seen from above); 15 walkers start on the first leg's first metres.
std::string twoLegs(float turnDeg, float radiusM, bool closed)
{
    const float a = glm::radians(turnDeg);
    // Scene z points south, so counter-clockwise from above is -z.
    const glm::vec2 end(kSecondLegM * std::cos(a), -kSecondLegM * std::sin(a));
    char buf[1024];
    std::snprintf(buf, sizeof buf,
                  "throng: 1\n"
                  "settings: {fps: 24, seed: 7, bounds: {min: [-30, -30], max: [30, 30]}}\n"
                  "agent_types:\n"
                  "  - {name: walker, radius: 0.25, max_speed: 1.4, behaviours: {path_following: 1, separation: 1}}\n"
                  "paths:\n"
                  "  - {name: turn, radius: %g, closed: %s, points: [[%g, 0], [0, 0], [%.6f, %.6f]]}\n"
                  "groups:\n"
                  "  - {name: walkers, type: walker, count: 15, rect: {min: [%g, %g], max: [%g, %g]}, path: turn}\n",
                  radiusM, closed ? "true" : "false", -kFirstLegM, end.x, end.y, -kFirstLegM + 0.3, -0.7 * radiusM,
                  -kFirstLegM + 5.0, 0.7 * radiusM);
    const LoadResult r = parseScene(buf, "turn.yaml", ".");
    if (!r.ok())
        qFatal("%s", r.diagnostics[0].format().c_str());
    return buf;
}

Scene scene(float turnDeg, float radiusM, bool closed = false)
{
    return parseScene(twoLegs(turnDeg, radiusM, closed), "turn.yaml", ".").scene;
}

}  // namespace

class TestPathTurns : public QObject {
    Q_OBJECT
private slots:
    void followersNeverWalkALegAgain_data()
    {
        QTest::addColumn<float>("turnDeg");
        QTest::addColumn<float>("radiusM");
        for (float turn : {0.0f, 30.0f, 60.0f, 90.0f, 120.0f, 150.0f, 165.0f, 173.0f, 179.0f})
            for (float radius : {0.5f, 1.0f, 2.0f})
                QTest::addRow("turn %g, radius %g", double(turn), double(radius)) << turn << radius;
    }

    void followersNeverWalkALegAgain()
    {
        QFETCH(float, turnDeg);
        QFETCH(float, radiusM);
        World world(scene(turnDeg, radiusM));
        const std::size_t n = world.agentCount();
        QCOMPARE(n, std::size_t(15));
        // Distance to the turn's point: falls along the first leg, rises along the second.
        // Once a walker has come round (been near the turn and left it by half a metre),
        // a fall of more than the give of a crowd pressing (kSlackM) is a walk back.
        constexpr float kSlackM = 1.5f;
        std::vector<float> nearest(n, INFINITY), farthest(n, 0.0f);
        std::vector<char> turned(n, 0), backed(n, 0);
        // The walk is 21 m at 1.4 m/s (15 s); the last of a queue of 15 needs a little more.
        const double limitS = 60.0;
        while (world.timeS() < limitS) {
            world.step();
            bool allArrived = true;
            for (std::size_t i = 0; i < n; ++i) {
                const float d = glm::length(glm::vec2(world.positions()[i].x, world.positions()[i].z));
                if (!turned[i]) {
                    nearest[i] = std::min(nearest[i], d);
                    turned[i] = nearest[i] < radiusM + 1.5f && d > nearest[i] + 0.5f;
                    farthest[i] = d;
                } else {
                    farthest[i] = std::max(farthest[i], d);
                    backed[i] = backed[i] || d < farthest[i] - kSlackM;
                }
                allArrived = allArrived && world.hasArrived(i);
            }
            if (allArrived)
                break;
        }
        int back = 0, late = 0;
        for (std::size_t i = 0; i < n; ++i) {
            back += backed[i];
            late += world.hasArrived(i) ? 0 : 1;
        }
        QVERIFY2(back == 0, qPrintable(QString("%1 of 15 walked a leg again").arg(back)));
        QVERIFY2(late == 0, qPrintable(QString("%1 of 15 not at the end after %2 s").arg(late).arg(world.timeS())));
        QCOMPARE(world.counters().nonFiniteValues, std::uint64_t(0));
    }

    // Fifteen walkers that reach the end of a narrow path (1 m wide) at once can ring its end
    // point, each pressing for it and none within 0.125 m of it: none stopped, so the pile
    // never began, and 9 of 15 were still milling round the end at 60 s, 0.03 to 0.1 m/s.
    // (These are the places a group drew when spawning avoided overlaps; a start that
    // changed nothing else.) Held to a crawl within the path's width of its end, a walker
    // stops where it stands, and the rest pile up against it.
    void aRingAtTheEndSettles()
    {
        const char* places[] = {
            "[-11.068, -0.262]", "[-11.637, -0.321]", "[-11.616, -0.226]", "[-10.582, 0.160]", "[-11.096, 0.334]",
            "[-10.053, 0.145]",  "[-11.674, 0.347]",  "[-8.462, -0.130]",  "[-9.435, -0.237]",  "[-7.666, -0.305]",
            "[-7.142, -0.311]",  "[-8.722, 0.286]",   "[-9.540, 0.342]",   "[-8.201, 0.309]",   "[-7.082, 0.183]"};
        std::string yaml = "throng: 1\n"
                           "settings: {fps: 24, seed: 7, bounds: {min: [-30, -30], max: [30, 30]}}\n"
                           "agent_types:\n"
                           "  - {name: walker, radius: 0.25, max_speed: 1.4, behaviours: {path_following: 1, separation: 1}}\n"
                           "paths:\n"
                           "  - {name: turn, radius: 0.5, points: [[-12, 0], [0, 0], [0, -9]]}\n"
                           "agents:\n";
        for (int k = 0; k < 15; ++k)
            yaml += "  - {id: " + std::to_string(k + 1) + ", type: walker, position: " + places[k] + ", path: turn}\n";
        const LoadResult r = parseScene(yaml, "ring.yaml", ".");
        QVERIFY2(r.ok(), r.ok() ? "" : r.diagnostics[0].format().c_str());
        World world(r.scene);
        std::vector<glm::vec3> before;
        while (world.timeS() < 60.0) {
            if (world.timeS() >= 59.0 && before.empty())
                before.assign(world.positions().begin(), world.positions().end());
            world.step();
        }
        int arrived = 0, still = 0, nearEnd = 0;
        for (std::size_t i = 0; i < world.agentCount(); ++i) {
            arrived += world.hasArrived(i) ? 1 : 0;
            still += world.positions()[i] == before[i] && world.velocities()[i] == glm::vec3(0.0f) ? 1 : 0;
            // On the last leg, past its first 2 m: the pile of 15 along a 1 m path reaches
            // back from the end some 6 m (stopped walkers queue within half a body).
            nearEnd += std::fabs(world.positions()[i].x) <= 0.75f && world.positions()[i].z <= -2.0f ? 1 : 0;
        }
        qInfo("%d of 15 arrived, %d stand still, %d on the last leg", arrived, still, nearEnd);
        QCOMPARE(nearEnd, 15);
        QCOMPARE(arrived, 15);
        QCOMPARE(still, 15);
    }

    void closedLoopKeepsGoingRound()
    {
        // A closed hairpin loop: followers lap it in one direction, so the distance they
        // cover in a minute is laps, not a shuffle at one bend.
        World world(scene(173.0f, 1.0f, true));
        std::vector<float> walked(world.agentCount(), 0.0f);
        std::vector<glm::vec3> last(world.positions().begin(), world.positions().end());
        for (int s = 0; s < 24 * 60; ++s) {
            world.step();
            for (std::size_t i = 0; i < world.agentCount(); ++i) {
                walked[i] += glm::distance(world.positions()[i], last[i]);
                last[i] = world.positions()[i];
            }
        }
        for (std::size_t i = 0; i < world.agentCount(); ++i)
            QVERIFY2(walked[i] > 50.0f, qPrintable(QString("walker %1 walked %2 m in 60 s").arg(i).arg(walked[i])));
    }

    void windowedProjectionSkipsAWalkedLeg()
    {
        // The point (3, -0.2) lies 0.2 m from the first leg (at 9 m along) and farther from
        // the second; a follower already 12.5 m along projects onto the second leg only.
        const std::vector<glm::vec3> pts{{-12, 0, 0}, {0, 0, 0}, {12, 0, -0.9f}};
        const SteeringPath path{pts, 1.0f, false};
        QCOMPARE(projectOntoPath(path, {-3, 0, -0.2f}).distanceAlongM, 9.0f);
        const PathProjection later = projectOntoPathWithin(path, {-3, 0, -0.2f}, 12.5f, 16.0f);
        QVERIFY(later.distanceAlongM >= 12.5f);
        QCOMPARE(advancePathProgress(path, {-3, 0, -0.2f}, 12.5f, 3.0f, false) >= 12.5f, true);
        // Windows past either end clamp on an open path and wrap on a closed one.
        QCOMPARE(projectOntoPathWithin(path, {50, 0, 0}, 30.0f, 40.0f).distanceAlongM, pathLength(path));
        const SteeringPath loop{pts, 1.0f, true};
        const float total = pathLength(loop);
        const PathProjection wrapped = projectOntoPathWithin(loop, {-11, 0, 0}, total - 0.5f, total + 3.0f);
        QVERIFY2(std::fabs(wrapped.distanceAlongM - 1.0f) < 1e-4f, qPrintable(QString::number(wrapped.distanceAlongM)));
    }
};

THRONG_REGISTER_TEST(TestPathTurns)
#include "TestPathTurns.moc"
