// Edits that add or remove agents resume from the edit frame (issue 6), driven as a user
// does: play the crossroads, scrub to frame 40, paint with the crowd brush. Frames 0..39
// stay as recorded (the old crowd), frame 40 shows the new agents at once and frame 41
// follows without a restart; erasing some at frame 50 hides them from 50 on while scrubbing back still
// shows them; undoing both gives the original recording back bit for bit.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "TestRegistry.h"

#include "editor/simulation/SimulationController.h"
#include "editor/viewport/Viewport.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <set>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

constexpr std::size_t kEditFrame = 40, kEraseFrame = 50, kLastFrame = 60;

}  // namespace

class TestResumeAgentsUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void playPressedRightAfterAStrokeAtFrameZeroPlays()
    {
        // The stroke reaches the simulation a moment after the mouse is released: the run
        // then starts over with the painted agents, and playback must go on, not stop.
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        SimulationController& sim = window.simulation();
        QVERIFY(clickToolButton(window, "crowdBrush"));
        dragOnGround(window, {{-38, -25}, {-26, -25}});
        const std::size_t painted = window.document().scene().agents.size();
        QVERIFY(painted >= 4);
        QVERIFY(playUntilRecorded(window, 24));
        QCOMPARE(sim.cache().agentCount(), kCrossroadsAgents + painted);
    }

    void paintEraseAndUndoResumeFromTheEditFrame()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        SimulationController& sim = window.simulation();
        QVERIFY(playUntilRecorded(window, kLastFrame));
        const std::uint64_t original = hashOfFirst(sim.cache(), kLastFrame + 1);
        const std::uint64_t keptFrames = sim.cache().hashFrames(0, kEditFrame);
        const std::size_t restarts = sim.restarts();
        QVERIFY(scrubWithKeys(window, kEditFrame));

        // Paint on the north-west block's sidewalk side at frame 40.
        QVERIFY(clickToolButton(window, "crowdBrush"));
        dragOnGround(window, {{-38, -25}, {-26, -25}});
        const std::size_t painted = window.document().scene().agents.size();
        QVERIFY(painted >= 4);
        // Every agent of the recording has its own id (kept members keep theirs).
        QTRY_VERIFY(sim.recordedFrames() == kEditFrame + 1);
        QTRY_COMPARE(sim.recordedFrames(), kEditFrame + 1);
        QCOMPARE(sim.currentFrame(), kEditFrame);
        QTRY_COMPARE(window.viewport().agentCount(), kCrossroadsAgents + painted);  // TestPaintedAgentsShowUi

        // Step: frame 41 follows from frame 40, not from a restart, with the new agents.
        QVERIFY(clickButton(window, "stepButton"));
        QTRY_COMPARE(sim.currentFrame(), kEditFrame + 1);
        QCOMPARE(sim.lastResumedAt(), kEditFrame);
        QCOMPARE(sim.restarts(), restarts);
        QCOMPARE(sim.cache().agentCount(), kCrossroadsAgents + painted);
        QCOMPARE(window.viewport().agentCount(), kCrossroadsAgents + painted);
        std::set<sim::AgentId> ids;
        for (const sim::AgentInfo& a : sim.cache().agents())
            ids.insert(a.id);
        QCOMPARE(ids.size(), sim.cache().agentCount());
        QVERIFY(playUntilRecorded(window, kLastFrame));
        QCOMPARE(sim.restarts(), restarts);
        QCOMPARE(sim.cache().hashFrames(0, kEditFrame), keptFrames);
        // The new agents (the last cache agents) are there from frame 40 only, where painted.
        const sim::FrameCache& cache = sim.cache();
        for (std::size_t i = kCrossroadsAgents; i < cache.agentCount(); ++i) {
            QVERIFY(!cache.at(kEditFrame - 1, i).present);
            QVERIFY(cache.at(kEditFrame, i).present);
            const sim::Agent* placed = nullptr;
            for (const sim::Agent& a : window.document().scene().agents)
                if (a.id == cache.agents()[i].id)
                    placed = &a;
            QVERIFY(placed);
            QVERIFY(glm::distance(glm::vec2(cache.at(kEditFrame + 1, i).position.x, cache.at(kEditFrame + 1, i).position.z),
                                  glm::vec2(placed->position.x, placed->position.z)) < 0.2f);
        }
        QVERIFY(scrubWithKeys(window, kEditFrame - 1));
        QCOMPARE(window.viewport().agentCount(), kCrossroadsAgents);

        // Erase the painted agents of the stroke's first half at frame 50.
        QVERIFY(scrubWithKeys(window, kEraseFrame));
        QVERIFY(clickToolButton(window, "eraseBrush"));
        dragOnGround(window, {{-38, -25}, {-33, -25}});
        const std::size_t left = window.document().scene().agents.size();
        QVERIFY(left < painted && left > 0);
        QTRY_COMPARE(sim.recordedFrames(), kEraseFrame + 1);
        QVERIFY(playUntilRecorded(window, kLastFrame));
        QCOMPARE(sim.restarts(), restarts);
        QCOMPARE(sim.lastResumedAt(), kEraseFrame);
        QVERIFY(scrubWithKeys(window, kEraseFrame));
        QCOMPARE(window.viewport().agentCount(), kCrossroadsAgents + left);
        QVERIFY(scrubWithKeys(window, kEraseFrame - 5));
        QCOMPARE(window.viewport().agentCount(), kCrossroadsAgents + painted);

        // Undo the erase at frame 50 and the stroke at frame 40: the original recording.
        QVERIFY(scrubWithKeys(window, kEraseFrame));
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(window.document().scene().agents.size(), painted);
        QTRY_COMPARE(sim.recordedFrames(), kEraseFrame + 1);
        QVERIFY(scrubWithKeys(window, kEditFrame));
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QVERIFY(window.document().scene().agents.empty());
        QTRY_COMPARE(sim.recordedFrames(), kEditFrame + 1);
        QTRY_COMPARE(sim.cache().agentCount(), kCrossroadsAgents);  // once frame 40 is recorded again
        QVERIFY(playUntilRecorded(window, kLastFrame));
        QCOMPARE(sim.restarts(), restarts);
        QCOMPARE(hashOfFirst(sim.cache(), kLastFrame + 1), original);
    }
};

THRONG_REGISTER_TEST(TestResumeAgentsUi)
#include "TestResumeAgentsUi.moc"
