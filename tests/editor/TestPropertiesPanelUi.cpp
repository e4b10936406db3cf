// The properties panel driven like a user: pick agents in the viewport and set their
// brain, group and type with the panel's combo boxes, rename a path (refused when the
// name is taken; the group that follows it follows the new name), and change a
// behaviour weight in a type's table and see the simulation change. Each edit is one
// undo step, and a saved scene opens again with the values.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "PanelTestScene.h"
#include "TestRegistry.h"

#include "editor/MessagesPanel.h"
#include "editor/panels/OutlinerPanel.h"
#include "editor/simulation/SimulationController.h"
#include "editor/viewport/Viewport.h"

#include <glm/geometric.hpp>

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QScrollArea>
#include <QSpinBox>
#include <QStyle>
#include <QStyleOptionButton>
#include <QTableWidget>
#include <QTest>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

void redo(MainWindow& window)
{
    QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
}

// How far the walkers (ids 1..6) moved from frame 0 to `frame`, summed.
float walkerTravel(SimulationController& sim, std::size_t frame)
{
    float travel = 0.0f;
    for (std::size_t k = 0; k < sim.cache().agentCount(); ++k)
        if (sim.cache().agents()[k].id >= 1 && sim.cache().agents()[k].id <= 6)
            travel += glm::length(sim.cache().at(frame, k).position - sim.cache().at(0, k).position);
    return travel;
}

}  // namespace

class TestPropertiesPanelUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void agentBrainAndGroupFromTheCombosUndoRedoAndSave()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "brain.yaml", panelScene()));
        QVERIFY(clickToolButton(window, "select"));
        clickOnGround(window, {-2, 0});  // walker 3
        QVERIFY(window.document().selection() == (Selection{{ItemKind::Agent, 2}}));

        pick(window, "brain", "stay");
        auto* group = field<QComboBox>(window, "group");
        QVERIFY(group && group->isEditable());
        typeInto(group->lineEdit(), "regulars");
        const sim::Scene& scene = window.document().scene();
        QCOMPARE(scene.agents[2].brain, std::string("stay"));
        QCOMPARE(scene.agents[2].group, std::string("regulars"));
        QCOMPARE(scene.agents[1].brain, std::string());  // only the selected agent
        QCOMPARE(window.document().undoStack()->count(), 2);

        undo(window);
        QCOMPARE(scene.agents[2].group, std::string());
        QCOMPARE(field<QComboBox>(window, "group")->currentText(), QString("(none)"));
        undo(window);
        QCOMPARE(scene.agents[2].brain, std::string());
        QCOMPARE(field<QComboBox>(window, "brain")->currentText(), QString("(none)"));
        redo(window);
        redo(window);
        QCOMPARE(scene.agents[2].brain, std::string("stay"));
        QCOMPARE(scene.agents[2].group, std::string("regulars"));
        QCOMPARE(field<QComboBox>(window, "brain")->currentText(), QString("stay"));

        QTest::keyClick(&window.viewport(), Qt::Key_S, Qt::ControlModifier);
        QVERIFY(!window.document().isModified());
        MainWindow reopened;
        reopened.show();
        QVERIFY(reopened.openScene(window.document().filePath()));
        QCOMPARE(reopened.document().scene().agents[2].brain, std::string("stay"));
        QCOMPARE(reopened.document().scene().agents[2].group, std::string("regulars"));
    }

    void boxSelectedAgentsGetATypeInOneStep()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "type.yaml", panelScene()));
        QVERIFY(clickToolButton(window, "select"));
        dragOnGround(window, {{-12, -3}, {8, 3}});  // walkers 1..5, not 6 at x = 10
        QCOMPARE(window.document().selection().size(), std::size_t(5));
        QCOMPARE(field<QComboBox>(window, "type")->currentText(), QString("walker"));
        // A brain for all five first: one step.
        pick(window, "brain", "go");
        QCOMPARE(window.document().undoStack()->count(), 1);

        pick(window, "type", "runner");
        const sim::Scene& scene = window.document().scene();
        for (std::size_t i = 0; i < 5; ++i)
            QCOMPARE(scene.agents[i].type, std::string("runner"));
        QCOMPARE(scene.agents[5].type, std::string("walker"));
        QCOMPARE(window.document().undoStack()->count(), 2);  // one step for all five
        undo(window);
        for (std::size_t i = 0; i < 6; ++i)
            QCOMPARE(scene.agents[i].type, std::string("walker"));
        QCOMPARE(scene.agents[0].brain, std::string("go"));
    }

    void aMixedSelectionShowsMixed()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "mixed.yaml", panelScene()));
        selectInOutliner(window, {{ItemKind::Agent, 0}});
        pick(window, "brain", "go");
        selectInOutliner(window, {{ItemKind::Agent, 0}, {ItemKind::Agent, 1}});
        QCOMPARE(field<QComboBox>(window, "brain")->currentText(), QString("(mixed)"));
        QCOMPARE(field<QComboBox>(window, "goal")->currentText(), QString("east"));
        QCOMPARE(field<QDoubleSpinBox>(window, "x")->text(), QString("(mixed)"));
        QCOMPARE(field<QDoubleSpinBox>(window, "heading")->value(), 0.0);
        // Typing a heading sets it on both.
        auto* heading = field<QDoubleSpinBox>(window, "heading");
        heading->setFocus();
        heading->selectAll();
        QTest::keyClicks(heading, "90");
        QTest::keyClick(heading, Qt::Key_Return);
        QCOMPARE(window.document().scene().agents[0].headingDeg, 90.0f);
        QCOMPARE(window.document().scene().agents[1].headingDeg, 90.0f);
        QCOMPARE(window.document().scene().agents[2].headingDeg, 0.0f);
        QCOMPARE(window.document().undoStack()->count(), 2);  // the brain, the heading
        // Stepping the same field on (arrow keys, a drag of the arrows) merges into that step.
        QTest::keyClick(heading, Qt::Key_Up);
        QTest::keyClick(heading, Qt::Key_Up);
        QCOMPARE(window.document().scene().agents[1].headingDeg, 100.0f);
        QCOMPARE(window.document().undoStack()->count(), 2);
        undo(window);
        QCOMPARE(window.document().scene().agents[0].headingDeg, 0.0f);
        QCOMPARE(window.document().scene().agents[1].headingDeg, 0.0f);
        QCOMPARE(window.document().scene().agents[0].brain, std::string("go"));
    }

    void checkBoxesAndCountsEditPathsAndGroups()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "checks.yaml", panelScene()));
        const sim::Scene& scene = window.document().scene();
        selectInOutliner(window, {{ItemKind::Path, 0}, {ItemKind::Path, 1}});
        auto* closed = field<QCheckBox>(window, "closed");
        QVERIFY(closed);
        QTRY_VERIFY(closed->isVisible());
        QCOMPARE(closed->checkState(), Qt::Unchecked);
        QStyleOptionButton box;
        box.initFrom(closed);
        QTest::mouseClick(closed, Qt::LeftButton, {},
                          closed->style()->subElementRect(QStyle::SE_CheckBoxIndicator, &box, closed).center());
        QVERIFY(scene.paths[0].closed && scene.paths[1].closed);
        QCOMPARE(window.document().undoStack()->count(), 1);
        undo(window);
        QVERIFY(!scene.paths[0].closed && !scene.paths[1].closed);

        selectInOutliner(window, {{ItemKind::Group, 0}});
        auto* count = field<QSpinBox>(window, "count");
        QCOMPARE(count->value(), 5);
        count->setFocus();
        count->selectAll();
        QTest::keyClicks(count, "12");
        QTest::keyClick(count, Qt::Key_Return);
        QCOMPARE(scene.groups[0].count, 12u);
        pick(window, "goal", "spare");
        QCOMPARE(scene.groups[0].goal, std::string("spare"));
        QCOMPARE(window.document().undoStack()->count(), 2);  // the undone check replaced by the count, the goal
        QTRY_COMPARE(window.viewport().agentCount(), std::size_t(6 + 12 + 1 + 1));  // placed, group, car, hero
    }

    void renameAPathRefusesATakenNameAndCarriesItsFollowers()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "rename.yaml", panelScene()));
        const QByteArray before = sceneYaml(window);
        selectInOutliner(window, {{ItemKind::Path, 1}});  // "lone"
        auto* name = field<QLineEdit>(window, "name");
        QCOMPARE(name->text(), QString("lone"));
        typeInto(name, "loop");
        QCOMPARE(sceneYaml(window), before);
        QCOMPARE(window.document().undoStack()->count(), 0);
        QCOMPARE(name->text(), QString("lone"));
        QVERIFY2(window.messages().item(0)->text().contains("already named \"loop\""),
                 qPrintable(window.messages().item(0)->text()));
        QVERIFY(name->toolTip().contains("already named"));
        typeInto(field<QLineEdit>(window, "name"), "");
        QCOMPARE(sceneYaml(window), before);
        QVERIFY(window.messages().item(0)->text().contains("cannot be empty"));

        selectInOutliner(window, {{ItemKind::Path, 0}});  // "loop", followed by "loopers"
        typeInto(field<QLineEdit>(window, "name"), "circuit");
        const sim::Scene& scene = window.document().scene();
        QCOMPARE(scene.paths[0].name, std::string("circuit"));
        QCOMPARE(scene.groups[0].path, std::string("circuit"));
        QCOMPARE(window.document().undoStack()->count(), 1);
        QCOMPARE(window.outliner().kindRow(ItemKind::Path)->child(0)->text(0), QString("circuit"));
        undo(window);
        QCOMPARE(sceneYaml(window), before);
    }

    void aBehaviourWeightChangesTheRunAndUndoRestoresIt()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "weights.yaml", panelScene()));
        SimulationController& sim = window.simulation();
        QVERIFY(playToFrame(window, 24));
        const float walked = walkerTravel(sim, 24);
        QVERIFY2(walked > 3.0f, qPrintable(QString::number(walked)));
        QVERIFY(clickButton(window, "restartButton"));
        QCOMPARE(window.viewport().frameIndex(), std::size_t(0));

        selectInOutliner(window, {{ItemKind::AgentType, 0}});  // walker
        auto* table = field<QTableWidget>(window, "behaviourTable");
        QVERIFY(table);
        QCOMPARE(table->rowCount(), 2);
        QCOMPARE(table->item(0, 0)->text(), QString("arrival"));
        QCOMPARE(table->item(0, 1)->data(Qt::EditRole).toDouble(), 1.0);
        QTRY_VERIFY(table->isVisible());  // rows added to a shown panel show on the next event loop pass
        // Scroll down to the table, double-click the arrival weight, type 0.1, Enter.
        window.findChild<QWidget*>("properties")->findChild<QScrollArea*>()->ensureWidgetVisible(table);
        const QPoint cell = table->visualItemRect(table->item(0, 1)).center();
        QTest::mouseClick(table->viewport(), Qt::LeftButton, {}, cell);
        QTest::mouseDClick(table->viewport(), Qt::LeftButton, {}, cell);
        auto* editor = table->viewport()->findChild<QDoubleSpinBox*>();
        QVERIFY2(editor && editor->isVisible(), "the weight's editor is open");
        QTest::keyClick(editor, Qt::Key_A, Qt::ControlModifier);
        QTest::keyClicks(editor, "0.1");
        QTest::keyClick(editor, Qt::Key_Return);
        const sim::Scene& scene = window.document().scene();
        QTRY_COMPARE(scene.agentTypes[0].behaviours[0].weight, 0.1f);
        QCOMPARE(scene.agentTypes[0].behaviours[1].weight, 1.5f);
        QCOMPARE(window.document().undoStack()->count(), 1);
        // The edit drops the recorded frames (a type edit starts the run over).
        QTRY_VERIFY(sim.recordedFrames() <= 1);

        QVERIFY(playToFrame(window, 24));
        const float slowed = walkerTravel(sim, 24);
        QVERIFY2(slowed < 0.5f * walked, qPrintable(QString("%1 m against %2 m").arg(slowed).arg(walked)));

        QVERIFY(clickButton(window, "restartButton"));
        undo(window);
        QCOMPARE(scene.agentTypes[0].behaviours[0].weight, 1.0f);
        QTRY_COMPARE(table->item(0, 1)->data(Qt::EditRole).toDouble(), 1.0);
        QTRY_VERIFY(sim.recordedFrames() <= 1);
        QVERIFY(playToFrame(window, 24));
        QCOMPARE(walkerTravel(sim, 24), walked);

        // Redo and undo while paused mid-run: the frames up to the shown one stay and the
        // run resumes from there with the edited weight (an undo there once crashed the
        // simulation thread).
        redo(window);
        QTRY_COMPARE(scene.agentTypes[0].behaviours[0].weight, 0.1f);
        QVERIFY(playToFrame(window, 48));
        QCOMPARE(walkerTravel(sim, 24), walked);
        const float weakSecond = walkerTravel(sim, 48) - walked;
        undo(window);
        QCOMPARE(scene.agentTypes[0].behaviours[0].weight, 1.0f);
        QVERIFY(playToFrame(window, 72));
        QCOMPARE(walkerTravel(sim, 24), walked);
        QCOMPARE(walkerTravel(sim, 48) - walked, weakSecond);
        QVERIFY(walkerTravel(sim, 72) > walkerTravel(sim, 48));
    }
};

THRONG_REGISTER_TEST(TestPropertiesPanelUi)
#include "TestPropertiesPanelUi.moc"
