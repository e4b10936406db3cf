// Reaction times (issue 26, RiMEA test 5): a walker whose type sets `variation.reaction`
// stands where it starts for a time drawn from that range, then sets off. Read from the
// positions: nobody moves before its time, and each one moves within a step after it; the
// times are drawn per walker within the range, the same at any frame rate and thread count;
// a walker walks round one still waiting instead of taking it for the pile at its goal; a
// checkpoint and an edit keep who still waits; the file keeps the key and refuses bad ones.
#include "TestRegistry.h"

#include "simcore/io/SceneIO.h"
#include "simcore/world/World.h"
#include "simcore/world/WorldState.h"

#include <QTest>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

using namespace throng;
using namespace throng::sim;

namespace {

Scene parseReactions(const std::string& yaml)
{
    const LoadResult r = parseScene(yaml, "reactions.yaml", "");
    if (!r.ok())
        qFatal("%s", r.diagnostics[0].format().c_str());
    return r.scene;
}

// A square room with a door on its west side: `count` walkers who react in [lo, hi] s and
// four who set off at once, all for the door.
std::string room(float lo, float hi, int count = 12, float fps = 24.0f)
{
    std::ostringstream y;
    y << "throng: 1\nsettings: {fps: " << fps
      << ", seed: 3, duration: 60, bounds: {min: [-12, -12], max: [12, 12]}}\n"
         "agent_types:\n"
         "  - {name: slow, radius: 0.2, max_speed: 1.3, variation: {reaction: ["
      << lo << ", " << hi
      << "]}}\n"
         "  - {name: quick, radius: 0.2, max_speed: 1.3}\n"
         "goals:\n  - {name: door, position: [-10, 0], radius: 1, exit: true}\n"
         "groups:\n"
         "  - {name: waiting, type: slow, count: "
      << count
      << ", rect: {min: [2, -6], max: [8, 6]}, goal: door}\n"
         "  - {name: going, type: quick, count: 4, rect: {min: [2, -6], max: [8, 6]}, goal: door}\n";
    return y.str();
}

// When each agent first moved from where it started (-1: never), stepping `world` to
// `seconds`. A walker that waits stands exactly where it stood.
std::vector<double> firstMoves(World& world, double seconds)
{
    const std::vector<glm::vec3> start(world.positions().begin(), world.positions().end());
    std::vector<double> moved(world.agentCount(), -1.0);
    while (world.timeS() < seconds - 1e-9) {
        world.step();
        for (std::size_t i = 0; i < moved.size(); ++i)
            if (moved[i] < 0.0 && world.positions()[i] != start[i])
                moved[i] = world.timeS();
    }
    return moved;
}

// Whether a walker that first moved on the step of `dt` that ended at `moved` set off on the
// first step at or after its time `due` on which walkers decide: at 24 fps every step, at
// higher rates the first step at or after each 24th of a second (StepRate.h), so at most a
// step past the next 24th.
bool onTheStepAfter(double moved, double due, double dt)
{
    const double stepStart = moved - dt, slack = dt < 1.0 / 24.0 - 1e-9 ? 1.0 / 24.0 + dt : dt;
    return stepStart >= due - 1e-9 && stepStart < due + slack - 1e-9;
}

}  // namespace

class TestReactionTimes : public QObject {
    Q_OBJECT

private slots:
    // Each waiting walker stands still until its own time and moves on the first step that
    // starts at or after it; the others move at once. The times lie in the range and differ from walker to walker.
    void eachWalkerSetsOffAtItsOwnTime()
    {
        const Scene s = parseReactions(room(2.0f, 8.0f));
        World world(s);
        QCOMPARE(world.agentCount(), std::size_t(16));
        std::set<double> times;
        for (std::size_t i = 0; i < 12; ++i) {
            QVERIFY(world.isUnstarted(i));
            const double t = world.startTimeS(i);
            QVERIFY2(t >= 2.0 && t <= 8.0, qPrintable(QString::number(t)));
            times.insert(t);
        }
        QCOMPARE(times.size(), std::size_t(12));
        QVERIFY(*times.begin() < 4.0 && *times.rbegin() > 6.0);  // spread over the range
        for (std::size_t i = 12; i < 16; ++i) {
            QVERIFY(!world.isUnstarted(i));
            QCOMPARE(world.startTimeS(i), 0.0);
        }
        const std::vector<double> moved = firstMoves(world, 12.0);
        for (std::size_t i = 0; i < 12; ++i) {
            const double t = world.startTimeS(i);
            QVERIFY2(onTheStepAfter(moved[i], t, 1.0 / 24.0),
                     qPrintable(QString("walker %1: due %2 s, moved %3 s").arg(i).arg(t).arg(moved[i])));
            QVERIFY(!world.isUnstarted(i));
        }
        for (std::size_t i = 12; i < 16; ++i)
            QVERIFY2(moved[i] > 0.0 && moved[i] < 0.5, qPrintable(QString::number(moved[i])));
    }

    // The times are drawn by walker, not by step: the same at 24 and at 60 fps, and each
    // walker sets off on the first decision at or after its time at either.
    void frameRatesAgree()
    {
        World at24(parseReactions(room(1.0f, 5.0f, 12, 24.0f)));
        World at60(parseReactions(room(1.0f, 5.0f, 12, 60.0f)));
        for (std::size_t i = 0; i < 12; ++i)
            QCOMPARE(at60.startTimeS(i), at24.startTimeS(i));
        const std::vector<double> moved24 = firstMoves(at24, 8.0), moved60 = firstMoves(at60, 8.0);
        for (std::size_t i = 0; i < 12; ++i) {
            const double t = at24.startTimeS(i);
            QVERIFY(onTheStepAfter(moved24[i], t, 1.0 / 24.0));
            QVERIFY2(onTheStepAfter(moved60[i], t, 1.0 / 60.0),
                     qPrintable(QString("due %1 s, moved %2 s").arg(t).arg(moved60[i])));
            // On the same 24th of a second at either rate.
            QVERIFY(std::abs(moved60[i] - moved24[i]) < 1.0 / 24.0 + 1.0 / 60.0);
        }
    }

    // One thread or two (each with chunks to run), the same positions: 3,000 walkers over a
    // square of 60 m, so that a loaded machine still hands the second thread some chunks.
    void threadCountsAgree()
    {
        std::string yaml = room(0.5f, 9.0f, 3000);
        auto swap = [&yaml](const std::string& from, const std::string& to) {
            QVERIFY(yaml.find(from) != std::string::npos);
            yaml.replace(yaml.find(from), from.size(), to);
        };
        swap("max: [12, 12]", "max: [40, 40]");
        swap("min: [-12, -12]", "min: [-40, -40]");
        swap("count: 3000, rect: {min: [2, -6], max: [8, 6]}", "count: 3000, rect: {min: [-30, -30], max: [30, 30]}");
        const Scene s = parseReactions(yaml);
        World one(s, WorldOptions{0, false, 1}), two(s, WorldOptions{0, false, 2});
        QCOMPARE(two.threads(), 2);
        for (int k = 0; k < 5 * 24; ++k) {
            one.step();
            two.step();
        }
        for (const std::uint64_t chunks : two.team().chunksRun())
            QVERIFY2(chunks > 0, "a thread ran no chunk");
        std::size_t waiting = 0;
        for (std::size_t i = 0; i < one.agentCount(); ++i) {
            QCOMPARE(two.positions()[i], one.positions()[i]);
            waiting += one.isUnstarted(i) ? 1 : 0;
        }
        QVERIFY(waiting > 0 && waiting < 3000);  // some still wait, some have set off
    }

    // A walker whose way to the goal passes one still waiting for the same goal walks round
    // it and arrives: the waiting one is not the pile of those who already arrived. And the
    // waiting one stays where it stands until its time, whoever passes.
    void othersWalkRoundOneStillWaiting()
    {
        const Scene s = parseReactions("throng: 1\n"
                                       "settings: {fps: 24, seed: 1, duration: 60, "
                                       "bounds: {min: [-5, -5], max: [15, 5]}}\n"
                                       "agent_types:\n"
                                       "  - {name: waiter, radius: 0.3, max_speed: 1.3, "
                                       "variation: {reaction: [30, 30]}}\n"
                                       "  - {name: walker, radius: 0.3, max_speed: 1.3}\n"
                                       "goals:\n  - {name: g, position: [10, 0], radius: 1}\n"
                                       "agents:\n"
                                       "  - {id: 1, type: waiter, position: [5, 0], goal: g}\n"
                                       "  - {id: 2, type: walker, position: [0, 0.05], goal: g}\n");
        World world(s);
        QCOMPARE(world.startTimeS(0), 30.0);
        const glm::vec3 stands = world.positions()[0];
        // In the goal's disk, not just counted as arrived: stopping against the pile counts too.
        auto inGoal = [&] { return glm::distance(glm::vec2(world.positions()[1].x, world.positions()[1].z),
                                                 glm::vec2(10.0f, 0.0f)) < 1.0f; };
        while (world.timeS() < 20.0 && !inGoal())
            world.step();
        QVERIFY2(inGoal(), qPrintable(QString("the walker stopped at x = %1, short of the goal")
                                          .arg(double(world.positions()[1].x))));
        QCOMPARE(world.positions()[0], stands);
        QVERIFY(world.isUnstarted(0) && !world.hasArrived(0));
        while (world.timeS() < 40.0 && !world.hasArrived(0))
            world.step();
        QVERIFY(world.hasArrived(0));
    }

    // A checkpoint keeps who still waits: the run resumed from it is the run that went on.
    // An edit that moves the others' goal keeps the waiting ones waiting until their time;
    // one that takes the reaction time away lets them go.
    void checkpointsKeepWhoStillWaits()
    {
        const std::string yaml = room(2.0f, 8.0f);
        const Scene s = parseReactions(yaml);
        World world(s);
        for (int k = 0; k < 4 * 24; ++k)
            world.step();
        const WorldState at4 = world.saveState();
        std::size_t waiting = 0;
        for (std::size_t i = 0; i < 12; ++i)
            waiting += world.isUnstarted(i) ? 1 : 0;
        QVERIFY(waiting > 2 && waiting < 10);
        for (int k = 0; k < 6 * 24; ++k)
            world.step();

        World resumed(s);
        resumed.restoreState(at4);
        for (int k = 0; k < 6 * 24; ++k)
            resumed.step();
        for (std::size_t i = 0; i < world.agentCount(); ++i)
            QCOMPARE(resumed.positions()[i], world.positions()[i]);

        Scene moved = s;
        moved.goals[0].position = glm::vec2(-10.0f, 4.0f);
        World edited(moved);
        QVERIFY(edited.adoptState(at4, s, moved));
        std::vector<glm::vec3> stood(edited.positions().begin(), edited.positions().end());
        for (std::size_t i = 0; i < 12; ++i)
            QCOMPARE(edited.isUnstarted(i), world.startTimeS(i) > 4.0 + 1e-9);
        while (edited.timeS() < 10.0 - 1e-9) {
            edited.step();
            for (std::size_t i = 0; i < 12; ++i)
                if (edited.timeS() <= edited.startTimeS(i))
                    QCOMPARE(edited.positions()[i], stood[i]);
        }
        for (std::size_t i = 0; i < 12; ++i)
            QVERIFY(!edited.isUnstarted(i) && edited.positions()[i] != stood[i]);

        // An edit that takes the reaction time away lets every one still waiting go at once.
        Scene prompt = s;
        prompt.agentTypes[0].variation.reactionS = glm::vec2(0.0f);
        World unheld(prompt);
        QVERIFY(unheld.adoptState(at4, s, prompt));
        stood.assign(unheld.positions().begin(), unheld.positions().end());
        for (int k = 0; k < 12; ++k)
            unheld.step();
        for (std::size_t i = 0; i < 12; ++i)
            QVERIFY2(!unheld.isUnstarted(i) && unheld.positions()[i] != stood[i], qPrintable(QString::number(i)));
    }

    // The key is written only when set, reads back the same, and refuses what it cannot be.
    void theFileKeepsAndChecksTheKey()
    {
        const Scene s = parseReactions(room(2.5f, 7.5f));
        QCOMPARE(s.agentTypes[0].variation.reactionS, glm::vec2(2.5f, 7.5f));
        QCOMPARE(s.agentTypes[1].variation.reactionS, glm::vec2(0.0f));
        const std::string written = sceneToYaml(s);
        QVERIFY2(written.find("reaction: [2.5, 7.5]") != std::string::npos, written.c_str());
        QCOMPARE(written.find("reaction:"), written.rfind("reaction:"));  // only the type that sets it
        QVERIFY(parseReactions(written).agentTypes == s.agentTypes);

        struct Bad {
            const char* range;
            const char* message;
        };
        for (const Bad& bad : {Bad{"[-1, 5]", "reaction"}, Bad{"[8, 2]", "min greater than max"},
                               Bad{"[1]", "reaction"}}) {
            std::string yaml = room(2.0f, 8.0f);
            yaml.replace(yaml.find("[2, 8]"), 6, bad.range);
            const LoadResult r = parseScene(yaml, "reactions.yaml", "");
            QVERIFY2(!r.ok(), bad.range);
            QVERIFY2(r.diagnostics[0].format().find(bad.message) != std::string::npos &&
                         r.diagnostics[0].format().find("reactions.yaml:4") != std::string::npos,
                     r.diagnostics[0].format().c_str());
        }
        // Only walkers wait out a reaction time: a vehicle type's is ignored, with a warning.
        const LoadResult car = parseScene("throng: 1\nagent_types:\n"
                                          "  - {name: car, kind: vehicle, variation: {reaction: [1, 2]}}\n",
                                          "reactions.yaml", "");
        QVERIFY(car.ok());
        QCOMPARE(car.diagnostics.size(), std::size_t(1));
        QCOMPARE(car.diagnostics[0].severity, Severity::Warning);
        QVERIFY2(car.diagnostics[0].format().find("variation.reaction") != std::string::npos,
                 car.diagnostics[0].format().c_str());
    }
};

THRONG_REGISTER_TEST(TestReactionTimes)
#include "TestReactionTimes.moc"
