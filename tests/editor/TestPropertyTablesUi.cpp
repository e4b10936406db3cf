// The properties panel's tables and choices driven like a user: a path's points edited
// in their table (a cell, Add point, Remove point, refused below two points), an
// obstacle turned into a box and sized, a group's area moved, refused when inverted and
// turned into a circle, an agent's leader (refused on itself), look, tint and height, and
// a brain deleted from the outliner (refused while an agent runs it). Each edit is one
// undo step, and undoing them all gives back the same saved bytes.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "PanelTestScene.h"
#include "TestRegistry.h"

#include "editor/panels/OutlinerPanel.h"
#include "editor/simulation/SimulationController.h"
#include "editor/viewport/Viewport.h"

#include <glm/geometric.hpp>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QTableWidget>
#include <QTest>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

// Double-clicks a cell of the points table, types `text` over it and presses Return.
void editCell(MainWindow& window, QTableWidget* table, int row, int column, const QString& text)
{
    showInPanel(window, table);
    const QPoint cell = table->visualItemRect(table->item(row, column)).center();
    QTest::mouseClick(table->viewport(), Qt::LeftButton, {}, cell);
    QTest::mouseDClick(table->viewport(), Qt::LeftButton, {}, cell);
    auto* editor = table->viewport()->findChild<QDoubleSpinBox*>();
    QVERIFY2(editor && editor->isVisible(), "the cell's editor is open");
    QTest::keyClick(editor, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(editor, text);
    QTest::keyClick(editor, Qt::Key_Return);
}

void clickRow(MainWindow& window, QTableWidget* table, int row)
{
    showInPanel(window, table);
    QTest::mouseClick(table->viewport(), Qt::LeftButton, {}, table->visualItemRect(table->item(row, 0)).center());
}

}  // namespace

class TestPropertyTablesUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void aPathsPointsAreEditedInTheirTable()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "points.yaml", tablesScene()));
        const QByteArray before = sceneYaml(window);
        const sim::Scene& scene = window.document().scene();
        selectInOutliner(window, {{ItemKind::Path, 1}});  // "lone": (-20, 20) to (-10, 20)
        auto* table = field<QTableWidget>(window, "points");
        QVERIFY(table);
        QCOMPARE(table->rowCount(), 2);
        QCOMPARE(table->item(1, 0)->data(Qt::EditRole).toDouble(), -10.0);

        editCell(window, table, 1, 0, "-4");
        QTRY_COMPARE(scene.paths[1].points[1], glm::vec2(-4, 20));
        QCOMPARE(window.document().undoStack()->count(), 1);
        QTRY_COMPARE(table->item(1, 0)->data(Qt::EditRole).toDouble(), -4.0);

        clickRow(window, table, 0);
        press(window, "addPoint");  // halfway between the first and the second
        QCOMPARE(scene.paths[1].points.size(), std::size_t(3));
        QCOMPARE(scene.paths[1].points[1], glm::vec2(-12, 20));
        QCOMPARE(table->rowCount(), 3);
        QCOMPARE(window.document().undoStack()->count(), 2);

        clickRow(window, table, 2);
        press(window, "removePoint");
        QCOMPARE(scene.paths[1].points, (std::vector<glm::vec2>{{-20, 20}, {-12, 20}}));
        QCOMPARE(window.document().undoStack()->count(), 3);
        clickRow(window, table, 0);
        press(window, "removePoint");  // two points stay
        QCOMPARE(scene.paths[1].points.size(), std::size_t(2));
        QCOMPARE(window.document().undoStack()->count(), 3);
        QVERIFY2(lastMessage(window).contains("at least 2 points"), qPrintable(lastMessage(window)));

        for (int k = 0; k < 3; ++k)
            undo(window);
        QCOMPARE(sceneYaml(window), before);
        QTRY_COMPARE(table->rowCount(), 2);
        // Redo the moved point: the select tool now finds the path where it reaches.
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QVERIFY(clickToolButton(window, "select"));
        clickOnGround(window, {-6, 20});
        QVERIFY(window.document().selection() == (Selection{{ItemKind::Path, 1}}));

        // Two paths with different points: "(mixed)", nothing to edit.
        selectInOutliner(window, {{ItemKind::Path, 0}, {ItemKind::Path, 1}});
        table = field<QTableWidget>(window, "points");
        QVERIFY(!table->isEnabled());
        QCOMPARE(table->rowCount(), 0);
    }

    void aWallsAndALanesPointsShowInTheTable()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "wall.yaml", tablesScene()));
        selectInOutliner(window, {{ItemKind::Wall, 0}});
        auto* table = field<QTableWidget>(window, "points");
        QCOMPARE(table->rowCount(), 2);
        editCell(window, table, 0, 1, "12");
        QTRY_COMPARE(window.document().scene().walls[0].points[0], glm::vec2(-5, 12));
        selectInOutliner(window, {{ItemKind::Lane, 1}});
        table = field<QTableWidget>(window, "points");
        QCOMPARE(table->item(1, 0)->data(Qt::EditRole).toDouble(), 30.0);
        QCOMPARE(table->item(1, 1)->data(Qt::EditRole).toDouble(), -27.0);
    }

    void anObstacleBecomesABoxWithASize()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "box.yaml", tablesScene()));
        const QByteArray before = sceneYaml(window);
        const sim::Scene& scene = window.document().scene();
        selectInOutliner(window, {{ItemKind::Obstacle, 1}});  // "post", round
        QCOMPARE(field<QComboBox>(window, "shape")->currentText(), QString("Circle"));
        QTRY_VERIFY(field<QDoubleSpinBox>(window, "radius")->isVisible());
        QVERIFY(!field<QDoubleSpinBox>(window, "width")->isVisible());
        pick(window, "shape", "Box");
        QCOMPARE(scene.obstacles[1].shape, sim::ObstacleShape::Box);
        QTRY_VERIFY(field<QDoubleSpinBox>(window, "width")->isVisible());
        QVERIFY(!field<QDoubleSpinBox>(window, "radius")->isVisible());
        typeInto(field<QDoubleSpinBox>(window, "width"), "3");
        typeInto(field<QDoubleSpinBox>(window, "depth"), "0.5");
        QCOMPARE(scene.obstacles[1].size, glm::vec2(3, 0.5f));
        QCOMPARE(window.document().undoStack()->count(), 3);

        selectInOutliner(window, {{ItemKind::Obstacle, 0}, {ItemKind::Obstacle, 1}});
        QCOMPARE(field<QComboBox>(window, "shape")->currentText(), QString("Box"));
        QCOMPARE(field<QDoubleSpinBox>(window, "width")->text(), QString("(mixed)"));
        QCOMPARE(field<QDoubleSpinBox>(window, "depth")->text(), QString("(mixed)"));
        QVERIFY(!field<QDoubleSpinBox>(window, "radius")->isVisible());
        for (int k = 0; k < 3; ++k)
            undo(window);
        QCOMPARE(sceneYaml(window), before);
    }

    void aGroupsAreaIsMovedAndTurnedIntoACircle()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "area.yaml", tablesScene()));
        const QByteArray before = sceneYaml(window);
        const sim::SpawnGroup& group = window.document().scene().groups[0];  // rect (-20, -22) to (-15, -18)
        selectInOutliner(window, {{ItemKind::Group, 0}});
        QCOMPARE(field<QComboBox>(window, "shape")->currentText(), QString("Rectangle"));
        QCOMPARE(field<QDoubleSpinBox>(window, "minX")->value(), -20.0);
        QVERIFY(!field<QDoubleSpinBox>(window, "altitudeMin")->isVisibleTo(window.findChild<QWidget*>("properties")));

        typeInto(field<QDoubleSpinBox>(window, "minX"), "-10");  // past max x = -15
        QCOMPARE(group.min.x, -20.0f);
        QVERIFY2(lastMessage(window).contains("cannot exceed"), qPrintable(lastMessage(window)));
        QVERIFY(field<QDoubleSpinBox>(window, "minX")->toolTip().contains("cannot exceed"));
        QCOMPARE(field<QDoubleSpinBox>(window, "minX")->value(), -20.0);
        QCOMPARE(window.document().undoStack()->count(), 0);

        typeInto(field<QDoubleSpinBox>(window, "maxX"), "-12");
        QCOMPARE(group.max, glm::vec2(-12, -18));
        pick(window, "shape", "Circle");  // round the rectangle's middle, its half short side
        QCOMPARE(group.shape, sim::AreaShape::Circle);
        QCOMPARE(group.center, glm::vec2(-16, -20));
        QCOMPARE(group.radiusM, 2.0f);
        QCOMPARE(window.document().undoStack()->count(), 2);
        QTRY_VERIFY(field<QDoubleSpinBox>(window, "centreX")->isVisible());
        QVERIFY(!field<QDoubleSpinBox>(window, "minX")->isVisible());
        QCOMPARE(field<QDoubleSpinBox>(window, "radius")->value(), 2.0);

        // The run starts over with the five spawned in the circle.
        const sim::FrameCache& cache = window.simulation().cache();
        auto startingIn = [&](auto inside) {
            int n = 0;
            for (std::size_t k = 0; cache.frameCount() > 0 && k < cache.agentCount(); ++k)
                n += inside(glm::vec2(cache.at(0, k).position.x, cache.at(0, k).position.z)) ? 1 : 0;
            return n;
        };
        const auto circle = [](glm::vec2 p) { return glm::length(p - glm::vec2(-16, -20)) <= 2.01f; };
        const auto rect = [](glm::vec2 p) { return p.x >= -20 && p.x <= -15 && p.y >= -22 && p.y <= -18; };
        const auto wideRect = [](glm::vec2 p) { return p.x >= -20 && p.x <= -12 && p.y >= -22 && p.y <= -18; };
        QTRY_COMPARE(startingIn(circle), 5);
        undo(window);
        QTRY_COMPARE(startingIn(wideRect), 5);
        undo(window);
        QCOMPARE(sceneYaml(window), before);
        QTRY_COMPARE(startingIn(rect), 5);
    }

    void anAgentsLeaderLookTintAndHeight()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "agent.yaml", tablesScene()));
        const QByteArray before = sceneYaml(window);
        const sim::Scene& scene = window.document().scene();
        selectInOutliner(window, {{ItemKind::Agent, 1}});  // walker 2
        QCOMPARE(field<QComboBox>(window, "leader")->currentText(), QString("(none)"));
        QCOMPARE(field<QComboBox>(window, "look")->currentText(), QString("(drawn)"));
        QCOMPARE(field<QDoubleSpinBox>(window, "heightScale")->text(), QString("drawn"));

        pick(window, "leader", "1: agent walker");
        pick(window, "look", "formal");
        pick(window, "tint", "#0000ff");
        typeInto(field<QDoubleSpinBox>(window, "heightScale"), "1.2");
        const sim::Agent& agent = scene.agents[1];
        QCOMPARE(agent.leader, 1u);
        QCOMPARE(agent.look, 1);
        QCOMPARE(agent.tint, 1);
        QCOMPARE(agent.heightScale, 1.2f);
        QCOMPARE(window.document().undoStack()->count(), 4);

        // Walker 1 may not lead itself.
        selectInOutliner(window, {{ItemKind::Agent, 0}});
        auto* leader = field<QComboBox>(window, "leader");
        leader->setFocus();
        QTest::keyClicks(leader, "1");  // keyboard search: "1: agent walker"
        QCOMPARE(scene.agents[0].leader, 0u);
        QVERIFY2(lastMessage(window).contains("cannot lead itself"), qPrintable(lastMessage(window)));
        QCOMPARE(leader->currentText(), QString("(none)"));
        QVERIFY(leader->toolTip().contains("cannot lead itself"));
        QCOMPARE(window.document().undoStack()->count(), 4);

        // Walkers 2 and 3: one has a leader, the other not.
        selectInOutliner(window, {{ItemKind::Agent, 1}, {ItemKind::Agent, 2}});
        QCOMPARE(field<QComboBox>(window, "leader")->currentText(), QString("(mixed)"));
        QCOMPARE(field<QDoubleSpinBox>(window, "heightScale")->text(), QString("(mixed)"));
        for (int k = 0; k < 4; ++k)
            undo(window);
        QCOMPARE(sceneYaml(window), before);

        // A group's leader likewise.
        selectInOutliner(window, {{ItemKind::Group, 0}});
        pick(window, "leader", "3: agent walker");
        QCOMPARE(scene.groups[0].leader, 3u);
    }

    void aBrainIsDeletedFromTheOutlinerUnlessAnAgentRunsIt()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "brains.yaml", tablesScene()));
        const sim::Scene& scene = window.document().scene();
        selectInOutliner(window, {{ItemKind::Agent, 2}});
        pick(window, "brain", "stay");
        const QByteArray before = sceneYaml(window);

        selectInOutliner(window, {{ItemKind::Brain, 1}});  // "stay", run by walker 3
        QTest::keyClick(&window.viewport(), Qt::Key_Delete);
        QCOMPARE(scene.brains.size(), std::size_t(2));
        QVERIFY2(lastMessage(window).contains("Agent 3 (walker)"), qPrintable(lastMessage(window)));

        selectInOutliner(window, {{ItemKind::Brain, 0}});  // "go", run by nobody
        QTest::keyClick(&window.viewport(), Qt::Key_Delete);
        QCOMPARE(scene.brains.size(), std::size_t(1));
        QCOMPARE(scene.brains[0].name, std::string("stay"));
        QCOMPARE(window.outliner().kindRow(ItemKind::Brain)->text(0), QString("Brains (1)"));
        undo(window);
        QCOMPARE(sceneYaml(window), before);
        QCOMPARE(window.outliner().kindRow(ItemKind::Brain)->text(0), QString("Brains (2)"));
    }
};

THRONG_REGISTER_TEST(TestPropertyTablesUi)
#include "TestPropertyTablesUi.moc"
