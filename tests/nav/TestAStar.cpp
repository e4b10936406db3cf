// A* finds paths as short as a brute-force Dijkstra on many small random grids, smoothing
// keeps only corners and never crosses a blocked cell, unreachable goals are reported, the
// plan cache shares and re-plans, and the follower helpers behave.
#include "TestRegistry.h"
#include "NavTestMaps.h"

#include "simcore/nav/AStar.h"
#include "simcore/nav/NavFollow.h"
#include "simcore/nav/PlanCache.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <cmath>
#include <random>

using namespace throng::sim;
using namespace throng::test;

class TestAStar : public QObject {
    Q_OBJECT
private slots:
    void pathsAreOptimalOnRandomGrids()
    {
        std::mt19937 gen(17);
        std::uniform_int_distribution<int> size(3, 14);
        std::uniform_real_distribution<float> density(0.0f, 0.45f);
        AStar astar;
        int found = 0, unreachable = 0;
        for (int map = 0; map < 300; ++map) {
            const NavGrid grid = randomGrid(gen, size(gen), size(gen), density(gen));
            std::uniform_int_distribution<int> ux(0, grid.cols() - 1), uz(0, grid.rows() - 1);
            for (int q = 0; q < 6; ++q) {
                const NavCell s{ux(gen), uz(gen)}, t{ux(gen), uz(gen)};
                const NavPlan plan = astar.plan(grid, s, t);
                if (!grid.walkable(s) || !grid.walkable(t)) {
                    QVERIFY(!plan.found());
                    continue;
                }
                const double want = bruteForceDistances(grid, s)[std::size_t(grid.index(t))];
                if (want < 0.0) {
                    QCOMPARE(plan.status, PlanStatus::Unreachable);
                    ++unreachable;
                    continue;
                }
                QVERIFY2(plan.found(), "a reachable goal was not found");
                ++found;
                QVERIFY(legalWalk(grid, plan.cells));
                QCOMPARE(plan.cells.front(), s);
                QCOMPARE(plan.cells.back(), t);
                double walked = 0.0;
                for (std::size_t k = 1; k < plan.cells.size(); ++k)
                    walked += plan.cells[k].x != plan.cells[k - 1].x && plan.cells[k].z != plan.cells[k - 1].z ? std::sqrt(2.0) : 1.0;
                if (std::abs(walked - want) > 1e-9 || std::abs(double(plan.lengthM) - want) > 1e-4)
                    QFAIL(qPrintable(QString("map %1: A* walked %2 cells, reported %3, optimum %4").arg(map).arg(walked).arg(plan.lengthM).arg(want)));
                QVERIFY(plan.smoothedLengthM <= plan.lengthM + 1e-4f);
            }
        }
        qInfo("optimal on %d plans, %d unreachable goals reported", found, unreachable);
        QVERIFY(found > 500 && unreachable > 20);
    }

    void smoothedPathsKeepCornersAndNeverCrossBlockedCells()
    {
        std::mt19937 gen(23);
        AStar astar;
        int plans = 0;
        std::size_t cells = 0, corners = 0;
        for (int map = 0; map < 60; ++map) {
            const NavGrid grid = randomGrid(gen, 40, 30, 0.15f);
            std::uniform_int_distribution<int> ux(0, 39), uz(0, 29);
            for (int q = 0; q < 5; ++q) {
                const NavPlan plan = astar.plan(grid, {ux(gen), uz(gen)}, {ux(gen), uz(gen)});
                if (!plan.found())
                    continue;
                ++plans;
                cells += plan.cells.size();
                corners += plan.corners.size();
                QVERIFY2(polylineStaysWalkable(grid, plan.corners, 0.02f), "a smoothed segment crosses a blocked cell");
                QCOMPARE(plan.waypoints.size() + 1, plan.corners.size());
                QCOMPARE(plan.waypoints.back(), grid.centre(plan.cells.back()));
                // Every kept corner is needed: its neighbours do not see each other.
                for (std::size_t k = 1; k + 1 < plan.corners.size(); ++k)
                    QVERIFY(!lineOfSight(grid, plan.corners[k - 1], plan.corners[k + 1]));
            }
        }
        qInfo("%d plans: %.1f cells and %.1f corners (start and goal included) per plan", plans, double(cells) / plans, double(corners) / plans);
        QVERIFY(plans > 100 && corners * 3 < cells);

        // Open ground: a straight line needs no corner at all.
        const NavGrid open(50, 50, {0, 0}, 1.0f);
        const NavPlan straight = astar.plan(open, {2, 3}, {45, 31});
        QCOMPARE(straight.waypoints.size(), std::size_t(1));
        QVERIFY(std::abs(straight.smoothedLengthM - glm::distance(glm::vec2(2, 3), glm::vec2(45, 31))) < 1e-3f);
    }

    void lineOfSightBetweenPointsMatchesDenseSampling()
    {
        std::mt19937 gen(31);
        std::uniform_real_distribution<float> u(0.0f, 1.0f);
        int clear = 0, blocked = 0;
        for (int map = 0; map < 40; ++map) {
            NavGrid grid = randomGrid(gen, 20, 15, 0.12f);
            for (int q = 0; q < 100; ++q) {
                // Half the queries start and end on cell edges or corners, the hard cases.
                glm::vec2 a(u(gen) * 20.0f, u(gen) * 15.0f), b(u(gen) * 20.0f, u(gen) * 15.0f);
                if (q % 2 == 0) {
                    a = glm::floor(a * 2.0f) * 0.5f;
                    b = glm::floor(b * 2.0f) * 0.5f;
                }
                bool sampledClear = true;
                for (int i = 0; i <= 4000 && sampledClear; ++i) {
                    const glm::vec2 p = a + (b - a) * (float(i) / 4000.0f);
                    sampledClear = grid.walkable(grid.cellOf(p));
                }
                const bool los = lineOfSight(grid, a, b);
                // The exact test is conservative: every sampled point clear whenever it says clear.
                if (los)
                    QVERIFY2(sampledClear, "line of sight through a blocked cell");
                (los ? clear : blocked) += 1;
                // Between cell centres it agrees with the integer walk.
                const NavCell ca = grid.cellOf(a), cb = grid.cellOf(b);
                QCOMPARE(lineOfSight(grid, grid.centre(ca), grid.centre(cb)), lineOfSight(grid, ca, cb));
            }
        }
        qInfo("%d clear and %d blocked sight lines", clear, blocked);
        QVERIFY(clear > 400 && blocked > 400);
    }

    void unreachableGoalsAreReportedNotLooped()
    {
        NavGrid grid(30, 30, {0, 0}, 1.0f);
        for (int k = 10; k <= 20; ++k) {  // a closed ring of blocked cells around (15, 15)
            grid.setWalkable({k, 10}, false);
            grid.setWalkable({k, 20}, false);
            grid.setWalkable({10, k}, false);
            grid.setWalkable({20, k}, false);
        }
        AStar astar;
        QCOMPARE(astar.plan(grid, {2, 2}, {15, 15}).status, PlanStatus::Unreachable);
        QVERIFY(astar.expandedLast() <= 900 - 121);  // only the outside was searched
        QCOMPARE(astar.plan(grid, {15, 15}, {2, 2}).status, PlanStatus::Unreachable);
        QVERIFY(astar.expandedLast() <= 81);
        const NavPlan here = astar.plan(grid, {3, 4}, {3, 4});
        QVERIFY(here.found() && here.cells.size() == 1 && here.waypoints.size() == 1 && here.lengthM == 0.0f);
        QCOMPARE(astar.plan(grid, {10, 10}, {2, 2}).status, PlanStatus::StartBlocked);
        QCOMPARE(astar.plan(grid, {2, 2}, {40, 2}).status, PlanStatus::GoalBlocked);
        // A gap the width of a diagonal does not count: no corner cutting.
        grid.setWalkable({15, 10}, true);
        QVERIFY(astar.plan(grid, {2, 2}, {15, 15}).found());
        grid.setWalkable({15, 10}, false);
        grid.setWalkable({20, 20}, true);  // the ring's corner opens diagonally only
        QCOMPARE(astar.plan(grid, {25, 25}, {15, 15}).status, PlanStatus::Unreachable);
    }

    void plansAreDeterministic()
    {
        std::mt19937 gen(5);
        const NavGrid grid = randomGrid(gen, 60, 60, 0.2f);
        AStar a, b;
        for (int q = 0; q < 20; ++q) {
            const NavCell s{q * 3 % 60, q * 7 % 60}, t{59 - q * 2, 59 - q};
            const NavPlan p1 = a.plan(grid, s, t), p2 = b.plan(grid, s, t), p3 = a.plan(grid, s, t);
            QCOMPARE(p1.cells, p2.cells);
            QCOMPARE(p1.cells, p3.cells);
            QCOMPARE(p1.waypoints, p2.waypoints);
        }
    }

    void planCacheSharesAndReplans()
    {
        NavGrid grid(40, 40, {0, 0}, 1.0f);
        AStar astar;
        PlanCache cache;
        const auto p1 = cache.plan(grid, {1, 1}, {30, 30}, astar);
        const auto p2 = cache.plan(grid, {1, 1}, {30, 30}, astar);
        const auto p3 = cache.plan(grid, {2, 1}, {30, 30}, astar);
        QCOMPARE(p1.get(), p2.get());
        QVERIFY(p3.get() != p1.get());
        QCOMPARE(cache.hits(), std::size_t(1));
        QCOMPARE(cache.misses(), std::size_t(2));
        QCOMPARE(cache.size(), std::size_t(2));
        QVERIFY(p1->found() && p1->waypoints.size() == 1);

        // A wall across the straight line: the cached plan is stale and a new one goes round.
        for (int k = 5; k < 35; ++k)
            grid.setWalkable({k, 40 - k}, false);
        QVERIFY(PlanCache::stale(*p1, grid));
        const auto p4 = cache.plan(grid, {1, 1}, {30, 30}, astar);
        QCOMPARE(cache.invalidations(), std::size_t(1));
        QCOMPARE(cache.size(), std::size_t(1));
        QVERIFY(p4.get() != p1.get() && p4->found() && !PlanCache::stale(*p4, grid));
        QVERIFY(p4->waypoints.size() >= 2);
        QVERIFY(p4->lengthM > p1->lengthM + 1.0f);
        QVERIFY(p1->waypoints.size() == 1);  // holders of the old plan keep it intact
    }

    void planBetweenPointsSnapsToWalkableCells()
    {
        NavGrid grid;
        grid.build(fieldTestScene(1), {0.5f, 0.3f});  // a room with a door in its east wall
        AStar astar;
        PlanCache cache;
        // From a point on the room's west wall (inside its inflated margin) to a goal outside.
        const auto plan = planBetween(cache, grid, {5.0f, 10.0f}, {26.0f, 10.0f}, astar);
        QVERIFY(plan && plan->found());
        QVERIFY(grid.walkable(plan->cells.front()));
        QVERIFY(glm::distance(grid.centre(plan->cells.front()), glm::vec2(5.0f, 10.0f)) < 0.8f);
        QVERIFY(glm::distance(plan->waypoints.back(), glm::vec2(26.0f, 10.0f)) < 0.5f);
        // It leaves by the door: some waypoint lies in the doorway (x near 20, z between 9 and 11).
        bool door = false;
        for (std::size_t k = 0; k + 1 < plan->corners.size(); ++k) {
            const glm::vec2 a = grid.centre(plan->corners[k]), b = grid.centre(plan->corners[k + 1]);
            if ((a.x - 20.0f) * (b.x - 20.0f) <= 0.0f && a.x != b.x) {
                const float z = a.y + (b.y - a.y) * (20.0f - a.x) / (b.x - a.x);
                door = door || (z > 9.0f && z < 11.0f);
            }
        }
        QVERIFY(door);
        QVERIFY(polylineStaysWalkable(grid, plan->corners, 0.02f));
        QCOMPARE(planBetween(cache, grid, {5.1f, 10.1f}, {26.0f, 10.0f}, astar).get(), plan.get());
        QCOMPARE(planBetween(cache, NavGrid(2, 2, {0, 0}, 1.0f), {0.5f, 0.5f}, {1.5f, 1.5f}, astar)->found(), true);
        NavGrid solid(2, 1, {0, 0}, 1.0f);
        solid.setWalkable({0, 0}, false);
        solid.setWalkable({1, 0}, false);
        QVERIFY(planBetween(cache, solid, {0.5f, 0.5f}, {1.5f, 0.5f}, astar) == nullptr);
    }

    void stuckAgentsReplanAroundTheJam()
    {
        // Two ways from west to east round a central block (rows 4 to 13): the passage north
        // of it is a row nearer the start's row 8 than the one south of it.
        NavGrid grid(30, 20, {0, 0}, 1.0f);
        for (int z = 4; z < 14; ++z)
            for (int x = 8; x < 22; ++x)
                grid.setWalkable({x, z}, false);
        AStar astar;
        const NavCell start{2, 8}, goal{27, 8};
        const NavPlan usual = astar.plan(grid, start, goal);
        QVERIFY(usual.found());
        bool north = false;
        for (const NavCell& c : usual.cells)
            north = north || c.z < 4;
        QVERIFY(north);
        // Stuck in the north passage: the re-plan goes south and never through the jam.
        const glm::vec2 jam(15.0f, 2.0f);
        const NavPlan detour = planAround(astar, grid, start, goal, jam, 2.5f);
        QVERIFY(detour.found());
        QCOMPARE(detour.generation, grid.generation());
        for (const NavCell& c : detour.cells) {
            QVERIFY(c.z < 4 ? glm::distance(grid.centre(c), jam) > 2.5f : true);
            QVERIFY(!(c.x >= 13 && c.x <= 17 && c.z < 4));
        }
        QVERIFY(detour.lengthM > usual.lengthM);
        QVERIFY(polylineStaysWalkable(grid, detour.corners, 0.02f));
        // Block the south way too: no way round is reported, and the grid itself is untouched.
        for (int z = 14; z < 20; ++z)
            grid.setWalkable({15, z}, false);
        const auto generation = grid.generation();
        QCOMPARE(planAround(astar, grid, start, goal, jam, 2.5f).status, PlanStatus::Unreachable);
        QCOMPARE(grid.generation(), generation);
        QVERIFY(astar.plan(grid, start, goal).found());
    }

    void followerHelpers()
    {
        float lo = 1e9f, hi = 0.0f;
        for (int k = 0; k <= 100; ++k) {
            const float r = waypointRadiusM(1.0f, float(k) / 100.0f, 0.5f);
            lo = std::min(lo, r);
            hi = std::max(hi, r);
        }
        QCOMPARE(lo, 0.5f);
        QCOMPARE(hi, 1.5f);
        QCOMPARE(waypointRadiusM(2.0f, 0.5f, 0.5f), 2.0f);

        const std::vector<glm::vec2> wp{{0, 0}, {1, 0}, {5, 0}};
        QCOMPARE(advanceWaypoint(wp, 0, {0.5f, 0.0f}, 0.6f), std::size_t(2));
        QCOMPARE(advanceWaypoint(wp, 0, {0.5f, 0.0f}, 0.4f), std::size_t(0));
        QCOMPARE(advanceWaypoint(wp, 2, {5.0f, 0.0f}, 1.0f), std::size_t(2));  // the last one stays

        StallWatch watch;
        int stalls = 0, step = 0;
        for (; step < 100; ++step)  // walking toward the goal at 1 m/s: never stalled
            stalls += updateStall(watch, 100.0f - float(step) * 0.1f, 0.1f) ? 1 : 0;
        QCOMPARE(stalls, 0);
        int firstStall = -1;
        for (int k = 0; k < 100; ++k)  // stuck in place: stalled after 3 s, then again after 3 s more
            if (updateStall(watch, 90.0f, 0.1f)) {
                ++stalls;
                if (firstStall < 0)
                    firstStall = k;
            }
        QVERIFY(firstStall >= 28 && firstStall <= 31);
        QCOMPARE(stalls, 3);
    }
};

THRONG_REGISTER_TEST(TestAStar)
#include "TestAStar.moc"
