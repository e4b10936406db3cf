// Measurements and the Analysis dock driven like a user: U picks the measure tool, a drag
// draws a line across the corridor and, in Area mode, a rectangle; neither re-simulates
// (the recorded frames stay byte for byte); undo and redo take them back and forth; a
// line keeps its two ends (Add point is refused); Delete removes one. The Analysis tab
// beside Messages opens on a click, Analyse measures the recorded run, and its figures
// agree with a recount from the cache: every walker crossed the line forward, and the
// exit's count. The flow chart plots the line, Save Report writes the HTML file, and an
// edit that changes the run marks the analysis as stale. The analysis runs on a thread of
// its own and Stop ends it; the recording holds still while it is read, and an edit stops
// the reading before it changes the frames.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "TestRegistry.h"

#include "editor/panels/AnalysisPanel.h"
#include "editor/panels/OutlinerPanel.h"
#include "editor/panels/PointTable.h"
#include "editor/simulation/SimulationController.h"
#include "editor/viewport/Viewport.h"

#include <glm/geometric.hpp>

#include <QtCharts/QChartView>
#include <QtCharts/QLineSeries>

#include <QAction>
#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QFile>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QTabBar>
#include <QTabWidget>
#include <QTableWidget>
#include <QTest>
#include <QTreeWidget>
#include <QUndoStack>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

// 20 walkers walk east from [0, 6] x [-2, 2] to an exit at x = 20.
const QByteArray kCorridor = R"(throng: 1
settings: {fps: 24, duration: 30, seed: 2, bounds: {min: [-5, -10], max: [25, 10]}}
agent_types:
  - {name: walker, radius: 0.25, max_speed: 1.3}
goals:
  - {name: out, position: [20, 0], radius: 2, exit: true}
groups:
  - {name: crowd, type: walker, count: 20, rect: {min: [0, -2], max: [6, 2]}, goal: out}
)";

// The value of `label` under the figures' section `section`; empty when there is none.
QString figure(QTreeWidget* tree, const QString& section, const QString& label)
{
    for (int s = 0; s < tree->topLevelItemCount(); ++s) {
        QTreeWidgetItem* top = tree->topLevelItem(s);
        if (top->text(0) != section)
            continue;
        for (int r = 0; r < top->childCount(); ++r)
            if (top->child(r)->text(0) == label)
                return top->child(r)->text(1);
    }
    return {};
}

}  // namespace

class TestAnalysisUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void measurementsAreDrawnWithoutReSimulating()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "corridor.yaml", kCorridor));
        const sim::Scene& scene = window.document().scene();
        QVERIFY(playUntilRecorded(window, 240));
        // Frames computed before the pause may still come in: wait until none has for 0.5 s.
        std::size_t recorded = window.simulation().recordedFrames();
        for (int quiet = 0, k = 0; quiet < 5 && k < 100; ++k) {
            QTest::qWait(100);
            const std::size_t now = window.simulation().recordedFrames();
            quiet = now == recorded ? quiet + 1 : 0;
            recorded = now;
        }
        const std::uint64_t hash = hashOfFirst(window.simulation().cache(), recorded);
        QUndoStack* stack = window.document().undoStack();
        const int steps = stack->count();

        window.viewport().setFocus();
        QTest::keyClick(&window.viewport(), Qt::Key_U);
        QTRY_VERIFY(window.findChild<QAction*>("measureAction")->isChecked());
        dragOnGround(window, {{12, -5}, {12, 0}, {12, 5}});
        QCOMPARE(scene.measurements.size(), std::size_t(1));
        const sim::Measurement& line = scene.measurements[0];
        QVERIFY(line.shape == sim::MeasurementShape::Line);
        QCOMPARE(line.name, std::string("line_1"));
        QVERIFY(glm::length(line.points[0] - glm::vec2(12, -5)) < 0.3f);
        QVERIFY(glm::length(line.points[1] - glm::vec2(12, 5)) < 0.3f);
        QCOMPARE(stack->count(), steps + 1);
        QCOMPARE(stack->text(stack->count() - 1), QString("Add measurement line_1"));
        QCOMPARE(window.outliner().kindRow(ItemKind::Measurement)->text(0), QString("Measurements (1)"));

        // Area mode in the tool options: a drag draws a rectangle.
        auto* shape = window.findChild<QComboBox*>("measureShape");
        QVERIFY(shape);
        // The arrow key: typing a name into it would reach the tools' letter shortcuts.
        shape->setFocus();
        QTest::keyClick(shape, Qt::Key_Down);
        QCOMPARE(shape->currentText(), QString("Area"));
        dragOnGround(window, {{9, -3}, {11, 0}, {14, 3}});
        QCOMPARE(scene.measurements.size(), std::size_t(2));
        const sim::Measurement& area = scene.measurements[1];
        QVERIFY(area.shape == sim::MeasurementShape::Area);
        QCOMPARE(area.points.size(), std::size_t(4));
        QVERIFY(std::abs(area.points[2].x - area.points[0].x - 5.0f) < 0.4f);
        QVERIFY(std::abs(area.points[2].y - area.points[0].y - 6.0f) < 0.4f);

        // Neither edit re-simulated: the frames are those recorded before.
        QTest::qWait(300);
        QCOMPARE(window.simulation().recordedFrames(), recorded);
        QCOMPARE(hashOfFirst(window.simulation().cache(), recorded), hash);

        undo(window);
        QCOMPARE(scene.measurements.size(), std::size_t(1));
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE(scene.measurements.size(), std::size_t(2));

        // Selected, the line shows its two ends, and keeps two.
        QTest::keyClick(&window.viewport(), Qt::Key_Q);
        QTRY_VERIFY(window.findChild<QAction*>("selectAction")->isChecked());
        clickOnGround(window, {12, 4});
        QCOMPARE(window.document().selection(), (Selection{{ItemKind::Measurement, 0}}));
        PointTable* ends = nullptr;
        for (PointTable* t : window.findChildren<PointTable*>())
            if (t->isVisible())
                ends = t;
        QVERIFY(ends);
        QCOMPARE(ends->table()->rowCount(), 2);
        const int before = stack->count();
        QPushButton* add = nullptr;
        for (QPushButton* b : ends->findChildren<QPushButton*>())
            if (b->text().remove('&').startsWith("Add"))
                add = b;
        QVERIFY(add);
        showInPanel(window, add);
        QTest::mouseClick(add, Qt::LeftButton);
        QCOMPARE(scene.measurements[0].points.size(), std::size_t(2));
        QCOMPARE(stack->count(), before);
        QVERIFY2(lastMessage(window).contains("2 points"), qPrintable(lastMessage(window)));

        // Delete removes it, undo brings it back.
        window.viewport().setFocus();
        QTest::keyClick(&window.viewport(), Qt::Key_Delete);
        QCOMPARE(scene.measurements.size(), std::size_t(1));
        QVERIFY(scene.measurements[0].shape == sim::MeasurementShape::Area);
        undo(window);
        QCOMPARE(scene.measurements.size(), std::size_t(2));
        QCOMPARE(scene.measurements[0].name, std::string("line_1"));
        QCOMPARE(window.simulation().recordedFrames(), recorded);
    }

    void theAnalysisDockMeasuresTheRecordedRun()
    {
        MainWindow window;
        QByteArray yaml = kCorridor;
        yaml += "measurements:\n  - {name: gate, line: [[12, -5], [12, 5]]}\n"
                "  - {name: before_gate, area: [[8, -3], [12, -3], [12, 3], [8, 3]]}\n";
        QVERIFY(showWithYaml(window, m_dir, "measured.yaml", yaml));
        QVERIFY(playUntilRecorded(window, 719, 120000));
        const sim::FrameCache& cache = window.simulation().cache();

        auto* dock = window.findChild<QDockWidget*>("analysisDock");
        QVERIFY(dock);
        // The foot is as low as the timeline needs until the analysis is brought forward;
        // then it grows to show the whole panel, without scrolling.
        auto* scroll = window.findChild<QScrollArea*>("analysisScroll");
        QVERIFY(scroll);
        QVERIFY(clickDockTab(window, "Analysis"));
        QTRY_VERIFY(!dock->visibleRegion().isEmpty());
        QTRY_VERIFY(!scroll->verticalScrollBar()->isVisible());
        QVERIFY(scroll->viewport()->height() >= window.analysis().minimumSizeHint().height());
        auto* status = window.findChild<QLabel*>("analysisStatus");
        QVERIFY(status->text().contains("press Analyse"));
        auto* analyse = window.findChild<QPushButton*>("analyseButton");
        // The heatmap in cells of 0.5 m, typed into the Density tab's box.
        auto* cell = window.findChild<QDoubleSpinBox*>("analysisCell");
        QVERIFY(cell);
        QCOMPARE(cell->value(), 1.0);
        cell->selectAll();
        QTest::keyClicks(cell, "0.5");
        QTest::keyClick(cell, Qt::Key_Enter);
        QCOMPARE(cell->value(), 0.5);
        QTest::mouseClick(analyse, Qt::LeftButton);
        // It measures on a thread of its own, with progress and Stop meanwhile.
        QVERIFY(window.analysis().analysing());
        QVERIFY(!analyse->isEnabled());
        QVERIFY(window.findChild<QPushButton*>("stopAnalysisButton")->isVisible());
        QTRY_VERIFY(!window.analysis().analysing());
        QVERIFY(window.analysis().analysis().has_value());
        QCOMPARE(window.analysis().analysis()->density.cellM, 0.5);
        QVERIFY(analyse->isEnabled());
        QVERIFY(!window.findChild<QPushButton*>("stopAnalysisButton")->isVisible());
        QVERIFY(!window.simulation().hasCacheReader());

        // Recount: walkers past x = 12 between one frame and the next, and out at the end.
        int crossings = 0, out = 0;
        for (std::size_t f = 1; f < cache.frameCount(); ++f)
            for (std::size_t i = 0; i < cache.agentCount(); ++i) {
                const sim::AgentFrame &a = cache.at(f - 1, i), &b = cache.at(f, i);
                crossings += a.present && !a.out && a.position.x < 12.0f && b.position.x >= 12.0f ? 1 : 0;
            }
        for (std::size_t i = 0; i < cache.agentCount(); ++i)
            out += cache.at(cache.frameCount() - 1, i).out ? 1 : 0;
        QCOMPARE(crossings, 20);
        QVERIFY(out > 15);
        QTreeWidget* figures = window.analysis().figures();
        QCOMPARE(figure(figures, "Measurement line gate", "Crossings forward"), QString::number(crossings));
        QCOMPARE(figure(figures, "Measurement line gate", "Crossings backward"), QString("0"));
        QCOMPARE(figure(figures, "Exit out", "Agents out"), QString::number(out));
        QCOMPARE(figure(figures, "Measurement area before_gate", "Area"), QString("24.00 m²"));
        QVERIFY(!figure(figures, "Measurement area before_gate", "Mean speed while occupied").isEmpty());
        QVERIFY2(status->text().startsWith(QString("Measured %1 frames").arg(cache.frameCount())),
                 qPrintable(status->text()));
        QVERIFY(cache.frameCount() >= 720);

        // The flow tab plots the line and the exit.
        QTabWidget* tabs = window.analysis().tabs();
        QTabBar* bar = tabs->tabBar();
        int flowTab = -1;
        for (int t = 0; t < bar->count(); ++t)
            if (bar->tabText(t) == "Flow")
                flowTab = t;
        QVERIFY(flowTab >= 0);
        QTest::mouseClick(bar, Qt::LeftButton, Qt::NoModifier, bar->tabRect(flowTab).center());
        QCOMPARE(tabs->currentIndex(), flowTab);
        auto* flow = window.findChild<QChartView*>("analysisFlow");
        QStringList names;
        for (QAbstractSeries* s : flow->chart()->series())
            names << s->name();
        QCOMPARE(names, QStringList({"Line gate", "Exit out"}));
        QVERIFY(!window.findChild<QLabel*>("analysisDensity")->pixmap().isNull());

        // The report, as Save Report writes it after its file dialog.
        const QString path = m_dir.filePath("measured-report.html");
        QString error;
        QVERIFY2(window.analysis().saveReport(path, error), qPrintable(error));
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray html = file.readAll();
        QVERIFY(html.contains("measured.yaml"));
        QVERIFY(html.contains("Measurement line gate"));
        QVERIFY(html.contains("\"forward\": 20"));
        QVERIFY(!window.analysis().saveReport(m_dir.filePath("no/such/folder/r.html"), error));
        QVERIFY2(error.contains("no/such/folder"), qPrintable(error));

        // An edit the run reads re-records: the analysis says it is out of date.
        const QString before = status->text();
        QVERIFY(!before.contains("changed"));
        QUndoStack* stack = window.document().undoStack();
        window.viewport().setFocus();
        QTest::keyClick(&window.viewport(), Qt::Key_Q);
        QTRY_VERIFY(window.findChild<QAction*>("selectAction")->isChecked());
        clickOnGround(window, {20, 0});
        QCOMPARE(window.document().selection(), (Selection{{ItemKind::Goal, 0}}));
        const int steps = stack->count();
        dragOnGround(window, {{20, 0}, {19, 0}, {18, -1}});
        QCOMPARE(stack->count(), steps + 1);
        QTRY_VERIFY(status->text().contains("changed"));

        // Analysed again and stopped at once with Stop: the buttons come back, the
        // recording is free, and an analysis is shown (the one before, or this one if it
        // finished first).
        QTest::mouseClick(analyse, Qt::LeftButton);
        QTest::mouseClick(window.findChild<QPushButton*>("stopAnalysisButton"), Qt::LeftButton);
        QVERIFY(!window.analysis().analysing());
        QVERIFY(analyse->isEnabled() && !window.simulation().hasCacheReader());
        QVERIFY(window.analysis().analysis().has_value());

        // Another scene (the edit taken back first: nothing to save): the last one's
        // analysis goes.
        undo(window);
        QVERIFY(!window.document().isModified());
        QVERIFY(showWithYaml(window, m_dir, "other.yaml", kCorridor));
        QVERIFY(!window.analysis().analysis().has_value());
        QCOMPARE(figures->topLevelItemCount(), 0);
        QVERIFY(!window.findChild<QPushButton*>("saveReportButton")->isEnabled());
    }

    // The dock reads the recording in place on a thread of its own. While a reader is set,
    // the frames the simulation records wait (a Step computes its frame into the runner),
    // and they come once it is done; an edit the run reads stops the reader before it
    // drops any frame.
    void theRecordingHoldsStillWhileItIsRead()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "held.yaml", kCorridor));
        SimulationController& sim = window.simulation();
        QTRY_VERIFY(sim.recordedFrames() >= 1);
        QTest::qWait(200);  // paused at frame 0: nothing more is computed
        const std::size_t held = sim.recordedFrames();
        int stops = 0;
        std::size_t framesAtStop = 0;
        auto reader = [&] {
            ++stops;
            framesAtStop = sim.recordedFrames();
        };
        sim.setCacheReader(reader);
        window.viewport().setFocus();
        QTest::keyClick(&window.viewport(), Qt::Key_Period);  // Step
        QTest::qWait(500);
        QCOMPARE(sim.recordedFrames(), held);
        QCOMPARE(sim.currentFrame(), std::size_t(0));
        sim.clearCacheReader();
        QTRY_COMPARE(sim.recordedFrames(), held + 1);
        QTRY_COMPARE(sim.currentFrame(), held);
        QCOMPARE(stops, 0);

        // Dragging the exit with the mouse: the reader is stopped with every frame still there.
        sim.setCacheReader(reader);
        const std::size_t before = sim.recordedFrames();
        window.viewport().setFocus();
        QTest::keyClick(&window.viewport(), Qt::Key_Q);
        QTRY_VERIFY(window.findChild<QAction*>("selectAction")->isChecked());
        clickOnGround(window, {20, 0});
        QCOMPARE(window.document().selection(), (Selection{{ItemKind::Goal, 0}}));
        dragOnGround(window, {{20, 0}, {19, 0}, {18, -1}});
        QTRY_COMPARE(stops, 1);
        QCOMPARE(framesAtStop, before);
        QVERIFY(!sim.hasCacheReader());
    }
};

THRONG_REGISTER_TEST(TestAnalysisUi)
#include "TestAnalysisUi.moc"
