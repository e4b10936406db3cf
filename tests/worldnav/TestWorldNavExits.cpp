// Flow fields and exits: flow-field walkers placed on every walkable cell of a small maze
// all leave through its exit, and agents that leave are counted, frozen and no longer
// part of the scene (the stats report them; nobody overlaps them any more).
#include "NavRig.h"
#include "TestRegistry.h"

#include "simcore/world/RunStats.h"

#include <glm/geometric.hpp>

#include <QTest>

using namespace throng::sim;
using throng::test::outCount;
using throng::test::parse;
using throng::test::runUntil;

namespace {

// A 10 m square hall with an east door (z in [-1, 1]) and four inner walls that make a
// serpentine of 2 m corridors; the exit's disk lies just outside the door.
const char* kMaze = R"(throng: 1
settings: {fps: 24, bounds: {min: [-7, -7], max: [8, 7]}, nav_cell: 0.5}
agent_types:
  - {name: walker, radius: 0.2, navigation: flow_field, behaviours: {arrival: 1, separation: 1}}
walls:
  - {points: [[5, 1], [5, 5], [-5, 5], [-5, -5], [5, -5], [5, -1]]}
  - {points: [[-3, -5], [-3, 3]]}
  - {points: [[-1, 5], [-1, -3]]}
  - {points: [[1, -5], [1, 3]]}
  - {points: [[3, 5], [3, -3]]}
goals:
  - {name: exit, position: [6, 0], radius: 1, exit: true}
)";

}  // namespace

class TestWorldNavExits : public QObject {
    Q_OBJECT
private slots:
    void flowFollowersFromEveryWalkableCellLeave()
    {
        // The grid the World builds for this maze tells which cells are walkable.
        const World probe(parse(std::string(kMaze) + "agents: [{type: walker, position: [-4, -4], goal: exit}]\n"));
        const NavGrid& grid = probe.navigation().grid;
        const FlowField& field = probe.navigation().fields[0];
        std::string yaml = std::string(kMaze) + "agents:\n";
        int placed = 0;
        for (int z = 0; z < grid.rows(); ++z)
            for (int x = 0; x < grid.cols(); ++x) {
                const NavCell c{x, z};
                const glm::vec2 p = grid.centre(c);
                if (!grid.walkable(c) || std::fabs(p.x) > 5.0f || std::fabs(p.y) > 5.0f)
                    continue;
                QVERIFY2(field.reachable(c), "every walkable cell of the hall leads to the exit");
                yaml += "  - {type: walker, position: [" + std::to_string(p.x) + ", " + std::to_string(p.y) +
                        "], goal: exit}\n";
                ++placed;
            }
        QVERIFY2(placed > 100, qPrintable(QString::number(placed)));
        World world(parse(yaml));
        runUntil(world, 300.0, [&](const World& w) { return outCount(w) == std::size_t(placed); });
        QCOMPARE(outCount(world), std::size_t(placed));
        QCOMPARE(world.counters().wallPenetrations, std::uint64_t(0));
        QCOMPARE(world.counters().nonFiniteValues, std::uint64_t(0));
    }

    void aWalkerInAPillarsMarginGoesOnNotBack()
    {
        // A pillar's margin on the navigation grid (cells whose centres lie within the body's
        // radius and 0.15 m of it) is wider than the pillar: a walker on the field's diagonal cuts a
        // corner of it. It was sent back to the nearest walkable cell, behind it; there the
        // field sent it on across the same corner, and it stood on the cells' edge for good
        // (the last of 20,000 in the evacuation demo). Now it goes into the walkable cell
        // next to it that is nearest the goal. Tried from every margin cell round the
        // pillar where the nearest walkable cell lies behind: each walker's first aim is
        // onward, and each leaves.
        const std::string hall = R"(throng: 1
settings: {fps: 24, bounds: {min: [-10, -10], max: [30, 10]}, nav_cell: 0.5}
agent_types:
  - {name: walker, radius: 0.25, navigation: flow_field, behaviours: {arrival: 1, separation: 1.5, obstacle_avoidance: 1}}
walls:
  - {points: [[25, -5], [25, -9], [-9, -9], [-9, 9], [25, 9], [25, 5]]}
obstacles:
  - {shape: circle, center: [5.48, 1.2], radius: 0.6}
goals:
  - {name: exit, position: [27, 0], radius: 5, exit: true}
)";
        // The grid blocks a cell whose centre lies within 0.6 + 0.25 + 0.15 m of the pillar's;
        // the pillar sits where five cells' centres fall between that and the body's reach.
        const glm::vec2 pillar(5.48f, 1.2f);
        const World probe(parse(hall + "agents: [{type: walker, position: [0, 0], goal: exit}]\n"));
        const NavGrid& grid = probe.navigation().grid;
        const FlowField& field = probe.navigation().fields[0];
        int tried = 0;
        for (int z = 0; z < grid.rows(); ++z)
            for (int x = 0; x < grid.cols(); ++x) {
                const NavCell c{x, z};
                const glm::vec2 p = grid.centre(c);
                if (grid.walkable(c) || glm::distance(p, pillar) < 0.6f + 0.25f + 0.02f ||
                    glm::distance(p, pillar) > 2.0f)
                    continue;  // a margin cell round the pillar whose centre the body fits on
                NavCell onward = c;
                float onwardM = INFINITY;
                for (int dz = -1; dz <= 1; ++dz)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const NavCell n{x + dx, z + dz};
                        if (grid.walkable(n) && field.reachable(n) && field.distanceM(n) < onwardM) {
                            onwardM = field.distanceM(n);
                            onward = n;
                        }
                    }
                const NavCell nearest = grid.nearestWalkable(c);
                if (!(onwardM < field.distanceM(nearest) - 0.25f))
                    continue;  // the nearest walkable cell is not behind
                ++tried;
                World world(parse(hall + "agents: [{type: walker, position: [" + std::to_string(p.x) + ", " +
                                  std::to_string(p.y) + "], goal: exit}]\n"));
                world.step();
                const WorldNav& nav = world.navigation();
                QVERIFY(nav.hasTarget[0]);
                const glm::vec2 aim = glm::normalize(nav.target[0] - p), ahead = glm::normalize(grid.centre(onward) - p);
                QVERIFY2(glm::dot(aim, ahead) > 0.99f,
                         qPrintable(QString("from (%1, %2) it aims (%3, %4), not onward (%5, %6)")
                                        .arg(p.x).arg(p.y).arg(aim.x).arg(aim.y).arg(ahead.x).arg(ahead.y)));
                runUntil(world, 60.0, [](const World& w) { return outCount(w) == 1; });
                QCOMPARE(outCount(world), std::size_t(1));
            }
        qInfo("%d margin cells round the pillar whose nearest walkable cell lies behind", tried);
        QVERIFY(tried >= 2);
    }

    void agentsThatLeaveAreCountedAndGone()
    {
        // 30 direct walkers crowd through one 2 m exit in an open set.
        World world(parse(R"(throng: 1
settings: {fps: 24, bounds: {min: [-20, -20], max: [20, 20]}}
agent_types:
  - {name: walker, behaviours: {arrival: 1, separation: 1}}
goals:
  - {name: gate, position: [10, 0], radius: 1, exit: true}
  - {name: bench, position: [-10, 0], radius: 1}
groups:
  - {name: leavers, type: walker, count: 30, rect: {min: [-4, -4], max: [4, 4]}, goal: gate}
  - {name: sitters, type: walker, count: 5, rect: {min: [-12, -2], max: [-8, 2]}, goal: bench}
)"));
        runUntil(world, 120.0, [](const World& w) { return outCount(w) == 30; });
        QCOMPARE(outCount(world), std::size_t(30));
        for (std::size_t i = 0; i < world.agentCount(); ++i)
            QCOMPARE(world.isOut(i), world.goalIndex(i) == 0);  // the bench is no exit

        // Gone: they stand where they left, and the pile at the gate is no overlap.
        const std::vector<glm::vec3> before(world.positions().begin(), world.positions().end());
        const std::uint64_t overlaps = world.counters().overlappingPairs;
        for (int s = 0; s < 120; ++s)
            world.step();
        for (std::size_t i = 0; i < 30; ++i)
            QCOMPARE(world.positions()[i], before[i]);
        QCOMPARE(world.counters().overlappingPairs, overlaps);

        const RunStats stats = RunStats::from(world, world.stepIndex() + 1, 1.0);
        QCOMPARE(stats.nav.agentsOut, std::uint64_t(30));
        QCOMPARE(stats.nav.exitAgents, std::uint64_t(30));
        QVERIFY(stats.nav.timeTo99PercentOutS > 0.0 && stats.nav.timeTo99PercentOutS < 120.0);
        QCOMPARE(stats.nav.exits.size(), std::size_t(1));
        QCOMPARE(stats.nav.exits[0].doorWidthM, 2.0);
        // 30 people through 2 m: a few persons per metre per second at most.
        QVERIFY(stats.nav.exits[0].flowPerMetrePerSecond > 0.1 && stats.nav.exits[0].flowPerMetrePerSecond < 5.0);
        const std::string json = stats.toJson();
        QVERIFY(json.find("\"agents_out\": 30,") != std::string::npos);
        QVERIFY(json.find("\"fraction_out\": 1,") != std::string::npos);
        QVERIFY(json.find("\"flow_per_metre_per_second\": ") != std::string::npos);
    }

    void steadyOutflowLeavesOutTheEnds()
    {
        // One person a second for 100 s, plus a straggler 60 s later: 1 per second.
        std::vector<float> times;
        for (int k = 0; k < 100; ++k)
            times.push_back(float(k));
        times.push_back(160.0f);
        QCOMPARE(steadyOutflowPerSecond(times), 1.0);
        QVERIFY(steadyOutflowPerSecond({1.0f, 2.0f, 3.0f}) < 0.0);
    }
};

THRONG_REGISTER_TEST(TestWorldNavExits)
#include "TestWorldNavExits.moc"
