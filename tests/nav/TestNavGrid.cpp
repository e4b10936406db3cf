// The navigation grid blocks every cell an inflated wall or obstacle touches and no cell
// far from one; cell queries agree with brute force; edits change the generation.
#include "TestRegistry.h"
#include "NavTestMaps.h"

#include "simcore/nav/NavGrid.h"

#include <glm/geometric.hpp>

#include <QTest>

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
    void rasterisationIsConservativeAndTight_data()
    {
        QTest::addColumn<float>("cellM");
        QTest::addColumn<float>("radiusM");
        QTest::newRow("fine cells, walker") << 0.25f << 0.3f;
        QTest::newRow("coarse cells, walker") << 1.0f << 0.3f;
        QTest::newRow("half-metre cells, rider") << 0.5f << 0.9f;
        QTest::newRow("no inflation") << 0.5f << 0.0f;
    }

    void rasterisationIsConservativeAndTight()
    {
        QFETCH(float, cellM);
        QFETCH(float, radiusM);
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
                    if (!grid.walkable({x, z})) {
                        ++blocked;
                        // Tight: a blocked cell holds a point within the inflated shapes.
                        QVERIFY2(clearance(shapes, c) <= radiusM + cellM * 0.7072f, "a cell far from every shape is blocked");
                        continue;
                    }
                    // Conservative: no point of a walkable cell (5 x 5 samples, edges included)
                    // comes within the agent radius of a shape.
                    for (int j = 0; j <= 4; ++j)
                        for (int i = 0; i <= 4; ++i) {
                            const glm::vec2 p = c + (glm::vec2(float(i), float(j)) / 4.0f - 0.5f) * cellM;
                            if (clearance(shapes, p) <= radiusM)
                                QFAIL(qPrintable(QString("walkable cell (%1, %2) has a point %3 m from a shape, radius %4")
                                                     .arg(x).arg(z).arg(clearance(shapes, p)).arg(radiusM)));
                        }
                }
            QVERIFY2(blocked > 0 && blocked < grid.cellCount(), "the random map must block some cells and leave others");
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
