// Exit choice (issue 26, RiMEA test 11): a group's walkers choose among its `exits` the one
// each expects to leave by soonest. Checked from the positions: a lone walker takes the
// nearer exit; a crowd at a narrow exit sends its back rows to a farther one while its
// front rows stay, and empties sooner than when all take the near one; the stats' count
// per exit matches a recount from where each walker went out; direct walkers choose too;
// the same choices for any thread count and after a checkpoint, and alike at 24, 30 and
// 60 fps; a source's agents choose as they enter; the file keeps the key and refuses what
// cannot be chosen, with its line.
#include "TestRegistry.h"

#include "simcore/io/SceneIO.h"
#include "simcore/world/RunStats.h"
#include "simcore/world/World.h"
#include "simcore/world/WorldState.h"

#include <QTest>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

using namespace throng;
using namespace throng::sim;

namespace {

Scene parseChoice(const std::string& yaml)
{
    const LoadResult r = parseScene(yaml, "choice.yaml", "");
    if (!r.ok())
        qFatal("%s", r.diagnostics[0].format().c_str());
    return r.scene;
}

// A hall 30 m x 16 m with a door 1 m wide in its west wall (west) and one in its east wall
// (east); `count` walkers of `navigation` spread over `rect`, choosing between the doors.
std::string hall(int count, const char* rect, const char* navigation = "flow_field", const char* exits = "[west, east]")
{
    std::ostringstream y;
    y << "throng: 1\nsettings: {fps: 24, seed: 4, duration: 600, bounds: {min: [-3, -9], max: [33, 9]}, "
         "nav_cell: 0.25}\n"
         "agent_types:\n  - {name: walker, radius: 0.2, max_speed: 1.3, variation: {speed: [1, 1]}, navigation: "
      << navigation
      << "}\n"
         "walls:\n"
         "  - {points: [[0, -0.5], [0, -8], [30, -8], [30, -0.5]]}\n"
         "  - {points: [[0, 0.5], [0, 8], [30, 8], [30, 0.5]]}\n"
         "goals:\n"
         "  - {name: west, position: [0, 0], radius: 0.5, exit: true}\n"
         "  - {name: east, position: [30, 0], radius: 0.5, exit: true}\n"
         "groups:\n"
         "  - {name: crowd, type: walker, count: "
      << count << ", rect: " << rect << ", exits: " << exits << "}\n";
    return y.str();
}

// Where each walker went out (0 west, 1 east: the nearer door to its position on the step it
// left; -1: still in), stepping the World until all are out or limitS.
std::vector<int> doorsTaken(World& world, double limitS)
{
    std::vector<int> door(world.agentCount(), -1);
    std::size_t out = 0;
    while (out < door.size() && world.timeS() < limitS) {
        world.step();
        for (std::size_t i = 0; i < door.size(); ++i)
            if (door[i] < 0 && world.isOut(i)) {
                door[i] = world.positions()[i].x < 15.0f ? 0 : 1;
                ++out;
            }
    }
    return door;
}

}  // namespace

class TestExitChoice : public QObject {
    Q_OBJECT

private slots:
    // With no one else about, each walker takes its nearer door, by flow field or straight.
    void aLoneWalkerTakesTheNearerExit_data()
    {
        QTest::addColumn<QString>("navigation");
        QTest::newRow("flow field") << "flow_field";
        QTest::newRow("a star") << "astar";
        QTest::newRow("direct") << "direct";
    }
    void aLoneWalkerTakesTheNearerExit()
    {
        QFETCH(QString, navigation);
        for (const char* rect : {"{min: [5, -1], max: [6, 1]}", "{min: [24, -1], max: [25, 1]}"}) {
            World world(parseChoice(hall(1, rect, navigation.toUtf8().constData())));
            const int nearer = world.positions()[0].x < 15.0f ? 0 : 1;
            QCOMPARE(world.goalIndex(0), nearer);
            const std::vector<int> door = doorsTaken(world, 60.0);
            QCOMPARE(door[0], nearer);
        }
    }

    // 400 walkers 6 to 12 m from the west door and 18 to 24 m from the east one: the front
    // rows leave by the west door, the queue there sends others east, and the hall empties
    // sooner than when every one of them takes the west door. The stats count each door's
    // walkers as the positions do.
    void aQueueSendsOthersToTheFarExit()
    {
        const std::string yaml = hall(400, "{min: [6, -7.5], max: [12, 7.5]}");
        const Scene s = parseChoice(yaml);
        World world(s);
        std::vector<float> startX;
        for (const glm::vec3& p : world.positions())
            startX.push_back(p.x);
        std::size_t east = 0;
        for (std::size_t i = 0; i < world.agentCount(); ++i)
            east += world.goalIndex(i) == 1 ? 1 : 0;
        QVERIFY2(east > 40 && east < 360, qPrintable(QString::number(east)));  // chosen from the start
        std::uint64_t steps = 0;
        std::vector<int> door(world.agentCount(), -1);
        std::size_t out = 0;
        while (out < door.size() && world.timeS() < 600.0) {
            world.step();
            ++steps;
            for (std::size_t i = 0; i < door.size(); ++i)
                if (door[i] < 0 && world.isOut(i)) {
                    door[i] = world.positions()[i].x < 15.0f ? 0 : 1;
                    ++out;
                }
        }
        QCOMPARE(out, door.size());
        const double choosingS = world.timeS();
        std::size_t byWest = 0, frontWest = 0, front = 0;
        for (std::size_t i = 0; i < door.size(); ++i) {
            byWest += door[i] == 0 ? 1 : 0;
            if (startX[i] < 7.5f) {  // the front rows, 6 to 7.5 m from the west door
                ++front;
                frontWest += door[i] == 0 ? 1 : 0;
            }
        }
        const std::size_t byEast = door.size() - byWest;
        QVERIFY2(byEast >= 40 && byWest >= 40, qPrintable(QString("%1 west, %2 east").arg(byWest).arg(byEast)));
        QVERIFY2(front > 50 && 10 * frontWest >= 9 * front, qPrintable(QString("%1 of %2").arg(frontWest).arg(front)));
        const RunStats stats = RunStats::from(world, steps + 1, 0.0);
        QCOMPARE(stats.nav.exits.size(), std::size_t(2));
        QCOMPARE(stats.nav.exits[0].agentsOut, std::uint64_t(byWest));
        QCOMPARE(stats.nav.exits[1].agentsOut, std::uint64_t(byEast));

        Scene allWest = s;
        allWest.groups[0].exits.clear();
        allWest.groups[0].goal = "west";
        World west(allWest);
        const std::vector<int> doors = doorsTaken(west, 600.0);
        QVERIFY(std::count(doors.begin(), doors.end(), 0) == std::ptrdiff_t(doors.size()));
        qInfo("%zu west, %zu east (front rows %zu of %zu west); out after %.1f s, %.1f s all by the west door", byWest,
              byEast, frontWest, front, choosingS, west.timeS());
        QVERIFY2(choosingS < 0.8 * west.timeS(),
                 qPrintable(QString("%1 s against %2 s").arg(choosingS).arg(west.timeS())));
    }

    // The same hall at 24, 30 and 60 fps: rounds of choices come every half second of
    // simulated time whatever the frame rate, so the crowd splits and empties alike (within
    // 10 % of the walkers and 5 % of the time).
    void frameRatesAgree()
    {
        std::size_t eastAt24 = 0;
        double timeAt24 = 0.0;
        for (const int fps : {24, 30, 60}) {
            std::string yaml = hall(300, "{min: [6, -7.5], max: [12, 7.5]}");
            yaml.replace(yaml.find("fps: 24"), 7, "fps: " + std::to_string(fps));
            World world(parseChoice(yaml));
            const std::vector<int> door = doorsTaken(world, 600.0);
            QVERIFY(std::count(door.begin(), door.end(), -1) == 0);
            const std::size_t east = std::size_t(std::count(door.begin(), door.end(), 1));
            qInfo("%d fps: %zu of 300 east, out after %.1f s", fps, east, world.timeS());
            if (fps == 24) {
                eastAt24 = east;
                timeAt24 = world.timeS();
                QVERIFY(east > 30 && east < 270);
                continue;
            }
            QVERIFY2(std::abs(double(east) - double(eastAt24)) <= 30.0,
                     qPrintable(QString("%1 against %2").arg(east).arg(eastAt24)));
            QVERIFY2(std::abs(world.timeS() - timeAt24) <= 0.05 * timeAt24,
                     qPrintable(QString("%1 s against %2 s").arg(world.timeS()).arg(timeAt24)));
        }
    }

    // A source's agents choose as they enter: the first ones, with no queue yet, the nearer
    // door (listed second) on the step they come in; a stream faster than that door lets out sends later
    // ones to the far door; all leave, and the stats count each door as the positions do.
    void aStreamChoosesAsItEnters()
    {
        std::string yaml = hall(0, "{min: [6, -1], max: [8, 1]}");
        yaml.replace(yaml.find("groups:"), std::string::npos,
                     "sources:\n  - {name: hall_door, type: walker, line: [[8, -6], [8, 6]], rate: 6, cap: 240, "
                     "exits: [east, west]}\n");  // the far door first: the choice, not the order, sends them west
        World world(parseChoice(yaml));
        QCOMPARE(world.agentCount(), std::size_t(240));
        std::vector<int> chosenOnEntry(world.agentCount(), -1), door(world.agentCount(), -1);
        std::uint64_t steps = 0;
        std::size_t out = 0;
        while (out < door.size() && world.timeS() < 400.0) {
            world.step();
            ++steps;
            for (std::size_t i = 0; i < door.size(); ++i) {
                if (chosenOnEntry[i] < 0 && !world.isOffstage(i))
                    chosenOnEntry[i] = world.goalIndex(i);
                if (door[i] < 0 && world.isOut(i)) {
                    door[i] = world.positions()[i].x < 15.0f ? 0 : 1;
                    ++out;
                }
            }
        }
        QCOMPARE(out, door.size());
        for (std::size_t i = 0; i < 5; ++i)
            QCOMPARE(chosenOnEntry[i], 0);  // the first arrivals: the west door, 8 m off
        const std::size_t east = std::size_t(std::count(door.begin(), door.end(), 1));
        QVERIFY2(east >= 40 && east <= 200, qPrintable(QString::number(east)));
        const RunStats stats = RunStats::from(world, steps + 1, 0.0);
        QCOMPARE(stats.nav.exits[0].agentsOut, std::uint64_t(door.size() - east));
        QCOMPARE(stats.nav.exits[1].agentsOut, std::uint64_t(east));
        qInfo("%zu of %zu by the far door", east, door.size());
    }

    // A group whose type's brain picks goals (an output.goal node, here inside a macro brain)
    // follows its brain, not an exit choice: loading warns, and every member goes where the
    // brain sends it (the far door) whatever the queue.
    void aBrainThatPicksGoalsWins()
    {
        std::string yaml = hall(40, "{min: [6, -3], max: [9, 3]}");
        yaml.replace(yaml.find("navigation: flow_field}"), 23, "navigation: flow_field, brain: sender}");
        yaml += "brains:\n"
                "  - name: sender\n"
                "    nodes:\n"
                "      - {id: 1, type: input.constant, params: {value: 1}}\n"
                "      - {id: 2, type: macro, params: {brain: east_picker}}\n"
                "    links:\n"
                "      - {from: [1, 0], to: [2, 0]}\n"
                "  - name: east_picker\n"
                "    nodes:\n"
                "      - {id: 1, type: macro.in, params: {port: 0}}\n"
                "      - {id: 2, type: input.constant, params: {value: 0}}\n"
                "      - {id: 3, type: output.goal, params: {goals: \"east west\"}}\n"
                "    links:\n"
                "      - {from: [1, 0], to: [3, 0]}\n"
                "      - {from: [2, 0], to: [3, 1]}\n";
        const LoadResult r = parseScene(yaml, "choice.yaml", "");
        QVERIFY2(r.ok(), r.diagnostics.empty() ? "" : r.diagnostics[0].format().c_str());
        QCOMPARE(r.diagnostics.size(), std::size_t(1));
        QCOMPARE(r.diagnostics[0].severity, Severity::Warning);
        QVERIFY2(r.diagnostics[0].format().find("picks its agents' goals") != std::string::npos,
                 r.diagnostics[0].format().c_str());
        World world(r.scene);
        QVERIFY2(world.brainErrors().empty(), world.brainErrors().empty() ? "" : world.brainErrors()[0].c_str());
        const std::vector<int> door = doorsTaken(world, 300.0);
        QCOMPARE(std::count(door.begin(), door.end(), 1), std::ptrdiff_t(40));  // all east, as the brain says
    }

    // One thread or two (each with chunks to run), the same choices and positions; and a
    // checkpoint resumed gives the run that went on. 3,000 walkers in a yard 80 m across
    // with an exit on each side, so that a loaded machine still hands the second thread
    // some chunks.
    void threadsAndCheckpointsAgree()
    {
        const Scene s = parseChoice(
            "throng: 1\nsettings: {fps: 24, seed: 4, duration: 600, bounds: {min: [-45, -45], max: [45, 45]}, "
            "nav_cell: 0.5}\n"
            "agent_types:\n  - {name: walker, radius: 0.2, max_speed: 1.3, navigation: flow_field}\n"
            "goals:\n"
            "  - {name: west, position: [-40, 0], radius: 1, exit: true}\n"
            "  - {name: east, position: [40, 0], radius: 1, exit: true}\n"
            "  - {name: north, position: [0, -40], radius: 1, exit: true}\n"
            "groups:\n"
            "  - {name: crowd, type: walker, count: 3000, rect: {min: [-30, -20], max: [10, 20]}, "
            "exits: [west, east, north]}\n");
        World one(s, WorldOptions{0, false, 1}), two(s, WorldOptions{0, false, 2});
        QCOMPARE(two.threads(), 2);
        for (int k = 0; k < 10 * 24; ++k) {
            one.step();
            two.step();
        }
        for (const std::uint64_t chunks : two.team().chunksRun())
            QVERIFY2(chunks > 0, "a thread ran no chunk");
        for (std::size_t i = 0; i < one.agentCount(); ++i) {
            QCOMPARE(two.goalIndex(i), one.goalIndex(i));
            QCOMPARE(two.positions()[i], one.positions()[i]);
        }
        const WorldState at10 = one.saveState();
        for (int k = 0; k < 10 * 24; ++k)
            one.step();
        World resumed(s);
        resumed.restoreState(at10);
        for (int k = 0; k < 10 * 24; ++k)
            resumed.step();
        for (std::size_t i = 0; i < one.agentCount(); ++i) {
            QCOMPARE(resumed.goalIndex(i), one.goalIndex(i));
            QCOMPARE(resumed.positions()[i], one.positions()[i]);
        }
    }

    // The key reads and writes back; fewer than two exits, a goal that is not an exit or does
    // not exist, one listed twice, and exits with a goal too are refused, naming the line.
    void theFileKeepsAndChecksTheKey()
    {
        std::string withSource = hall(3, "{min: [6, -1], max: [8, 1]}");
        withSource += "sources:\n  - {name: door, type: walker, line: [[8, -6], [8, 6]], rate: 1, exits: [east, west]}\n";
        const Scene s = parseChoice(withSource);
        QCOMPARE(s.groups[0].exits, (std::vector<std::string>{"west", "east"}));
        QCOMPARE(s.sources[0].exits, (std::vector<std::string>{"east", "west"}));
        const std::string written = sceneToYaml(s);
        QVERIFY2(written.find("exits: [west, east]") != std::string::npos, written.c_str());
        QVERIFY2(written.find("exits: [east, west]") != std::string::npos, written.c_str());
        QVERIFY(parseChoice(written).groups == s.groups);
        QVERIFY(parseChoice(written).sources == s.sources);
        // A source with exits and a goal too is refused, naming both.
        std::string both = withSource;
        both.replace(both.find("exits: [east, west]"), 19, "goal: east, exits: [east, west]");
        const LoadResult twice = parseScene(both, "choice.yaml", "");
        QVERIFY(!twice.ok());
        QVERIFY2(twice.diagnostics[0].format().find("no goal or path too") != std::string::npos,
                 twice.diagnostics[0].format().c_str());
        struct Bad {
            const char* exits;
            const char* message;
        };
        for (const Bad& bad : {Bad{"[west]", "at least two exits"}, Bad{"[west, door]", "no goal named 'door'"},
                               Bad{"[west, west]", "listed twice"}, Bad{"[west, east], goal: east", "no goal, path"},
                               Bad{"[west, hall]", "not an exit"}}) {
            std::string yaml = hall(3, "{min: [6, -1], max: [8, 1]}", "flow_field", bad.exits);
            yaml.replace(yaml.find("goals:\n"), 7, "goals:\n  - {name: hall, position: [15, 0], radius: 1}\n");
            const LoadResult r = parseScene(yaml, "choice.yaml", "");
            QVERIFY2(!r.ok(), bad.exits);
            QVERIFY2(r.diagnostics[0].format().find(bad.message) != std::string::npos &&
                         r.diagnostics[0].format().find("choice.yaml:13") != std::string::npos,
                     r.diagnostics[0].format().c_str());
        }
    }
};

THRONG_REGISTER_TEST(TestExitChoice)
#include "TestExitChoice.moc"
