// Simulation > Simulate to End driven like a user: the progress dialog counts the
// recorded frames, closes itself at the last one, and Cancel stops the recording and
// keeps what was made. An edit that changes nothing the simulation reads (the variation
// brush) keeps the recorded frames; a real edit throws them away.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "TestRegistry.h"

#include "editor/panels/TimelinePanel.h"
#include "editor/simulation/SimulationController.h"
#include "editor/viewport/Viewport.h"

#include <QAction>
#include <QProgressDialog>
#include <QPushButton>
#include <QSlider>
#include <QTest>
#include <QToolButton>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

// 2 s at 24 fps: 49 frames.
const QByteArray kShortScene = R"(throng: 1
settings: {fps: 24, duration: 2, seed: 3}
agent_types:
  - name: walker
goals:
  - {name: far, position: [20, 0], radius: 1}
agents:
  - {type: walker, position: [0, 0], goal: far}
  - {type: walker, position: [0, 2], goal: far}
  - {type: walker, position: [0, -2], goal: far}
)";

QAction* simulateToEnd(MainWindow& window)
{
    return window.findChild<QAction*>("simulateToEndAction");
}

QProgressDialog* openDialog(MainWindow& window)
{
    for (QProgressDialog* d : window.findChildren<QProgressDialog*>("simulateToEndDialog"))
        if (d->isVisible())
            return d;
    return nullptr;
}

}  // namespace

class TestSimulateToEndUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void recordsEveryFrameAndCloses()
    {
        MainWindow window;
        window.resize(1200, 800);
        window.show();
        window.activateWindow();
        QVERIFY(QTest::qWaitForWindowExposed(&window) && QTest::qWaitForWindowActive(&window));
        QVERIFY(window.openScene(writeScene(m_dir, "short.yaml", kShortScene)));
        SimulationController& sim = window.simulation();
        QCOMPARE(sim.totalFrames(), std::size_t(49));
        QVERIFY(simulateToEnd(window));
        QTest::keyClick(&window.viewport(), Qt::Key_E, Qt::ControlModifier);
        QTRY_COMPARE_WITH_TIMEOUT(sim.recordedFrames(), std::size_t(49), 20000);
        QTRY_VERIFY(openDialog(window) == nullptr);  // closed itself
        // Every frame can be scrubbed to; by the last the walkers have gone east.
        QSlider* scrub = window.timeline().scrubBar();
        QCOMPARE(scrub->maximum(), 48);
        scrub->setFocus();
        QTest::keyClick(scrub, Qt::Key_End);
        QCOMPARE(window.viewport().frameIndex(), std::size_t(48));
        for (std::size_t i = 0; i < 3; ++i)
            QVERIFY2(sim.cache().frame(48)[i].position.x > 1.0f, qPrintable(QString::number(sim.cache().frame(48)[i].position.x)));
    }

    void cancelStopsTheRecordingAndKeepsTheFrames()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));  // 240 s: 5761 frames
        SimulationController& sim = window.simulation();
        simulateToEnd(window)->trigger();
        QProgressDialog* dialog = nullptr;
        QTRY_VERIFY((dialog = openDialog(window)) != nullptr);
        QTRY_VERIFY_WITH_TIMEOUT(sim.recordedFrames() >= 10, 20000);
        QTRY_VERIFY(dialog->value() >= 10);  // the bar follows the recording
        auto* cancel = dialog->findChild<QPushButton*>();
        QVERIFY(cancel);
        QTest::mouseClick(cancel, Qt::LeftButton);
        QTRY_VERIFY(openDialog(window) == nullptr);
        QTest::qWait(300);  // frames already computed arrive
        const std::size_t kept = sim.recordedFrames();
        QTest::qWait(700);
        QCOMPARE(sim.recordedFrames(), kept);  // nothing more is computed
        QVERIFY(kept >= 10 && kept < sim.totalFrames());
    }

    void aVariationEditKeepsTheFramesARealEditDoesNot()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        QVERIFY(clickToolButton(window, "crowdBrush"));
        dragOnGround(window, {{-38, -25}, {-14, -25}});
        SimulationController& sim = window.simulation();
        // The crossroads' agents and the painted ones: the edit has reached the views.
        QTRY_COMPARE(window.viewport().agentCount(), kCrossroadsAgents + window.document().scene().agents.size());
        QTRY_VERIFY(sim.recordedFrames() >= 1);
        for (std::size_t k = 1; k <= 6; ++k) {
            QTest::mouseClick(window.findChild<QToolButton*>("stepButton"), Qt::LeftButton);
            QTRY_COMPARE(window.viewport().frameIndex(), k);
        }

        QVERIFY(clickToolButton(window, "variationBrush"));
        dragOnGround(window, {{-30, -25}, {-20, -25}});
        QCOMPARE(window.document().undoStack()->count(), 2);
        QVERIFY(window.document().undoStack()->text(1).startsWith("Vary"));
        QTest::qWait(100);
        QCOMPARE(sim.currentFrame(), std::size_t(6));
        QVERIFY(sim.recordedFrames() >= 7);
        QCOMPARE(window.viewport().frameIndex(), std::size_t(6));

        // An edit the simulation reads keeps the frames up to the shown one (issue 6).
        QVERIFY(clickToolButton(window, "obstacle"));
        clickOnGround(window, {-30, -35});
        QCOMPARE(sim.currentFrame(), std::size_t(6));
        QCOMPARE(sim.recordedFrames(), std::size_t(7));
        QCOMPARE(window.viewport().frameIndex(), std::size_t(6));
    }
};

THRONG_REGISTER_TEST(TestSimulateToEndUi)
#include "TestSimulateToEndUi.moc"
