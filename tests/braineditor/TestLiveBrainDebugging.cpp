// Live debugging: pick an agent in the viewport, play, and every node shows the picked
// agent's current value (bars for truths, numbers for others), links show the flow, and
// the values change from frame to frame as the agent walks to its goal.
#include "BrainTestScenes.h"
#include "BrainUiDriver.h"
#include "TestRegistry.h"

#include "editor/brain/BrainScene.h"
#include "editor/brain/LinkItem.h"
#include "editor/brain/NodeItem.h"
#include "editor/simulation/SimulationController.h"
#include "editor/viewport/Viewport.h"

#include <QTest>
#include <QToolButton>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

class TestLiveBrainDebugging : public QObject {
    Q_OBJECT

private slots:
    void aPickedAgentsValuesChangeWhilePlaying()
    {
        QTemporaryDir dir;
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.open(dir, kWalkBrainScene));
        SimulationController& sim = window.simulation();
        QTRY_VERIFY_WITH_TIMEOUT(sim.recordedFrames() > 0, 30000);
        window.viewport().frameAll();
        // Nobody picked: nodes show their port names, not values.
        BrainScene& scene = ui.panel().scene();
        QVERIFY(scene.nodeItem(1)->liveText(0).isEmpty());
        // Pick the agent at the origin (id 1) with the Pick Agent button and a click.
        QTest::mouseClick(ui.panel().findChild<QToolButton*>("pickAgentButton"), Qt::LeftButton);
        QTest::mouseClick(&window.viewport(), Qt::LeftButton, {}, window.viewport().worldToPixel({0, 0, 0}).toPoint());
        QCOMPARE(ui.panel().pickedAgent(), std::ptrdiff_t(0));
        sim.play();
        QTRY_VERIFY_WITH_TIMEOUT(sim.currentFrame() >= 12, 30000);
        const std::size_t f1 = sim.currentFrame();
        const QString distance1 = scene.nodeItem(1)->liveText(0);
        const QString speed1 = scene.nodeItem(3)->liveText(0);
        QVERIFY(!distance1.isEmpty());
        // The goal distance node reads what the user sees: the gap from agent to goal.
        const float x1 = sim.cache().at(f1, 0).position.x;
        QVERIFY2(std::abs(distance1.toFloat() - (15.0f - x1)) < 0.7f, qPrintable(distance1 + " at x " + QString::number(double(x1))));
        QTRY_VERIFY_WITH_TIMEOUT(sim.currentFrame() >= f1 + 12, 30000);
        sim.pause();
        const QString distance2 = scene.nodeItem(1)->liveText(0);
        QVERIFY2(distance2.toFloat() < distance1.toFloat() - 0.2f, qPrintable(distance1 + " -> " + distance2));
        QVERIFY(!speed1.isEmpty());
        // The far-from-goal truth is 1 (a full bar), and its links carry it.
        QCOMPARE(scene.nodeItem(2)->liveText(0), QString("1"));
        int flowing = 0;
        for (LinkItem* link : scene.linkItems())
            flowing += link->flow().has_value() ? 1 : 0;
        QCOMPARE(flowing, 5);
        // Scrubbing back to frame 0 shows no values (no step yet), frame 6 shows them again.
        sim.seek(0);
        QVERIFY(scene.nodeItem(1)->liveText(0).isEmpty());
        sim.seek(6);
        QVERIFY(!scene.nodeItem(1)->liveText(0).isEmpty());
        // Picking nobody clears the graph.
        ui.panel().pickAgent(-1);
        QVERIFY(scene.nodeItem(1)->liveText(0).isEmpty());
    }

    // The values come from the playback's own World: an agent picked after playing shows
    // values at frames recorded before the pick too (they are computed again for it).
    void anAgentPickedAfterPlayingShowsValuesWhenScrubbedBack()
    {
        QTemporaryDir dir;
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.open(dir, kWalkBrainScene));
        SimulationController& sim = window.simulation();
        QTRY_VERIFY_WITH_TIMEOUT(sim.recordedFrames() > 0, 30000);
        sim.play();
        QTRY_VERIFY_WITH_TIMEOUT(sim.currentFrame() >= 30, 30000);
        sim.pause();
        BrainScene& scene = ui.panel().scene();
        ui.panel().pickAgent(0);
        sim.seek(12);
        QTRY_VERIFY_WITH_TIMEOUT(!scene.nodeItem(1)->liveText(0).isEmpty(), 30000);
        const float x = sim.cache().at(12, 0).position.x;
        const QString distance = scene.nodeItem(1)->liveText(0);
        QVERIFY2(std::abs(distance.toFloat() - (15.0f - x)) < 0.7f, qPrintable(distance + " at x " + QString::number(double(x))));
        sim.seek(0);
        QVERIFY(scene.nodeItem(1)->liveText(0).isEmpty());
    }
};

THRONG_REGISTER_TEST(TestLiveBrainDebugging)
#include "TestLiveBrainDebugging.moc"
