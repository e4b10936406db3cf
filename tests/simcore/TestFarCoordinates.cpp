// Scenes at map coordinates (issue 23, finding 5): a user placed a room about 1e6 m from
// the origin (UTM-like eastings and northings) and every walker stood still for 60 s, each
// step of a few centimetres rounding to nothing in 32-bit floats, while `check` said valid.
// The same set at 1e6 and 1e7 m must move exactly as it does at the origin.
#include "TestRegistry.h"

#include "simcore/io/SceneIO.h"
#include "simcore/scene/SceneOrigin.h"
#include "simcore/world/World.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <cmath>
#include <cstdio>
#include <string>

using namespace throng::sim;

namespace {

// One number of the scene text: the set's own coordinate plus the offset, printed exactly
// (every coordinate of the set is a multiple of 1/4 m, and offsets are whole metres).
std::string at(double offset, double v)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.4f", offset + v);
    return buf;
}

// A room with a 2 m door, a box and a circle obstacle, a spawned crowd walking to the
// door's exit and beyond, A* walkers round the box, and a path with a sharp turn: every
// kind of geometry a far scene shifts, translated by (dx, dz).
Scene room(double dx, double dz)
{
    auto p = [&](double x, double z) { return "[" + at(dx, x) + ", " + at(dz, z) + "]"; };
    auto p3 = [&](double x, double z) { return "[" + at(dx, x) + ", 0, " + at(dz, z) + "]"; };
    const std::string yaml = std::string("throng: 1\n") +
        "settings: {fps: 24, seed: 3, bounds: {min: " + p(-30, -30) + ", max: " + p(30, 30) + "}}\n"
        "agent_types:\n"
        "  - {name: walker, radius: 0.3, max_speed: 1.4, behaviours: {arrival: 1, separation: 1, wall_following: 1, obstacle_avoidance: 1}}\n"
        "  - {name: planner, radius: 0.3, navigation: astar, behaviours: {arrival: 1, separation: 1}}\n"
        "  - {name: follower, radius: 0.3, behaviours: {path_following: 1, separation: 1}}\n"
        "walls:\n"
        "  - {points: [" + p(8, 1) + ", " + p(8, 10) + ", " + p(-10, 10) + ", " + p(-10, -10) + ", " + p(8, -10) + ", " +
        p(8, -1) + "]}\n"
        "obstacles:\n"
        "  - {shape: box, center: " + p(0, 4) + ", size: [3, 1.5], angle: 30}\n"
        "  - {shape: circle, center: " + p(-2, -4) + ", radius: 1.25}\n"
        "goals:\n"
        "  - {name: door, position: " + p(8, 0) + ", radius: 1, exit: true}\n"
        "  - {name: yard, position: " + p(20, 5) + ", radius: 2}\n"
        "paths:\n"
        "  - {name: lap, radius: 1, points: [" + p(-20, -20) + ", " + p(-5, -20) + ", " + p(-19, -18.5) + "]}\n"
        "groups:\n"
        "  - {name: crowd, type: walker, count: 40, rect: {min: " + p(-8, -8) + ", max: " + p(-2, 8) + "}, goal: door}\n"
        "agents:\n"
        "  - {id: 1, type: planner, position: " + p3(-6, 7) + ", goal: yard}\n"
        "  - {id: 2, type: planner, position: " + p3(-6, -7.5) + ", goal: yard}\n"
        "  - {id: 3, type: follower, position: " + p3(-21, -21) + ", path: lap}\n"
        "  - {id: 4, type: walker, position: " + p3(20, -20) + ", heading: 45, goal: yard}\n";
    const LoadResult r = parseScene(yaml, "far.yaml", ".");
    if (!r.ok())
        qFatal("%s", r.diagnostics[0].format().c_str());
    return r.scene;
}

// Largest distance between agent positions of the two Worlds in the scene's coordinates,
// the far one's brought back by its offset; loneOnly: of the path follower and the
// walker in the yard only (ids 3 and 4), who meet nobody.
double largestGap(const World& nearWorld, const World& farWorld, glm::dvec3 offset, bool loneOnly)
{
    double worst = 0.0;
    for (std::size_t i = 0; i < nearWorld.agentCount(); ++i) {
        if (loneOnly && (nearWorld.id(i) < 3 || nearWorld.id(i) > 4))
            continue;
        const glm::dvec3 a(nearWorld.positions()[i]);
        const glm::dvec3 b = glm::dvec3(farWorld.positions()[i]) + (farWorld.origin() - offset);
        worst = std::max(worst, glm::length(a - b));
    }
    return worst;
}

}  // namespace

class TestFarCoordinates : public QObject {
    Q_OBJECT
private slots:
    void farSceneMovesAsAtTheOrigin_data()
    {
        QTest::addColumn<double>("dx");
        QTest::addColumn<double>("dz");
        QTest::addColumn<double>("toleranceM");
        // Offsets whose scene centre is the offset itself: the shift is exact, and so are
        // the trajectories. 1e7 m east: floats there are 1 m apart, and every x of the
        // set is a whole metre, so the file's floats hold it exactly.
        QTest::newRow("origin twice") << 0.0 << 0.0 << 0.0;
        QTest::newRow("utm-like 1e6") << 500000.0 << 5000000.0 << 0.0;
        QTest::newRow("1e6 negative") << -1000000.0 << 1000000.0 << 0.0;
        QTest::newRow("far east 1e7") << 10000000.0 << 0.0 << 0.0;
        // The centre rounds to whole metres, half a metre from the offset: the World
        // then computes with other floats, and the lone walkers keep within a tight
        // tolerance of the same walk (the crowd's pushing amplifies the last bit, as any
        // change of rounding does; it still leaves as the crowd at the origin does).
        QTest::newRow("half-metre centre") << 2000000.5 << -3000000.5 << 1e-3;
    }

    void farSceneMovesAsAtTheOrigin()
    {
        QFETCH(double, dx);
        QFETCH(double, dz);
        QFETCH(double, toleranceM);
        const Scene nearScene = room(0.0, 0.0), farScene = room(dx, dz);
        World nearWorld(nearScene), farWorld(farScene);
        QCOMPARE(nearWorld.origin(), glm::dvec3(0.0));
        QVERIFY(std::fabs(farWorld.origin().x - dx) <= 0.5 && std::fabs(farWorld.origin().z - dz) <= 0.5);
        QCOMPARE(farWorld.agentCount(), nearWorld.agentCount());
        const glm::dvec3 offset(dx, 0.0, dz);
        const bool loneOnly = toleranceM > 0.0;
        QVERIFY(largestGap(nearWorld, farWorld, offset, loneOnly) <= toleranceM);
        double worst = 0.0;
        for (int s = 0; s < 24 * 30; ++s) {
            nearWorld.step();
            farWorld.step();
            worst = std::max(worst, largestGap(nearWorld, farWorld, offset, loneOnly));
        }
        QVERIFY2(worst <= toleranceM, qPrintable(QString("trajectories differ by %1 m").arg(worst)));
        // And they are walks, not the frozen crowd of the old code: everyone moved metres.
        std::size_t moved = 0, out = 0;
        const World start(farScene);
        for (std::size_t i = 0; i < farWorld.agentCount(); ++i) {
            moved += glm::distance(farWorld.positions()[i], start.positions()[i]) > 2.0f ? 1 : 0;
            out += farWorld.isOut(i) ? 1 : 0;
            if (!loneOnly) {
                QCOMPARE(farWorld.isOut(i), nearWorld.isOut(i));
                QCOMPARE(farWorld.hasArrived(i), nearWorld.hasArrived(i));
            }
        }
        QCOMPARE(moved, farWorld.agentCount());
        QVERIFY2(out >= 35, qPrintable(QString::number(out)));
    }

    void nearSceneIsNotShifted()
    {
        // Bounds within 8 km of the origin: simulated as written, so every existing scene's
        // figures stay what they were.
        QCOMPARE(simulationOrigin(room(4000.0, -4000.0)), glm::dvec2(0.0));
        QCOMPARE(World(room(4000.0, -4000.0)).origin(), glm::dvec3(0.0));
        QCOMPARE(simulationOrigin(room(9000.0, 0.0)), glm::dvec2(9000.0, 0.0));
    }

    void shiftKeepsEveryCoordinate()
    {
        // Every ground coordinate moves by the same exact amount, and nothing else changes.
        const Scene s = room(1000000.0, 2000000.0);
        const Scene shifted = shiftedScene(s, {1000000.0, 2000000.0});
        const Scene nearScene = room(0.0, 0.0);
        QVERIFY(shifted.walls == nearScene.walls);
        QVERIFY(shifted.obstacles == nearScene.obstacles);
        QVERIFY(shifted.goals == nearScene.goals);
        QVERIFY(shifted.paths == nearScene.paths);
        QCOMPARE(shifted.groups.size(), nearScene.groups.size());
        QCOMPARE(shifted.groups[0].min, nearScene.groups[0].min);
        QCOMPARE(shifted.groups[0].max, nearScene.groups[0].max);
        QVERIFY(shifted.agents == nearScene.agents);
        QVERIFY(shifted.settings == nearScene.settings);
        // The spacing of the file's floats there: 1/8 m at 2e6 m, 1 m at 1e7 m.
        QCOMPARE(coordinateSpacingM(s), 0.125);
        QCOMPARE(coordinateSpacingM(room(10000000.0, 0.0)), 1.0);
        QCOMPARE(coordinateSpacingM(nearScene) < 1e-5, true);
    }
};

THRONG_REGISTER_TEST(TestFarCoordinates)
#include "TestFarCoordinates.moc"
