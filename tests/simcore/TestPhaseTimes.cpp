// World::phaseTimes as a user of `throng-cli bench` reads it: every phase that ran is timed
// and one that did not run (brains in a brainless world, traffic where there is none) has
// no time at all; the phases add up to the steps' wall-clock time; a step at 12 fps counts
// as the two steps it takes.
#include "TestRegistry.h"

#include "simcore/io/SceneIO.h"
#include "simcore/scenarios/BenchScenarios.h"
#include "simcore/world/World.h"

#include <QTest>

#include <chrono>

using namespace throng::sim;

namespace {

Scene benchScene(const char* name, std::uint32_t agents)
{
    Scene scene;
    if (!makeBenchScenario(name, agents, scene))
        qFatal("no bench scenario %s", name);
    return scene;
}

// Steps a World and returns the wall-clock seconds the steps took, measured round them.
double stepFor(World& world, int steps)
{
    const auto start = std::chrono::steady_clock::now();
    for (int s = 0; s < steps; ++s)
        world.step();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

class TestPhaseTimes : public QObject {
    Q_OBJECT
private slots:
    void everyPhaseThatRunsIsTimedAndTheyAddUpToTheSteps()
    {
        World world(benchScene("cross-brain", 3000));
        const double wall = stepFor(world, 40);
        const PhaseTimes& t = world.phaseTimes();
        QCOMPARE(t.steps(), std::uint64_t(40));
        for (const StepPhase p : {StepPhase::Grid, StepPhase::Navigate, StepPhase::Brain, StepPhase::Move,
                                  StepPhase::Collide, StepPhase::Commit, StepPhase::Count})
            QVERIFY2(t.seconds(p) > 0.0, kStepPhaseNames[std::size_t(p)].data());
        QCOMPARE(t.seconds(StepPhase::Traffic), 0.0);  // the cross has no traffic
        // The laps cover each step from its first clock mark to its last, so they add up to
        // all but the loop's own time round the steps.
        QVERIFY2(t.totalSeconds() <= wall, qPrintable(QString("%1 > %2").arg(t.totalSeconds()).arg(wall)));
        QVERIFY2(t.totalSeconds() >= 0.5 * wall, qPrintable(QString("%1 of %2").arg(t.totalSeconds()).arg(wall)));
        // Walkers with a 40-node brain and reciprocal avoidance spend their step moving
        // and thinking, not on bookkeeping.
        QVERIFY(t.seconds(StepPhase::Move) > t.seconds(StepPhase::Enter));
        QVERIFY(t.seconds(StepPhase::Brain) > t.seconds(StepPhase::Enter));
    }

    void aPhaseThatDoesNotRunHasNoTime()
    {
        World world(benchScene("cross", 2000));
        stepFor(world, 30);
        const PhaseTimes& t = world.phaseTimes();
        QCOMPARE(t.seconds(StepPhase::Brain), 0.0);
        QCOMPARE(t.seconds(StepPhase::Traffic), 0.0);
        QVERIFY(t.seconds(StepPhase::Move) > 0.0);
    }

    void trafficIsTimedWhereThereIsTraffic()
    {
        const LoadResult r = loadScene(std::string(THRONG_SOURCE_DIR) + "/resources/scenes/crossroads.yaml");
        QVERIFY(r.ok());
        World world(r.scene);
        stepFor(world, 48);
        const PhaseTimes& t = world.phaseTimes();
        QVERIFY(t.seconds(StepPhase::Traffic) > 0.0);
        QVERIFY(t.seconds(StepPhase::Brain) > 0.0);  // its walkers and cars run brains
        QCOMPARE(t.steps(), std::uint64_t(48));
    }

    // Below 24 fps a frame takes several steps (StepRate.h), and each is timed.
    void aFrameOfSeveralStepsCountsEachStep()
    {
        Scene scene = benchScene("cross", 500);
        scene.settings.fps = 12;
        World world(scene);
        QCOMPARE(world.subSteps(), 2);
        stepFor(world, 10);
        QCOMPARE(world.phaseTimes().steps(), std::uint64_t(20));
    }
};

THRONG_REGISTER_TEST(TestPhaseTimes)
#include "TestPhaseTimes.moc"
