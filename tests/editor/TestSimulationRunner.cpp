// The simulation runner's checkpoints as the editor relies on them: kept within their
// byte budget by thinning (the interval doubles), an edit resumes from the last one before
// the edit frame and pins one there, and an edit that adds an agent starts over.
#include "TestRegistry.h"

#include "editor/simulation/SimulationRunner.h"
#include "simcore/io/SceneIO.h"

#include <QElapsedTimer>
#include <QTest>

#include <vector>

using namespace throng;
using namespace throng::editor;

namespace {

sim::Scene crossroads()
{
    const sim::LoadResult r = sim::loadScene(THRONG_SOURCE_DIR "/resources/scenes/crossroads.yaml");
    return r.scene;
}

// Takes batches until `frames` frames came (or 60 s passed); returns them all, merged.
SimulationRunner::Batch collect(SimulationRunner& runner, std::size_t frames)
{
    SimulationRunner::Batch all;
    QElapsedTimer clock;
    clock.start();
    bool first = true;
    while (all.frameCount < frames && clock.elapsed() < 60000) {
        SimulationRunner::Batch b = runner.takeFrames();
        if (b.frameCount == 0) {
            QTest::qWait(5);
            continue;
        }
        if (first) {
            all.agents = b.agents;
            all.resumedAt = b.resumedAt;
            first = false;
        }
        all.frames.insert(all.frames.end(), b.frames.begin(), b.frames.end());
        all.frameCount += b.frameCount;
    }
    return all;
}

}  // namespace

class TestSimulationRunner : public QObject {
    Q_OBJECT

private slots:
    void checkpointsStayWithinTheirBudget()
    {
        SimulationRunner runner([] {});
        runner.setCheckpointBudget(4, 600 * 1024);
        runner.start(crossroads());
        runner.setTarget(101);
        QCOMPARE(collect(runner, 101).frameCount, std::size_t(101));
        // About 100 KB each: 26 checkpoints every 4 frames would not fit, every 32 do.
        QCOMPARE(runner.checkpointFrames(), (std::vector<std::size_t>{0, 32, 64, 96}));
        QVERIFY(runner.checkpointBytes() <= 600 * 1024);
        QVERIFY(runner.checkpointBytes() > 4 * 50 * 1024);
    }

    void anEditResumesFromTheEditFrameAndAnAddedAgentStartsOver()
    {
        const sim::Scene scene = crossroads();
        SimulationRunner runner([] {});
        runner.start(scene);
        runner.setTarget(80);
        const SimulationRunner::Batch first = collect(runner, 80);
        QCOMPARE(first.frameCount, std::size_t(80));
        QCOMPARE(runner.checkpointFrames(), (std::vector<std::size_t>{0, 24, 48, 72}));

        sim::Scene walled = scene;
        walled.walls.push_back({"", {{30.0f, 20.0f}, {40.0f, 20.0f}}});
        runner.resume(walled, 50);
        runner.setTarget(60);
        const SimulationRunner::Batch resumed = collect(runner, 9);
        QCOMPARE(resumed.resumedAt, std::size_t(50));
        QVERIFY(resumed.agents.empty());
        QCOMPARE(resumed.frameCount, std::size_t(9));  // frames 51..59
        QCOMPARE(runner.checkpointFrames(), (std::vector<std::size_t>{0, 24, 48, 50}));
        // A wall 12 m from the nearest walker: frame 51 is the recorded one for every
        // walker on a path (the A* errands plan again on the edited grid).
        const std::size_t n = first.agents.size();
        for (std::size_t i = 0; i < n; ++i)
            if (first.agents[i].typeIndex == 0)
                QCOMPARE(resumed.frames[i].position, first.frames[51 * n + i].position);

        sim::Scene crowded = walled;
        sim::Agent extra;
        extra.id = 9000;
        extra.type = "pedestrian";
        extra.position = {-7.5f, 0.0f, -30.0f};
        crowded.agents.push_back(extra);
        runner.resume(crowded, 55);
        const SimulationRunner::Batch again = collect(runner, 1);
        QCOMPARE(again.resumedAt, std::size_t(0));
        QCOMPARE(again.agents.size(), n + 1);
        QCOMPARE(runner.checkpointFrames(), (std::vector<std::size_t>{0}));
    }
};

THRONG_REGISTER_TEST(TestSimulationRunner)
#include "TestSimulationRunner.moc"
