// Small editor gaps, driven like a user: the selection outline follows a selected agent
// while the simulation plays; the outliner lists flow strokes, selects one and deletes
// it with the Delete key (undo brings it back); a closed path's closing segment is
// clicked to select the path and double-clicked to insert a point; Escape during a drag
// takes it back and leaves neither an undo nor a redo step.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "TestRegistry.h"

#include "editor/panels/OutlinerPanel.h"
#include "editor/simulation/SimulationController.h"
#include "editor/viewport/Viewport.h"
#include "editor/viewport/ViewportPalette.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <cmath>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

const QByteArray kScene = R"(throng: 1
settings: {fps: 24, duration: 10, seed: 2, bounds: {min: [-12, -12], max: [12, 12]}}
agent_types: [{name: walker, radius: 0.3, max_speed: 1.4, max_force: 3, variation: {speed: [1, 1]}}]
goals: [{name: east, position: [9, -6], radius: 1}]
agents: [{id: 1, type: walker, position: [-8, 0, -6], goal: east}]
obstacles: [{name: post, shape: circle, center: [6, 6], radius: 0.8}]
paths: [{name: loop, points: [[-8, 2], [-2, 2], [-2, 8], [-8, 8]], radius: 1, closed: true}]
flow_strokes:
  - {points: [[0, -2], [4, -2], [8, -2]], width: 2}
  - {points: [[0, 10], [4, 10], [8, 10]], width: 3}
)";

// Of 24 points on a circle of `radiusM` round `centre`, how many show the selection colour.
int selectionPixelsAround(MainWindow& window, const QImage& image, glm::vec2 centre, float radiusM)
{
    int hits = 0;
    for (int k = 0; k < 24; ++k) {
        const float a = float(k) * 6.2831853f / 24.0f;
        const glm::vec3 p(centre.x + radiusM * std::cos(a), 0.0f, centre.y + radiusM * std::sin(a));
        hits += sameColour(pixelAt(image, window.viewport(), window.viewport().worldToPixel(p)), palette::kSelection, 40);
    }
    return hits;
}

Selection only(ItemKind kind, std::size_t index)
{
    return {SceneItem{kind, index}};
}

}  // namespace

class TestEditorGapsUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

    bool open(MainWindow& window) { return showWithSceneFile(window, writeScene(m_dir, "gaps.yaml", kScene)); }

private slots:
    void selectionOutlineFollowsTheAgentDuringPlayback()
    {
        MainWindow window;
        QVERIFY(open(window));
        QVERIFY(clickToolButton(window, "select"));
        clickOnGround(window, {-8, -6});
        QVERIFY(window.document().selection() == only(ItemKind::Agent, 0));
        const float ring = 0.3f + 0.25f;  // body radius + the outline's margin
        QTest::qWait(50);
        QImage shown = window.viewport().grabFramebuffer();
        QVERIFY(selectionPixelsAround(window, shown, {-8, -6}, ring) >= 16);

        SimulationController& sim = window.simulation();
        QTRY_VERIFY_WITH_TIMEOUT(sim.recordedFrames() > 0, 30000);
        sim.play();
        QTRY_VERIFY_WITH_TIMEOUT(sim.currentFrame() >= 72, 30000);
        sim.pause();
        const glm::vec3 now = sim.cache().at(sim.currentFrame(), 0).position;
        QVERIFY2(glm::distance(glm::vec2(now.x, now.z), glm::vec2(-8, -6)) > 3.0f, "the agent walked");
        QTest::qWait(50);
        shown = window.viewport().grabFramebuffer();
        const int atAgent = selectionPixelsAround(window, shown, {now.x, now.z}, ring);
        const int atStart = selectionPixelsAround(window, shown, {-8, -6}, ring);
        QVERIFY2(atAgent >= 16 && atStart <= 2, qPrintable(QString("%1 at the agent, %2 at the start").arg(atAgent).arg(atStart)));
        // Scrubbing back to frame 0 brings the outline back to the start.
        sim.seek(0);
        QTest::qWait(50);
        shown = window.viewport().grabFramebuffer();
        QVERIFY(selectionPixelsAround(window, shown, {-8, -6}, ring) >= 16);
    }

    void outlinerListsFlowStrokesSelectsAndDeletesThem()
    {
        MainWindow window;
        QVERIFY(open(window));
        const std::vector<sim::FlowStroke> before = window.document().scene().flowStrokes;
        OutlinerPanel& outliner = window.outliner();
        QTreeWidgetItem* heading = outliner.kindRow(ItemKind::FlowStroke);
        QVERIFY(heading);
        QCOMPARE(heading->childCount(), 2);
        QVERIFY(heading->text(0).contains("2"));
        heading->setExpanded(true);
        QTreeWidgetItem* second = heading->child(1);
        outliner.scrollToItem(second);
        QTest::mouseClick(outliner.viewport(), Qt::LeftButton, {}, outliner.visualItemRect(second).center());
        QVERIFY(window.document().selection() == only(ItemKind::FlowStroke, 1));

        QTest::keyClick(&outliner, Qt::Key_Delete);
        QTRY_COMPARE(window.document().scene().flowStrokes.size(), std::size_t(1));
        QVERIFY(window.document().scene().flowStrokes[0] == before[0]);
        QTRY_COMPARE(outliner.kindRow(ItemKind::FlowStroke)->childCount(), 1);
        QCOMPARE(window.document().undoStack()->count(), 1);

        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QTRY_VERIFY(window.document().scene().flowStrokes == before);
        QTRY_COMPARE(outliner.kindRow(ItemKind::FlowStroke)->childCount(), 2);
    }

    void closedPathsClosingSegmentSelectsAndTakesANewPoint()
    {
        MainWindow window;
        QVERIFY(open(window));
        QVERIFY(clickToolButton(window, "select"));
        // (-8, 5) lies on the closing segment, from the last point (-8, 8) back to (-8, 2).
        clickOnGround(window, {-8, 5});
        QVERIFY(window.document().selection() == only(ItemKind::Path, 0));
        QTest::mouseDClick(&window.viewport(), Qt::LeftButton, Qt::NoModifier, pixelOf(window, {-8, 5}));
        const std::vector<glm::vec2>& points = window.document().scene().paths[0].points;
        QCOMPARE(points.size(), std::size_t(5));
        QVERIFY2(glm::distance(points[4], glm::vec2(-8, 5)) < 0.3f,
                 qPrintable(QString("%1, %2").arg(points[4].x).arg(points[4].y)));
        QCOMPARE(window.document().undoStack()->count(), 1);
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QTRY_COMPARE(window.document().scene().paths[0].points.size(), std::size_t(4));
    }

    void escapeDuringADragLeavesNoUndoOrRedoStep()
    {
        MainWindow window;
        QVERIFY(open(window));
        QUndoStack* stack = window.document().undoStack();
        QWidget* viewport = &window.viewport();
        // Moving the post with the select tool, then Escape before the release.
        QVERIFY(clickToolButton(window, "select"));
        clickOnGround(window, {6, 6});
        QVERIFY(window.document().selection() == only(ItemKind::Obstacle, 0));
        QTest::mousePress(viewport, Qt::LeftButton, Qt::NoModifier, pixelOf(window, {6, 6}));
        for (int k = 1; k <= 6; ++k)
            QTest::mouseMove(viewport, pixelOf(window, {6.0f + float(k), 6.0f}));
        QVERIFY(window.document().scene().obstacles[0].center.x > 10.0f);
        QTest::keyClick(viewport, Qt::Key_Escape);
        QTest::mouseRelease(viewport, Qt::LeftButton, Qt::NoModifier, pixelOf(window, {12, 6}));
        QVERIFY(glm::distance(window.document().scene().obstacles[0].center, glm::vec2(6, 6)) < 1e-4f);
        QCOMPARE(stack->count(), 0);
        QVERIFY(!stack->canUndo() && !stack->canRedo());

        // A crowd brush stroke cancelled halfway: no agent added, nothing to undo or redo.
        QVERIFY(clickToolButton(window, "crowdBrush"));
        QTest::mousePress(viewport, Qt::LeftButton, Qt::NoModifier, pixelOf(window, {-6, 4}));
        for (int k = 1; k <= 8; ++k)
            QTest::mouseMove(viewport, pixelOf(window, {-6.0f + float(k), 4.0f}));
        QVERIFY(window.document().scene().agents.size() > 1);
        QTest::keyClick(viewport, Qt::Key_Escape);
        for (int k = 1; k <= 4; ++k)
            QTest::mouseMove(viewport, pixelOf(window, {2.0f + float(k), 4.0f}));
        QTest::mouseRelease(viewport, Qt::LeftButton, Qt::NoModifier, pixelOf(window, {6, 4}));
        QCOMPARE(window.document().scene().agents.size(), std::size_t(1));
        QCOMPARE(stack->count(), 0);
        QVERIFY(!stack->canUndo() && !stack->canRedo());
    }
};

THRONG_REGISTER_TEST(TestEditorGapsUi)
#include "TestEditorGapsUi.moc"
