// Flow fields: the distance to the exit lies between the straight line and the grid's
// shortest path, a point that follows the field reaches a goal from every walkable cell
// without entering a blocked cell, walled-off cells are left alone, and builds repeat exactly.
#include "TestRegistry.h"
#include "NavTestMaps.h"

#include "simcore/nav/AStar.h"
#include "simcore/nav/FlowField.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <cmath>
#include <cstring>

using namespace throng::sim;
using namespace throng::test;

namespace {

struct FollowFigures {
    int starts = 0, arrived = 0, enteredBlocked = 0;
    float worstDetour = 0.0f;  // walked length / field distance, worst start
};

// A point integrator: moves a quarter cell per step along the sampled field.
FollowFigures followFromEveryCell(const FlowField& field)
{
    const NavGrid& grid = field.grid();
    const float step = 0.25f * grid.cellM();
    FollowFigures f;
    for (int i = 0; i < grid.cellCount(); ++i) {
        const NavCell start = grid.cellAt(i);
        if (!field.reachable(start) || field.isGoal(start))
            continue;
        ++f.starts;
        glm::vec2 p = grid.centre(start);
        const float d0 = field.distanceM(start);
        const int maxSteps = int(3.0f * d0 / step) + 40;
        float walked = 0.0f;
        for (int k = 0; k < maxSteps; ++k) {
            if (field.isGoal(grid.cellOf(p))) {
                ++f.arrived;
                f.worstDetour = std::max(f.worstDetour, walked / d0);
                break;
            }
            p += field.sample(p) * step;
            walked += step;
            if (!grid.walkable(grid.cellOf(p))) {
                ++f.enteredBlocked;
                break;
            }
        }
    }
    return f;
}

}  // namespace

class TestFlowField : public QObject {
    Q_OBJECT
private slots:
    void followersReachTheGoalFromEveryCell_data()
    {
        QTest::addColumn<int>("map");
        QTest::addColumn<float>("cellM");
        QTest::addColumn<QList<float>>("goals");  // x, z, radius triples
        QTest::newRow("open ground, one exit") << 0 << 0.5f << QList<float>{28.0f, 10.0f, 1.0f};
        QTest::newRow("room with a door") << 1 << 0.5f << QList<float>{26.0f, 10.0f, 1.0f};
        QTest::newRow("maze, coarse cells") << 2 << 1.0f << QList<float>{28.0f, 2.0f, 1.5f};
        QTest::newRow("maze, fine cells, three exits") << 2 << 0.25f << QList<float>{28.0f, 2.0f, 1.0f, 1.0f, 19.0f, 0.5f, 15.0f, 18.0f, 1.0f};
    }

    void followersReachTheGoalFromEveryCell()
    {
        QFETCH(int, map);
        QFETCH(float, cellM);
        QFETCH(QList<float>, goals);
        NavGrid grid;
        grid.build(fieldTestScene(map), {cellM, 0.3f});
        std::vector<FlowGoal> exits;
        for (qsizetype k = 0; k + 2 < goals.size(); k += 3)
            exits.push_back({{goals[k], goals[k + 1]}, goals[k + 2]});
        FlowField field;
        field.build(grid, exits);
        const FollowFigures f = followFromEveryCell(field);
        qInfo("%d starts, %d arrived, %d entered a blocked cell, worst walked/distance %.3f", f.starts, f.arrived,
              f.enteredBlocked, double(f.worstDetour));
        QVERIFY(f.starts > 400);
        QCOMPARE(f.enteredBlocked, 0);
        QCOMPARE(f.arrived, f.starts);
        QVERIFY(f.worstDetour < 1.25f);

        // No cell's own direction leads into a blocked cell within half a cell.
        for (int i = 0; i < grid.cellCount(); ++i) {
            const NavCell c = grid.cellAt(i);
            if (!field.reachable(c) || field.isGoal(c))
                continue;
            const glm::vec2 d = field.direction(c);
            QVERIFY(std::abs(glm::length(d) - 1.0f) < 1e-5f);
            QVERIFY(grid.walkable(grid.cellOf(grid.centre(c) + d * (0.5f * cellM))));
        }
    }

    void distanceLiesBetweenStraightLineAndGridPath()
    {
        NavGrid grid;
        grid.build(fieldTestScene(2), {0.5f, 0.3f});
        const glm::vec2 exit(28.0f, 2.0f);
        const NavCell goal = grid.cellOf(exit);
        FlowField field;
        field.build(grid, std::span<const NavCell>(&goal, 1));
        AStar astar;
        float worstOver = 0.0f, worstUnder = 0.0f;
        int checked = 0;
        for (int i = 0; i < grid.cellCount(); i += 7) {
            const NavCell c = grid.cellAt(i);
            if (!field.reachable(c))
                continue;
            const NavPlan plan = astar.plan(grid, c, goal);
            QVERIFY(plan.found());
            const float straight = glm::distance(grid.centre(c), grid.centre(goal));
            worstUnder = std::max(worstUnder, straight - field.distanceM(c));
            worstOver = std::max(worstOver, field.distanceM(c) / std::max(plan.lengthM, 1e-3f));
            ++checked;
        }
        qInfo("%d cells: field distance at most %.3f m under the straight line and %.4f x the 8-connected path",
              checked, double(worstUnder), double(worstOver));
        QVERIFY(checked > 200);
        QVERIFY(worstUnder < 0.01f);
        QVERIFY(worstOver <= 1.05f);
    }

    void severalGoalsActAsTheNearest()
    {
        NavGrid grid;
        grid.build(fieldTestScene(0), {0.5f, 0.3f});
        const NavCell a = grid.cellOf({2.0f, 2.0f}), b = grid.cellOf({27.0f, 17.0f});
        FlowField fa, fb, both;
        fa.build(grid, std::span<const NavCell>(&a, 1));
        fb.build(grid, std::span<const NavCell>(&b, 1));
        const NavCell ab[2] = {a, b};
        both.build(grid, ab);
        // Away from the line where the two fronts meet the two-exit field is the nearer
        // exit's; on that line the marching front blends both, a little shorter.
        float longer = 0.0f, shorter = 0.0f;
        for (int i = 0; i < grid.cellCount(); ++i) {
            const NavCell c = grid.cellAt(i);
            if (!grid.walkable(c))
                continue;
            const float nearer = std::min(fa.distanceM(c), fb.distanceM(c));
            longer = std::max(longer, both.distanceM(c) - nearer);
            shorter = std::max(shorter, nearer - both.distanceM(c));
        }
        qInfo("two exits: at most %.4f m longer and %.4f m shorter than the nearer single exit's", double(longer), double(shorter));
        QVERIFY(longer < 1e-4f);
        QVERIFY(shorter < 0.5f * grid.cellM());
        QVERIFY(both.distanceM(grid.cellOf({5.0f, 3.0f})) < 4.0f && both.distanceM(grid.cellOf({25.0f, 16.0f})) < 4.0f);
    }

    void walledOffCellsHaveNoFlow()
    {
        NavGrid grid;
        Scene scene = fieldTestScene(0);
        scene.walls.push_back({"pen", {{20, 14}, {26, 14}, {26, 19}, {20, 19}, {20, 14}}});
        grid.build(scene, {0.5f, 0.3f});
        FlowField field;
        const FlowGoal exit{{2.0f, 2.0f}, 1.0f};
        field.build(grid, std::span<const FlowGoal>(&exit, 1));
        const NavCell inside = grid.cellOf({23.0f, 16.5f});
        QVERIFY(grid.walkable(inside));
        QVERIFY(!field.reachable(inside));
        QVERIFY(std::isinf(field.distanceM(inside)));
        QCOMPARE(field.sample({23.0f, 16.5f}), glm::vec2(0.0f));
        QCOMPARE(field.sample({-5.0f, 3.0f}), glm::vec2(0.0f));  // outside the grid
        QVERIFY(glm::length(field.sample({10.0f, 10.0f})) > 0.99f);

        FlowField none;  // no goal at all: nowhere to flow, everywhere unreachable
        none.build(grid, std::span<const NavCell>());
        QVERIFY(!none.reachable(grid.cellOf({10.0f, 10.0f})));
        QCOMPARE(none.sample({10.0f, 10.0f}), glm::vec2(0.0f));
        QCOMPARE(FlowField().sample({10.0f, 10.0f}), glm::vec2(0.0f));  // never built
    }

    void buildsAreBitIdentical()
    {
        NavGrid grid;
        grid.build(fieldTestScene(2), {0.5f, 0.3f});
        const FlowGoal exits[2] = {{{28.0f, 2.0f}, 1.0f}, {{1.0f, 19.0f}, 0.5f}};
        FlowField f1, f2;
        f1.build(grid, exits);
        f2.build(grid, exits);
        for (int i = 0; i < grid.cellCount(); ++i) {
            const NavCell c = grid.cellAt(i);
            const float d1 = f1.distanceM(c), d2 = f2.distanceM(c);
            QVERIFY(std::memcmp(&d1, &d2, sizeof d1) == 0);
            QVERIFY(f1.direction(c) == f2.direction(c));
        }
    }
};

THRONG_REGISTER_TEST(TestFlowField)
#include "TestFlowField.moc"
