// A lane drawn with the real lane tool at frame 40 of the crossroads resumes the run from
// frame 40 (issue 6), not from frame 0: the first batch after the edit says resumedAt 40,
// frames 0..40 stay as recorded (the lane carries no vehicle), and undo gives the
// original recording back bit for bit. Driven as a user does, with real mouse and key events.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "TestRegistry.h"

#include "editor/panels/TimelinePanel.h"
#include "editor/simulation/SimulationController.h"
#include "editor/viewport/Viewport.h"

#include <QTest>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

constexpr std::size_t kEditFrame = 40, kLastFrame = 60;

}  // namespace

class TestResumeTrafficUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void aLaneDrawnAtFrameFortyResumesThereAndUndoGivesTheRecordingBack()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        SimulationController& sim = window.simulation();
        QVERIFY(playUntilRecorded(window, kLastFrame));
        const std::uint64_t original = hashOfFirst(sim.cache(), kLastFrame + 1);
        const std::uint64_t kept = sim.cache().hashFrames(0, kEditFrame + 1);
        const std::size_t restarts = sim.restarts();
        QCOMPARE(sim.lastResumedAt(), std::size_t(0));
        QVERIFY(scrubWithKeys(window, kEditFrame));

        // A lane in the north-west block, clicked point by point, ended with Return.
        QVERIFY(clickToolButton(window, "lane"));
        for (glm::vec2 p : {glm::vec2(-40, -30), glm::vec2(-20, -30), glm::vec2(-20, -20)})
            clickOnGround(window, p);
        QTest::keyClick(&window.viewport(), Qt::Key_Return);
        QCOMPARE(window.document().scene().lanes.size(), std::size_t(5));
        QTRY_COMPARE(sim.lastResumedAt(), kEditFrame);
        QCOMPARE(sim.restarts(), restarts);
        QCOMPARE(sim.currentFrame(), kEditFrame);
        QCOMPARE(sim.cache().hashFrames(0, kEditFrame + 1), kept);
        QVERIFY(playUntilRecorded(window, kLastFrame));
        QCOMPARE(sim.restarts(), restarts);
        QCOMPARE(sim.cache().hashFrames(0, kEditFrame + 1), kept);

        // Undo at frame 40: the original recording, bit for bit.
        QVERIFY(scrubWithKeys(window, kEditFrame));
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(window.document().scene().lanes.size(), std::size_t(4));
        QTRY_COMPARE(sim.recordedFrames(), kEditFrame + 1);
        QVERIFY(playUntilRecorded(window, kLastFrame));
        QCOMPARE(sim.restarts(), restarts);
        QCOMPARE(sim.lastResumedAt(), kEditFrame);
        QCOMPARE(hashOfFirst(sim.cache(), kLastFrame + 1), original);
    }
};

THRONG_REGISTER_TEST(TestResumeTrafficUi)
#include "TestResumeTrafficUi.moc"
