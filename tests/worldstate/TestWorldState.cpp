// Checkpoints of a World as a user of the editor relies on them: a run resumed from a
// checkpoint taken at step 100 gives bit-identical frames to the run that never stopped,
// on scenes where every kind of state matters (traffic, a hero, A* and flow-field
// walkers, exits, brains with memory), for 1 and 2 threads.
#include "StateScenes.h"
#include "TestRegistry.h"

#include "simcore/brain/BrainEvaluator.h"
#include "simcore/world/WorldState.h"

#include <QTest>

#include <stdexcept>

using namespace throng::sim;
using namespace throng::test::state;

class TestWorldState : public QObject {
    Q_OBJECT

private slots:
    void resumedRunIsBitIdentical_data()
    {
        QTest::addColumn<QString>("sceneName");
        QTest::addColumn<int>("threads");
        QTest::newRow("crossroads with brains, 1 thread") << "crossroads" << 1;
        QTest::newRow("crossroads with brains, 2 threads") << "crossroads" << 2;
        QTest::newRow("crossroads as shipped, 2 threads") << "crossroads-plain" << 2;
        QTest::newRow("evacuation, 1 thread") << "evacuation" << 1;
        QTest::newRow("evacuation, 2 threads") << "evacuation" << 2;
    }

    void resumedRunIsBitIdentical()
    {
        QFETCH(QString, sceneName);
        QFETCH(int, threads);
        const Scene scene = sceneName == "crossroads" ? crossroadsWithBrains()
                            : sceneName == "evacuation" ? smallEvacuation()
                                                        : crossroads();
        const WorldOptions options{0, false, threads};

        World straight(scene, options);
        QVERIFY2(straight.brainErrors().empty(), straight.brainErrors().empty() ? "" : straight.brainErrors()[0].c_str());
        for (int s = 0; s < 100; ++s)
            straight.step();
        const WorldState at100 = straight.saveState();
        QCOMPARE(at100.step, std::uint64_t(100) * std::uint64_t(straight.subSteps()));  // steps, frames times sub-steps
        const FrameCache reference = record(straight, 100);

        World resumed(scene, options);
        resumed.restoreState(at100);
        QCOMPARE(resumed.stepIndex(), std::uint64_t(100));
        const FrameCache again = record(resumed, 100);
        QCOMPARE(again.frameCount(), std::size_t(101));
        QCOMPARE(again.hash(), reference.hash());
        QCOMPARE(resumed.counters().agentSteps, straight.counters().agentSteps);
        QCOMPARE(resumed.counters().overlappingPairs, straight.counters().overlappingPairs);

        // The scene really holds the state the checkpoint must carry.
        if (sceneName == "crossroads") {
            QVERIFY(straight.trafficSystem() && straight.trafficSystem()->vehicleCount() == 16);
            const BrainEvaluator* brain = straight.brainEvaluator(0);
            QVERIFY(brain && brain->stateColumns().size() >= 3);
            // Some pedestrian's memory (a running maximum of the density it felt) is above 0.
            float most = 0.0f;
            for (const auto& column : brain->stateColumns())
                for (float v : column)
                    most = std::max(most, v);
            QVERIFY(most > 0.0f);
        } else if (sceneName == "evacuation") {
            std::size_t out = 0;
            for (std::size_t i = 0; i < straight.agentCount(); ++i)
                out += straight.isOut(i) ? 1 : 0;
            QVERIFY2(out > 0, "no evacuee left through a door by step 200");
        }
    }

    void sameFramesForOneAndTwoThreads()
    {
        const Scene scene = crossroadsWithBrains();
        std::uint64_t hashes[2] = {};
        for (int t = 1; t <= 2; ++t) {
            World world(scene, {0, false, t});
            for (int s = 0; s < 60; ++s)
                world.step();
            World resumed(scene, {0, false, 3 - t});
            resumed.restoreState(world.saveState());
            hashes[t - 1] = record(resumed, 60).hash();
        }
        QCOMPARE(hashes[0], hashes[1]);
    }

    void restoringIsRepeatable()
    {
        // One checkpoint restored twice into the same World gives the same frames twice:
        // nothing of the first resumed run leaks into the second.
        const Scene scene = crossroadsWithBrains();
        World world(scene);
        for (int s = 0; s < 50; ++s)
            world.step();
        const WorldState at50 = world.saveState();
        const std::uint64_t first = record(world, 40).hash();
        world.restoreState(at50);
        QCOMPARE(world.stepIndex(), std::uint64_t(50));
        QCOMPARE(record(world, 40).hash(), first);
        QVERIFY(at50.memoryBytes() > world.agentCount() * 100);
    }

    void refusesAnotherScenesCheckpoint()
    {
        const Scene scene = crossroadsWithBrains();
        World world(scene);
        World other(smallEvacuation());
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, other.restoreState(world.saveState()));
        QCOMPARE(other.stepIndex(), std::uint64_t(0));
    }
};

THRONG_REGISTER_TEST(TestWorldState)
#include "TestWorldState.moc"
