// The editor driven like a user: open the crossroads demo, pick a tool on the tool bar,
// paint, erase and draw on the viewport with real mouse events, and undo and redo with
// the keyboard. Checks what the user would see: counts, positions, outliner rows.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "TestRegistry.h"

#include "editor/MessagesPanel.h"
#include "editor/panels/OutlinerPanel.h"
#include "editor/tools/ToolManager.h"
#include "editor/viewport/Viewport.h"

#include <glm/geometric.hpp>

#include <QDoubleSpinBox>
#include <QLabel>
#include <QTest>

#include <algorithm>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

// Distance from p to the segment ab, on the ground.
float segmentDistance(glm::vec2 p, glm::vec2 a, glm::vec2 b)
{
    const glm::vec2 ab = b - a;
    const float t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
    return glm::length(p - (a + t * ab));
}

// The crossroads scene shows 210 agents from its spawn groups; placed agents add to them.

}  // namespace

class TestEditingUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void crowdBrushStrokeAddsAgentsAlongItAndUndoRedoWork()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        QCOMPARE(agentCountText(window), QString("%1 agents").arg(kCrossroadsAgents));
        QVERIFY(clickToolButton(window, "crowdBrush"));

        // Across the open block north-west of the crossing, away from walls and posts.
        const glm::vec2 from(-35, -25), to(-15, -25);
        dragOnGround(window, {from, to});
        const std::vector<sim::Agent>& agents = window.document().scene().agents;
        // 3 m brush, 0.5 agents/m2 over a 20 m x 6 m band: about 70 agents.
        QVERIFY2(agents.size() >= 40 && agents.size() <= 110, qPrintable(QString::number(agents.size())));
        float minX = 1e9f, maxX = -1e9f;
        for (const sim::Agent& a : agents) {
            const glm::vec2 p(a.position.x, a.position.z);
            QVERIFY2(segmentDistance(p, from, to) <= 3.0f + 0.2f,
                     qPrintable(QString("agent at %1, %2 is off the stroke").arg(p.x).arg(p.y)));
            minX = std::min(minX, p.x);
            maxX = std::max(maxX, p.x);
        }
        QVERIFY2(minX < -33.0f && maxX > -17.0f, "the agents must cover the whole stroke");
        const std::size_t painted = agents.size();
        QCOMPARE(window.document().undoStack()->count(), 1);  // the stroke is one step
        QTRY_COMPARE(agentCountText(window), QString("%1 agents").arg(kCrossroadsAgents + painted));

        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QTRY_COMPARE(window.document().scene().agents.size(), std::size_t(0));
        QTRY_COMPARE(agentCountText(window), QString("%1 agents").arg(kCrossroadsAgents));
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QTRY_COMPARE(window.document().scene().agents.size(), painted);
        QTRY_COMPARE(agentCountText(window), QString("%1 agents").arg(kCrossroadsAgents + painted));
    }

    void eraseBrushRemovesOnlyUnderTheBrush()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        QVERIFY(clickToolButton(window, "crowdBrush"));
        dragOnGround(window, {{-35, -25}, {-15, -25}});
        const std::size_t painted = window.document().scene().agents.size();
        QVERIFY(clickToolButton(window, "eraseBrush"));
        dragOnGround(window, {{-35, -25}, {-30, -25}});  // 2 m brush over the stroke's west end
        const std::vector<sim::Agent>& left = window.document().scene().agents;
        QVERIFY2(left.size() < painted && left.size() > painted / 3,
                 qPrintable(QString("%1 of %2").arg(left.size()).arg(painted)));
        for (const sim::Agent& a : left)
            QVERIFY(segmentDistance({a.position.x, a.position.z}, {-35, -25}, {-30, -25}) > 2.0f - 0.2f);
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QTRY_COMPARE(window.document().scene().agents.size(), painted);
    }

    void wallDrawnWithClicksShowsInTheOutliner()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        QCOMPARE(window.outliner().kindRow(ItemKind::Wall)->text(0), QString("Walls (4)"));
        QVERIFY(clickToolButton(window, "wall"));
        const std::vector<glm::vec2> corners{{-30, -30}, {-20, -30}, {-20, -20}};
        for (glm::vec2 c : corners)
            clickOnGround(window, c);
        QCOMPARE(window.document().scene().walls.size(), std::size_t(4));  // not before Enter
        QTest::keyClick(&window.viewport(), Qt::Key_Return);
        const auto& walls = window.document().scene().walls;
        QCOMPARE(walls.size(), std::size_t(5));
        QCOMPARE(walls.back().points.size(), corners.size());
        for (std::size_t i = 0; i < corners.size(); ++i)
            QVERIFY2(glm::length(walls.back().points[i] - corners[i]) < 0.3f,
                     qPrintable(QString("corner %1 at %2, %3").arg(i).arg(walls.back().points[i].x).arg(walls.back().points[i].y)));
        QTreeWidgetItem* row = window.outliner().kindRow(ItemKind::Wall);
        QCOMPARE(row->text(0), QString("Walls (5)"));
        QCOMPARE(row->child(4)->text(0), QString::fromStdString(walls.back().name));

        // Escape throws an unfinished wall away.
        clickOnGround(window, {-40, -40});
        clickOnGround(window, {-38, -40});
        QTest::keyClick(&window.viewport(), Qt::Key_Escape);
        QTest::keyClick(&window.viewport(), Qt::Key_Return);
        QCOMPARE(walls.size(), std::size_t(5));

        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(window.outliner().kindRow(ItemKind::Wall)->text(0), QString("Walls (4)"));
    }

    void trafficLightPlacedWhereClicked()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        QVERIFY(clickToolButton(window, "trafficLight"));
        clickOnGround(window, {20, -12});
        const auto& lights = window.document().scene().trafficLights;
        QCOMPARE(lights.size(), std::size_t(3));
        QVERIFY(glm::length(lights.back().position - glm::vec2(20, -12)) < 0.3f);
        QVERIFY(lights.back().greenS > 0.0f && lights.back().redS > 0.0f);
        QCOMPARE(window.outliner().kindRow(ItemKind::TrafficLight)->text(0), QString("Traffic Lights (3)"));
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(lights.size(), std::size_t(2));
    }

    void doubleClickingAMessageSelectsItsItem()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        sim::Diagnostic about{sim::Severity::Warning, "crossroads.yaml", 33, 5, "walls[1].points", "a sharp corner"};
        window.messages().showDiagnostics("Checked.", {about});
        QListWidgetItem* row = window.messages().item(1);
        QVERIFY(row && row->text().contains("crossroads.yaml:33:5"));
        QWidget* list = window.messages().viewport();
        const QPoint at = window.messages().visualItemRect(row).center();
        QTest::mouseClick(list, Qt::LeftButton, Qt::NoModifier, at);
        QTest::mouseDClick(list, Qt::LeftButton, Qt::NoModifier, at);
        QCOMPARE(window.document().selection().size(), std::size_t(1));
        QVERIFY(window.document().selection().front() == (SceneItem{ItemKind::Wall, 1}));
        QTreeWidgetItem* wall = window.outliner().kindRow(ItemKind::Wall)->child(1);
        QVERIFY(wall->isSelected());
    }

    void propertiesEditTheSelectedItemsAsOneUndoStep()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        // Pick two obstacles in the outliner, the second with Ctrl held.
        QTreeWidgetItem* obstacles = window.outliner().kindRow(ItemKind::Obstacle);
        obstacles->setExpanded(true);
        QWidget* tree = window.outliner().viewport();
        QTest::mouseClick(tree, Qt::LeftButton, Qt::NoModifier,
                          window.outliner().visualItemRect(obstacles->child(0)).center());
        QTest::mouseClick(tree, Qt::LeftButton, Qt::ControlModifier,
                          window.outliner().visualItemRect(obstacles->child(2)).center());
        QCOMPARE(window.document().selection().size(), std::size_t(2));

        auto* radius = window.findChild<QWidget*>("properties")->findChild<QDoubleSpinBox*>("radius");
        QVERIFY(radius);
        QCOMPARE(radius->value(), 0.4);
        radius->selectAll();
        QTest::keyClicks(radius, "1.25");
        QTest::keyClick(radius, Qt::Key_Return);
        const auto& scene = window.document().scene();
        QCOMPARE(scene.obstacles[0].radiusM, 1.25f);
        QCOMPARE(scene.obstacles[2].radiusM, 1.25f);
        QCOMPARE(scene.obstacles[1].radiusM, 0.4f);
        QCOMPARE(window.document().undoStack()->count(), 1);
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(scene.obstacles[0].radiusM, 0.4f);
        QCOMPARE(scene.obstacles[2].radiusM, 0.4f);
    }

    void selectToolPicksAndDragsAnObstacleInOneStep()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        QVERIFY(clickToolButton(window, "select"));
        // The lamp post at (-7.5, -20) on the north-west sidewalk, dragged 10 m west.
        dragOnGround(window, {{-7.5f, -20.0f}, {-17.5f, -20.0f}});
        const auto& scene = window.document().scene();
        QVERIFY(window.document().selection() == (Selection{{ItemKind::Obstacle, 0}}));
        QVERIFY2(glm::length(scene.obstacles[0].center - glm::vec2(-17.5f, -20.0f)) < 0.3f,
                 qPrintable(QString("at %1, %2").arg(scene.obstacles[0].center.x).arg(scene.obstacles[0].center.y)));
        QCOMPARE(window.document().undoStack()->count(), 1);
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(scene.obstacles[0].center, glm::vec2(-7.5f, -20.0f));
        // A click on empty ground clears the selection.
        clickOnGround(window, {-30, -30});
        QVERIFY(window.document().selection().empty());
    }

    void toolShortcutsPickTools()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        QTest::keyClick(&window.viewport(), Qt::Key_B);
        QCOMPARE(window.tools().activeTool()->objectKey(), QString("crowdBrush"));
        QTest::keyClick(&window.viewport(), Qt::Key_W);
        QCOMPARE(window.tools().activeTool()->objectKey(), QString("wall"));
        for (ViewportTool* t : window.tools().tools())
            QVERIFY2(!t->toolTip().isEmpty() && !t->shortcut().isEmpty(), qPrintable(t->name()));
    }
};

THRONG_REGISTER_TEST(TestEditingUi)
#include "TestEditingUi.moc"
