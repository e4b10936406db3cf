// Lane geometry as a layout artist would check it: points along a lane are where the
// arc length says, projecting a point gives back its distance and side, stop lines and
// crosswalks land where they were drawn, and the pedestrian rule holds.
#include "TestRegistry.h"

#include "TrafficHarness.h"
#include "simcore/traffic/LaneNetwork.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <cmath>
#include <random>

using namespace throng::sim;

class TestLaneNetwork : public QObject {
    Q_OBJECT
private slots:
    void arcLengthPositionsAndTangents()
    {
        Scene scene;
        // An L-shaped lane: 30 m east, then 40 m south (z grows), then 10 m west.
        scene.lanes.push_back({"bend", {{0, 0}, {30, 0}, {30, 40}, {20, 40}}, 3.5f, 10.0f, false});
        const LaneNetwork net(scene);
        QCOMPARE(net.laneCount(), std::size_t(1));
        QCOMPARE(net.length(0), 80.0f);
        QVERIFY(glm::distance(net.positionAt(0, 0.0f), glm::vec2(0, 0)) < 1e-6f);
        QVERIFY(glm::distance(net.positionAt(0, 15.0f), glm::vec2(15, 0)) < 1e-5f);
        QVERIFY(glm::distance(net.positionAt(0, 30.0f), glm::vec2(30, 0)) < 1e-5f);
        QVERIFY(glm::distance(net.positionAt(0, 50.0f), glm::vec2(30, 20)) < 1e-5f);
        QVERIFY(glm::distance(net.positionAt(0, 80.0f), glm::vec2(20, 40)) < 1e-5f);
        QVERIFY(glm::distance(net.positionAt(0, 95.0f), glm::vec2(20, 40)) < 1e-5f);  // open lane clamps
        QVERIFY(glm::distance(net.tangentAt(0, 10.0f), glm::vec2(1, 0)) < 1e-6f);
        QVERIFY(glm::distance(net.tangentAt(0, 45.0f), glm::vec2(0, 1)) < 1e-6f);
        QVERIFY(glm::distance(net.tangentAt(0, 75.0f), glm::vec2(-1, 0)) < 1e-6f);
    }

    void loopingLaneWraps()
    {
        Scene scene;
        scene.lanes.push_back({"ring", {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 0}}, 3.5f, 10.0f, true});
        const LaneNetwork net(scene);
        QCOMPARE(net.length(0), 40.0f);
        QVERIFY(glm::distance(net.positionAt(0, 45.0f), glm::vec2(5, 0)) < 1e-5f);
        QVERIFY(glm::distance(net.positionAt(0, -5.0f), glm::vec2(0, 5)) < 1e-5f);
        QCOMPARE(net.wrap(0, 40.0f), 0.0f);
    }

    void projectionRoundTrips()
    {
        Scene scene;
        scene.lanes.push_back({"curve", {{0, 0}, {20, 5}, {40, 0}, {60, 10}}, 4.0f, 10.0f, false});
        const LaneNetwork net(scene);
        std::mt19937 gen(3);
        std::uniform_real_distribution<float> us(0.5f, net.length(0) - 0.5f), off(-1.5f, 1.5f);
        int checked = 0;
        for (int k = 0; k < 500; ++k) {
            const float s = us(gen), d = off(gen);
            const glm::vec2 t = net.tangentAt(0, s);
            const glm::vec2 left{t.y, -t.x};
            const glm::vec2 p = net.positionAt(0, s) + left * d;
            const LaneProjection pr = net.project(0, p);
            // Near a convex corner another segment may be nearer; the distance is then
            // smaller still, never larger.
            QVERIFY(pr.distanceM <= std::abs(d) + 1e-4f);
            if (std::abs(pr.s - s) < 1e-3f) {
                QVERIFY2(std::abs(pr.lateralM - d) < 1e-3f, "lateral offset is the signed distance to the left");
                ++checked;
            }
        }
        QVERIFY(checked > 400);
        // Left of an eastbound lane is north (-z).
        Scene east;
        east.lanes.push_back({"e", {{0, 0}, {10, 0}}, 3.5f, 10.0f, false});
        QVERIFY(LaneNetwork(east).project(0, {5, -1}).lateralM > 0.9f);
    }

    void stopLinesAndCrosswalksResolve()
    {
        throng::test::CrossingSetup setup;
        const Scene scene = throng::test::crossingScene(setup);
        const LaneNetwork net(scene);
        QCOMPARE(net.stopLines().size(), std::size_t(4));
        QCOMPARE(net.stopLineCount(), std::size_t(8));  // four lane lines, four crosswalks
        const int east = net.findLane("eastbound");
        QCOMPARE(net.stopLinesOn(east).size(), std::size_t(1));
        QVERIFY(glm::distance(net.positionAt(east, net.stopLinesOn(east)[0].s), glm::vec2(-8.5f, 1.75f)) < 1e-4f);
        // The eastbound lane crosses the west crosswalk (x in [-7.5, -4.5]) and then the
        // east one (x in [4.5, 7.5]), and no other.
        const auto& st = net.stretchesOn(east);
        QCOMPARE(st.size(), std::size_t(2));
        QCOMPARE(scene.crosswalks[std::size_t(st[0].crosswalk)].name, std::string("west"));
        QVERIFY(std::abs(st[0].s0 - 92.5f) < 1e-3f && std::abs(st[0].s1 - 95.5f) < 1e-3f);
        QCOMPARE(scene.crosswalks[std::size_t(st[1].crosswalk)].name, std::string("east"));
        QVERIFY(std::abs(st[1].s0 - 104.5f) < 1e-3f && std::abs(st[1].s1 - 107.5f) < 1e-3f);
        QCOMPARE(net.stretches().size(), std::size_t(8));
        for (std::size_t c = 0; c < net.crosswalkCount(); ++c)
            QVERIFY(net.crosswalk(int(c)).light >= 0);
    }

    // The road part of a crosswalk is found where it crosses the lanes, whatever the
    // strip's length: the kerb lines of a 1,000 km crosswalk over a two-lane street are
    // those of a 12 m one (sampling the whole strip every 2 cm took 9 s), and a strip far
    // from every lane lies over none.
    void roadPartOfALongCrosswalk()
    {
        Scene scene;
        scene.lanes.push_back({"n", {{1.75f, -50}, {1.75f, 50}}, 3.5f, 10.0f, false});
        scene.lanes.push_back({"s", {{-1.75f, 50}, {-1.75f, -50}}, 3.5f, 10.0f, false});
        scene.crosswalks.push_back({"short", {-6, 0}, {6, 0}, 3.0f});
        scene.crosswalks.push_back({"long", {-1e6f, 20}, {6, 20}, 3.0f});
        scene.crosswalks.push_back({"away", {100, 0}, {1e6f, 0}, 3.0f});
        const LaneNetwork net(scene);
        const CrosswalkStrip& a = net.crosswalk(0);
        const CrosswalkStrip& b = net.crosswalk(1);
        QVERIFY(a.overLane && b.overLane);
        // Kerb lines as x: -3.5 and 3.5, each widened by a 2 cm sample (float steps are
        // 6 cm at 1,000 km).
        QVERIFY(std::abs(a.a.x + a.roadU0 - -3.52f) < 0.011f && std::abs(a.a.x + a.roadU1 - 3.52f) < 0.011f);
        QVERIFY2(std::abs(b.a.x + b.roadU0 - -3.52f) < 0.1f && std::abs(b.a.x + b.roadU1 - 3.52f) < 0.1f,
                 qPrintable(QString("%1 %2").arg(double(b.a.x + b.roadU0)).arg(double(b.a.x + b.roadU1))));
        QVERIFY(!net.crosswalk(2).overLane);
        QCOMPARE(net.crosswalk(2).roadU0, 0.0f);
        QCOMPARE(net.crosswalk(2).roadU1, net.crosswalk(2).lengthM);
    }

    void obliqueCrosswalkStretch()
    {
        Scene scene;
        scene.lanes.push_back({"e", {{-20, 0}, {20, 0}}, 3.5f, 10.0f, false});
        // A 4 m wide strip at 45 degrees through the origin: the centre line is inside it
        // for |x| <= 2 / sin(45) = 2.83 m.
        scene.crosswalks.push_back({"diag", {-5, -5}, {5, 5}, 4.0f});
        const LaneNetwork net(scene);
        QCOMPARE(net.stretchesOn(0).size(), std::size_t(1));
        const LaneStretch st = net.stretchesOn(0)[0];
        QVERIFY(std::abs(st.s0 - (20.0f - 2.0f * std::sqrt(2.0f))) < 1e-3f);
        QVERIFY(std::abs(st.s1 - (20.0f + 2.0f * std::sqrt(2.0f))) < 1e-3f);
        QCOMPARE(net.crosswalk(0).light, -1);
        QCOMPARE(net.crosswalkStopLineIndex(0), -1);
    }

    void pedestriansStayOffLanesExceptOnCrosswalks()
    {
        const Scene scene = throng::test::crossingScene({});
        const LaneNetwork net(scene);
        QVERIFY(net.forbiddenForPedestrian({-30, 1.75f}));       // middle of the eastbound lane
        QVERIFY(net.forbiddenForPedestrian({-30, 3.4f}, 0.3f));  // a body reaching over the lane edge
        QVERIFY(!net.forbiddenForPedestrian({-30, 4.2f}, 0.3f)); // on the pavement beside it
        QVERIFY(!net.forbiddenForPedestrian({-6, 1.75f}, 0.3f)); // on the west crosswalk
        QVERIFY(!net.forbiddenForPedestrian({-6, -5.0f}));       // crosswalk end on the kerb
        QVERIFY(net.forbiddenForPedestrian({-8, 0.5f}, 0.3f));   // beside the crosswalk, in the road
        QVERIFY(!net.forbiddenForPedestrian({-120, 1.75f}));     // beyond the lane's start
        QCOMPARE(net.crosswalkAt({-6, 0}), 0);
        QCOMPARE(net.crosswalkAt({-9, 0}), -1);
        QCOMPARE(net.carriagewayAt({0, 1.0f}).lane >= 0, true);
    }

    void kerbBarriersLeaveOnlyTheCrosswalksOpen()
    {
        const Scene scene = throng::test::crossingScene({});
        const LaneNetwork net(scene);
        const std::vector<BarrierSegment> kerbs = net.pedestrianBarriers();
        auto crosses = [&](glm::vec2 p, glm::vec2 q) {
            auto cross = [](glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; };
            for (const BarrierSegment& k : kerbs) {
                const glm::vec2 r = q - p, s = k.b - k.a;
                const float den = cross(r, s);
                if (den == 0.0f)
                    continue;
                const float t = cross(k.a - p, s) / den, u = cross(k.a - p, r) / den;
                if (t >= 0.0f && t <= 1.0f && u >= 0.0f && u <= 1.0f)
                    return true;
            }
            return false;
        };
        QVERIFY(kerbs.size() >= 16);
        // Along every crosswalk, kerb to kerb: nothing in the way.
        for (std::size_t c = 0; c < net.crosswalkCount(); ++c) {
            const CrosswalkStrip& s = net.crosswalk(int(c));
            const glm::vec2 side{s.dir.y, -s.dir.x};
            for (float w : {-1.2f, 0.0f, 1.2f})
                QVERIFY(!crosses(s.a - s.dir * 2.0f + side * w, s.b + s.dir * 2.0f + side * w));
        }
        QVERIFY(crosses({-30, 6}, {-30, 1.75f}));     // off the pavement into the road
        QVERIFY(crosses({-6, 1.75f}, {-9, 1.75f}));   // sideways off a crosswalk into the road
        QVERIFY(!crosses({-30, 1.0f}, {-30, -1.0f})); // between two lanes: no kerb on the road
        QVERIFY(!crosses({-2, -2}, {2, 2}));          // across the junction box
        // Every small step from where a walker may be to where it may not crosses a kerb.
        std::mt19937 gen(17);
        std::uniform_real_distribution<float> u(-20.0f, 20.0f), step(-0.5f, 0.5f);
        int entries = 0;
        for (int k = 0; k < 200000; ++k) {
            const glm::vec2 p{u(gen), u(gen)}, q = p + glm::vec2(step(gen), step(gen));
            if (net.forbiddenForPedestrian(p) || !net.forbiddenForPedestrian(q))
                continue;
            ++entries;
            QVERIFY2(crosses(p, q), "a way into a lane other than a crosswalk");
        }
        qInfo("%zu kerb segments; %d random steps into a lane, each across a kerb", kerbs.size(), entries);
        QVERIFY(entries > 1000);
    }
};

THRONG_REGISTER_TEST(TestLaneNetwork)
#include "TestLaneNetwork.moc"
