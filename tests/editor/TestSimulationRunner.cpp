// The simulation runner's checkpoints as the editor relies on them: kept within their
// byte budget by thinning (the interval doubles), an edit resumes from the last one before
// the edit frame and pins one there, an edit that adds an agent resumes too (the new agent
// marked new), a settings edit starts over, picking an agent for brain values after an
// edit replays each span with the scene it was recorded with, and a new run asked for
// while a World is being built neither waits for it nor gets anything of it.
#include "TestRegistry.h"

#include "editor/simulation/SimulationRunner.h"
#include "simcore/io/SceneIO.h"
#include "simcore/world/World.h"

#include <QElapsedTimer>
#include <QScopeGuard>
#include <QTest>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <future>
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
        if (!b.error.empty())
            qWarning("runner: %s", b.error.c_str());
        if (b.frameCount == 0) {
            QTest::qWait(5);
            continue;
        }
        if (first) {
            all.agents = b.agents;
            all.previous = b.previous;
            all.resumedAt = b.resumedAt;
            first = false;
        }
        all.frames.insert(all.frames.end(), b.frames.begin(), b.frames.end());
        for (auto& v : b.brainValues)
            all.brainValues.push_back(std::move(v));
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

    void anEditResumesFromTheEditFrameAndAnAddedAgentToo()
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
        const SimulationRunner::Batch resumed = collect(runner, 10);
        QCOMPARE(resumed.resumedAt, std::size_t(50));
        QCOMPARE(resumed.agents.size(), first.agents.size());
        for (std::size_t i = 0; i < resumed.previous.size(); ++i)
            QCOMPARE(resumed.previous[i], std::int32_t(i));
        QCOMPARE(resumed.frameCount, std::size_t(10));  // frames 50..59: the edit frame again, then on
        QCOMPARE(runner.checkpointFrames(), (std::vector<std::size_t>{0, 24, 48, 50}));
        // A wall 12 m from the nearest walker: frame 50 is the recorded one for everyone,
        // frame 51 for every walker on a path (the A* errands plan again on the edited grid).
        const std::size_t n = first.agents.size();
        for (std::size_t i = 0; i < n; ++i) {
            QCOMPARE(resumed.frames[i].position, first.frames[50 * n + i].position);
            if (first.agents[i].typeIndex == 0)
                QCOMPARE(resumed.frames[n + i].position, first.frames[51 * n + i].position);
        }

        sim::Scene crowded = walled;
        sim::Agent extra;
        extra.id = 9000;
        extra.type = "pedestrian";
        extra.position = {-7.5f, 0.0f, -30.0f};
        crowded.agents.push_back(extra);
        runner.resume(crowded, 55);
        runner.setTarget(57);
        const SimulationRunner::Batch again = collect(runner, 1);
        QCOMPARE(again.resumedAt, std::size_t(55));
        QCOMPARE(again.agents.size(), n + 1);
        QCOMPARE(again.previous.size(), n + 1);
        QCOMPARE(again.previous[0], std::int32_t(-1));  // placed agents come first
        QCOMPARE(again.agents[0].id, sim::AgentId(9000));
        QCOMPARE(runner.checkpointFrames(), (std::vector<std::size_t>{0, 24, 48, 50, 55}));

        sim::Scene faster = crowded;
        faster.settings.fps = 30.0f;
        runner.resume(faster, 56);
        const SimulationRunner::Batch restarted = collect(runner, 1);
        QCOMPARE(restarted.resumedAt, std::size_t(0));
        QCOMPARE(runner.checkpointFrames(), (std::vector<std::size_t>{0}));
    }

    void brainValuesAfterAnEditAreThoseOfTheFramesShown()
    {
        const sim::Scene scene = crossroads();
        std::size_t car = 0;
        while (scene.agentTypes[sim::World(scene).agentInfo()[car].typeIndex].name != "car")
            ++car;
        // The car's values with it picked from the start, on the scene as it was.
        SimulationRunner reference([] {});
        reference.pickBrainAgent(std::ptrdiff_t(car));
        reference.start(scene);
        reference.setTarget(60);
        const SimulationRunner::Batch picked = collect(reference, 60);
        QCOMPARE(picked.brainValues.size(), std::size_t(60));
        const sim::AgentId carId = picked.agents[car].id;

        // Recorded with nobody picked; at frame 30 a stroke adds two agents (which moves
        // the car's index) and the light's cycle shifts; picked afterwards.
        sim::Scene edited = scene;
        for (std::uint32_t k = 0; k < 2; ++k) {
            sim::Agent a;
            a.id = 9000 + k;
            a.type = "pedestrian";
            a.position = {-7.5f, 0.0f, -30.0f - float(k)};
            edited.agents.push_back(a);
        }
        edited.trafficLights[0].offsetS += 20.0f;
        SimulationRunner runner([] {});
        runner.start(scene);
        runner.setTarget(40);
        QCOMPARE(collect(runner, 40).frameCount, std::size_t(40));
        runner.resume(edited, 30);
        runner.setTarget(50);
        QCOMPARE(collect(runner, 19).resumedAt, std::size_t(30));
        runner.replayBrainValues(carId, 50);
        runner.setTarget(50);
        const SimulationRunner::Batch replay = collect(runner, 49);  // frames 1..49
        QCOMPARE(replay.frameCount, std::size_t(49));
        QVERIFY(replay.frames.empty());
        // Frames 1..30 were simulated before the edit: the values of the pick from the start.
        for (std::size_t f = 1; f <= 30; ++f) {
            const auto& got = replay.brainValues[f - 1].values;
            const auto& want = picked.brainValues[f].values;
            QVERIFY2(!want.empty(), "the car runs a brain");
            QCOMPARE(got.size(), want.size());
            for (std::size_t k = 0; k < got.size(); ++k)
                QCOMPARE(got[k].values, want[k].values);
        }
        // From frame 31 the car is agent car + 2 of the edited World, and the values are still its.
        QCOMPARE(replay.brainValues[30].agent, std::ptrdiff_t(car + 2));
        QVERIFY(!replay.brainValues[48].values.empty());
    }

    // A run asked for while the runner builds a big World returns at once (the World
    // cannot be interrupted: the GUI thread would otherwise wait for it, seconds on a big
    // crowd), and what comes is the latest run's alone: nothing of the run it replaced.
    void aNewRunDoesNotWaitForTheWorldBeingBuilt()
    {
        sim::Scene big;
        big.settings.boundsMin = {-300.0f, -300.0f};
        big.settings.boundsMax = {300.0f, 300.0f};
        sim::AgentType walker;
        walker.name = "walker";
        big.agentTypes.push_back(walker);
        sim::SpawnGroup crowd;
        crowd.name = "crowd";
        crowd.type = "walker";
        crowd.count = 100000;
        crowd.min = {-200.0f, -200.0f};
        crowd.max = {200.0f, 200.0f};
        big.groups.push_back(crowd);
        sim::Scene small = big;
        small.groups[0].count = 30;

        // The runner is held just before it builds the big crowd's World, as if the build
        // took forever: a start asked for then must return all the same.
        std::promise<void> release;
        const std::shared_future<void> released = release.get_future().share();
        std::atomic<int> builds{0};
        SimulationRunner runner([] {});
        runner.setBuildGate([&] {
            if (builds++ == 0)
                released.wait();
        });
        auto letGo = qScopeGuard([&] {
            if (released.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
                release.set_value();
        });
        runner.start(big);
        QTRY_VERIFY_WITH_TIMEOUT(builds.load() == 1, 30000);
        std::future<void> started = std::async(std::launch::async, [&] { runner.start(small); });
        if (started.wait_for(std::chrono::seconds(30)) != std::future_status::ready) {
            release.set_value();
            QFAIL("the start waited for the World being built");
        }
        QCOMPARE(builds.load(), 1);  // the big World is still not built
        release.set_value();

        runner.setTarget(5);
        const SimulationRunner::Batch got = collect(runner, 5);
        QCOMPARE(got.frameCount, std::size_t(5));
        QCOMPARE(got.agents.size(), std::size_t(30));
        QCOMPARE(got.frames.size(), std::size_t(5 * 30));
        QCOMPARE(runner.checkpointFrames(), std::vector<std::size_t>{0});
        // Nothing of the big run came: the runner built it (after the gate let go) before
        // it took up the small run, and handed none of it over.
        QCOMPARE(builds.load(), 2);
        const SimulationRunner::Batch late = runner.takeFrames();
        QCOMPARE(late.frameCount, std::size_t(0));
        QVERIFY(late.agents.empty());
    }
};

THRONG_REGISTER_TEST(TestSimulationRunner)
#include "TestSimulationRunner.moc"
