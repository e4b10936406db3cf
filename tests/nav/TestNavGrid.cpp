// The navigation grid blocks every cell whose centre an inflated wall or obstacle reaches
// and every cell a shape passes through, and no other; a door or passage the body fits
// through stays open; cell queries agree with brute force; edits change the generation.
#include "TestRegistry.h"
#include "NavTestMaps.h"

#include "simcore/nav/FlowField.h"
#include "simcore/nav/NavGrid.h"
#include "simcore/nav/NavPassages.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

using namespace throng::sim;
using namespace throng::test;

namespace {

// Distance from p to the nearest solid point of the shapes (0 inside a circle or box).
float clearance(const NavShapes& shapes, glm::vec2 p)
{
    float d = 1e9f;
    for (const Segment& s : shapes.walls)
        d = std::min(d, pointSegmentDistance(p, s.a, s.b));
    for (const NavCircle& c : shapes.circles)
        d = std::min(d, std::max(0.0f, glm::distance(p, c.centre) - c.radiusM));
    for (const NavBox& b : shapes.boxes) {
        if (b.contains(p))
            return 0.0f;
        Segment sides[4];
        boxSides(b, sides);
        for (const Segment& s : sides)
            d = std::min(d, pointSegmentDistance(p, s.a, s.b));
    }
    return d;
}

Scene randomShapes(std::mt19937& gen)
{
    std::uniform_real_distribution<float> u(-18.0f, 18.0f), len(-8.0f, 8.0f), r(0.2f, 2.0f), ang(0.0f, 180.0f);
    Scene s;
    s.settings.boundsMin = {-20.0f, -15.0f};
    s.settings.boundsMax = {20.0f, 15.0f};
    for (int k = 0; k < 6; ++k) {
        const glm::vec2 a(u(gen), u(gen) * 0.8f);
        s.walls.push_back({"w", {a, a + glm::vec2(len(gen), len(gen)), a + glm::vec2(len(gen), len(gen))}});
    }
    for (int k = 0; k < 5; ++k)
        s.obstacles.push_back({"c", ObstacleShape::Circle, {u(gen), u(gen) * 0.8f}, r(gen), {1, 1}, 0.0f});
    for (int k = 0; k < 4; ++k)
        s.obstacles.push_back({"b", ObstacleShape::Box, {u(gen), u(gen) * 0.8f}, 0.5f, {r(gen) * 2, r(gen) * 3}, ang(gen)});
    return s;
}

}  // namespace

class TestNavGrid : public QObject {
    Q_OBJECT
private slots:
    void rasterisationIsByCentreAndWatertight_data()
    {
        QTest::addColumn<float>("cellM");
        QTest::addColumn<float>("radiusM");
        QTest::newRow("fine cells, walker") << 0.25f << 0.3f;
        QTest::newRow("coarse cells, walker") << 1.0f << 0.3f;
        QTest::newRow("half-metre cells, rider") << 0.5f << 0.9f;
        QTest::newRow("no inflation") << 0.5f << 0.0f;
    }

    // A cell is blocked exactly when a shape comes within the radius of its centre, or
    // within 0.75 of a cell; so no shape passes through a walkable cell (5 x 5 samples,
    // edges included, all clear of every shape), however coarse the cells.
    void rasterisationIsByCentreAndWatertight()
    {
        QFETCH(float, cellM);
        QFETCH(float, radiusM);
        const float reach = std::max(radiusM, 0.75f * cellM);
        std::mt19937 gen(3);
        for (int map = 0; map < 4; ++map) {
            const Scene scene = randomShapes(gen);
            const NavShapes shapes = navShapes(scene);
            NavGrid grid;
            grid.build(scene, {cellM, radiusM});
            QCOMPARE(grid.cols(), int(std::ceil(40.0f / cellM)));
            int blocked = 0;
            for (int z = 0; z < grid.rows(); ++z)
                for (int x = 0; x < grid.cols(); ++x) {
                    const glm::vec2 c = grid.centre({x, z});
                    const float atCentre = clearance(shapes, c);
                    if (!grid.walkable({x, z})) {
                        ++blocked;
                        QVERIFY2(atCentre <= reach + 1e-4f, "a cell whose centre is clear of every shape is blocked");
                        continue;
                    }
                    QVERIFY2(atCentre > reach - 1e-4f, "a walkable cell's centre is within reach of a shape");
                    for (int j = 0; j <= 4; ++j)
                        for (int i = 0; i <= 4; ++i) {
                            const glm::vec2 p = c + (glm::vec2(float(i), float(j)) / 4.0f - 0.5f) * cellM;
                            if (clearance(shapes, p) <= 0.0f)
                                QFAIL(qPrintable(
                                    QString("a shape passes through walkable cell (%1, %2)").arg(x).arg(z)));
                        }
                }
            QVERIFY2(blocked > 0 && blocked < grid.cellCount(), "the random map must block some cells and leave others");
        }
    }

    // A 1 m door in a wall, for walkers of 0.2 m and 0.15 m of clearance (0.35 m), on cells
    // of 0.25 m: wherever the posts fall on the grid, a row of cells stays open through the
    // doorway. (Measured from each cell's square instead, the door closed when its posts lay
    // on cell edges, and the walkers in rooms behind such doors stood there for good.)
    void aDoorStaysOpenWhereverItsPostsFall()
    {
        for (const float shift : {0.0f, 0.05f, 0.1f, 0.125f, 0.2f}) {
            Scene scene;
            scene.settings.boundsMin = {-5.0f, -5.0f};
            scene.settings.boundsMax = {5.0f, 5.0f};
            scene.walls.push_back({"west", {{-5.0f, 0.0f}, {shift, 0.0f}}});
            scene.walls.push_back({"east", {{shift + 1.0f, 0.0f}, {5.0f, 0.0f}}});
            NavGrid grid;
            grid.build(scene, {0.25f, 0.35f});
            int open = 0;
            for (int x = 0; x < grid.cols(); ++x)
                open += grid.walkable(grid.cellOf({grid.centre({x, 0}).x, 0.01f})) ? 1 : 0;
            QVERIFY2(open >= 1, qPrintable(QString("the door is closed with its posts shifted %1 m").arg(shift)));
        }
    }

    // A passage 0.78 m wide and 2 m long off a room, for walkers of 0.2 m and 0.15 m of
    // clearance: the clearance closes it (every cell across it lies within 0.35 m of a
    // side), though the body fits. openNarrowPassages opens the cells between its sides
    // that the body alone fits in, so a field from beyond it reaches the room; a wall with
    // nothing across it keeps its clearance, and a box obstacle's inside stays closed.
    void aPassageTheBodyFitsStaysOpen_data()
    {
        QTest::addColumn<float>("cellM");
        QTest::newRow("0.1 m cells") << 0.1f;
        QTest::newRow("0.2 m cells") << 0.2f;
        QTest::newRow("0.25 m cells") << 0.25f;
    }

    void aPassageTheBodyFitsStaysOpen()
    {
        QFETCH(float, cellM);
        Scene scene;
        scene.settings.boundsMin = {-2.0f, -8.0f};
        scene.settings.boundsMax = {20.0f, 8.0f};
        scene.walls.push_back({"room", {{12.0f, -0.39f}, {10.0f, -0.39f}, {10.0f, -5.0f}, {0.0f, -5.0f},
                                        {0.0f, 5.0f}, {10.0f, 5.0f}, {10.0f, 0.39f}, {12.0f, 0.39f}}});
        // A thin box in the open (0.6 m thick): its inside must not count as a passage.
        scene.obstacles.push_back({"slab", ObstacleShape::Box, {16.0f, 4.0f}, 0.5f, {4.0f, 0.6f}, 0.0f});
        const NavShapes shapes = navShapes(scene);
        const float body = 0.2f, inflate = 0.35f;
        NavGrid grid;
        grid.build(shapes, scene.settings.boundsMin, scene.settings.boundsMax, {cellM, inflate});
        const NavCell inRoom = grid.cellOf({5.0f, 0.0f}), inPassage = grid.cellOf({11.0f, 0.0f});
        const FlowGoal beyond{{17.0f, 0.0f}, 1.0f};
        FlowField closed;
        closed.build(grid, std::span<const FlowGoal>(&beyond, 1));
        QVERIFY2(!closed.reachable(inRoom), "the clearance did not close the passage: the test shows nothing");

        const std::size_t opened = openNarrowPassages(grid, shapes, body, inflate);
        QVERIFY(opened > 0);
        FlowField field;
        field.build(grid, std::span<const FlowGoal>(&beyond, 1));
        QVERIFY2(field.reachable(inRoom), "the room does not reach beyond the passage");
        QVERIFY(!grid.walkable(inPassage) || field.reachable(inPassage));
        const float bodyReach = std::max(body, 0.75f * cellM);
        for (int z = 0; z < grid.rows(); ++z)
            for (int x = 0; x < grid.cols(); ++x) {
                const glm::vec2 c = grid.centre({x, z});
                if (!grid.walkable({x, z}))
                    continue;
                // Every walkable cell: the body fits at its centre.
                QVERIFY2(clearance(shapes, c) > bodyReach - 1e-4f,
                         qPrintable(QString("cell (%1, %2) opened within a body of a shape").arg(x).arg(z)));
                // Away from the passage and its mouth (more than the inflation and a cell from
                // its rectangle), the clearance is kept: along single walls, in the room's
                // corners, round and inside the slab.
                const glm::vec2 out = glm::max(glm::abs(c - glm::vec2(11.0f, 0.0f)) - glm::vec2(1.0f, 0.39f), 0.0f);
                if (glm::length(out) > inflate + cellM)
                    QVERIFY2(clearance(shapes, c) > inflate - 1e-4f,
                             qPrintable(QString("cell (%1, %2) outside the passage lost its clearance").arg(x).arg(z)));
            }
    }

    void cellQueriesMatchBruteForce()
    {
        NavGrid grid(13, 9, {-3.0f, 2.0f}, 0.5f);
        QCOMPARE(grid.cellOf({-3.0f, 2.0f}), (NavCell{0, 0}));
        QCOMPARE(grid.cellOf({-2.74f, 2.6f}), (NavCell{0, 1}));
        QCOMPARE(grid.cellOf({-3.01f, 2.0f}), (NavCell{-1, 0}));
        QVERIFY(!grid.walkable({-1, 0}));
        QVERIFY(!grid.walkable({13, 0}));
        const glm::vec2 c = grid.centre({4, 7});
        QCOMPARE(c.x, -0.75f);
        QCOMPARE(c.y, 5.75f);
        QCOMPARE(grid.cellOf(c), (NavCell{4, 7}));

        std::mt19937 gen(8);
        // Some queries come from far outside the grid (a goal placed off the set).
        const auto q0 = [](int trial) { return trial % 5 == 0 ? -3000 : -3; };
        const auto q1 = [](int trial) { return trial % 5 == 1 ? 5000 : 0; };
        for (int trial = 0; trial < 40; ++trial) {
            NavGrid g = randomGrid(gen, 11, 8, trial < 2 ? 0.97f : 0.6f);
            std::uniform_int_distribution<int> ux(q0(trial), 13 + q1(trial)), uz(-3, 10);
            for (int q = 0; q < 30; ++q) {
                const NavCell from{ux(gen), uz(gen)};
                long best = -1;
                NavCell want{-1, -1};
                for (int z = 0; z < g.rows(); ++z)
                    for (int x = 0; x < g.cols(); ++x) {
                        const long d2 = long(x - from.x) * (x - from.x) + long(z - from.z) * (z - from.z);
                        if (g.walkable({x, z}) && (best < 0 || d2 < best)) {
                            best = d2;
                            want = {x, z};
                        }
                    }
                QCOMPARE(g.nearestWalkable(from), want);
            }
        }
    }

    // A goal or agent a mutated file puts a billion metres away (or at NaN) still finds the
    // nearest walkable cell, without integer overflow (the sanitizer build checks that).
    void farAndNonFiniteQueriesStayInRange()
    {
        std::mt19937 gen(3);
        const NavGrid g = randomGrid(gen, 11, 8, 0.6f);
        const auto bruteNearest = [&](NavCell from) {
            long double best = -1;
            NavCell want{-1, -1};
            for (int z = 0; z < g.rows(); ++z)
                for (int x = 0; x < g.cols(); ++x) {
                    const long double dx = (long double)x - from.x, dz = (long double)z - from.z;
                    if (g.walkable({x, z}) && (best < 0 || dx * dx + dz * dz < best)) {
                        best = dx * dx + dz * dz;
                        want = {x, z};
                    }
                }
            return want;
        };
        const int big = std::numeric_limits<int>::max(), small = std::numeric_limits<int>::min();
        for (const NavCell from : {NavCell{big, 3}, NavCell{small, 3}, NavCell{4, big}, NavCell{4, small},
                                   NavCell{big, big}, NavCell{small, big}, NavCell{big - 5, small + 7}}) {
            const NavCell got = g.nearestWalkable(from);
            QVERIFY2(g.walkable(got), qPrintable(QString("from %1 %2").arg(from.x).arg(from.z)));
            QCOMPARE(got, bruteNearest(from));
        }
        const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
        for (const glm::vec2 p : {glm::vec2(3.4e38f, 1.0f), glm::vec2(-3.4e38f, 1e9f), glm::vec2(inf, -inf),
                                  glm::vec2(nan, 2.0f), glm::vec2(1.0f, nan)}) {
            const NavCell c = g.cellOf(p);
            QVERIFY(!g.inside(c));
            QVERIFY(g.walkable(g.nearestWalkable(c)));
        }
        QVERIFY(g.cellOf({3.4e38f, 1.0f}).x >= g.cols());
        QVERIFY(g.cellOf({-3.4e38f, 1.0f}).x < 0);
    }

    void editsBumpTheGeneration()
    {
        NavGrid grid;
        grid.build(fieldTestScene(1), {0.5f, 0.3f});
        const auto g0 = grid.generation();
        const NavCell free = grid.cellOf({2.0f, 2.0f});
        QVERIFY(grid.walkable(free));
        grid.setWalkable(free, true);  // no change
        QCOMPARE(grid.generation(), g0);
        grid.setWalkable(free, false);
        QVERIFY(!grid.walkable(free));
        const auto g1 = grid.generation();
        QVERIFY(g1 != g0);
        grid.build(fieldTestScene(1), {0.5f, 0.3f});
        QVERIFY(grid.generation() != g1 && grid.generation() != g0);
        const NavGrid copy = grid, other(4, 4, {0, 0}, 1.0f), another(4, 4, {0, 0}, 1.0f);
        QCOMPARE(copy.generation(), grid.generation());  // a flow field's copy is current
        QVERIFY(other.generation() != another.generation() && other.generation() != grid.generation());
        QVERIFY(grid.walkable(free));
    }
};

THRONG_REGISTER_TEST(TestNavGrid)
#include "TestNavGrid.moc"
