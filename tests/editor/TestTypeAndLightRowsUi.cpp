// An agent type's look, collisions and flier rows and a traffic light's stop lines in the properties
// panel, driven like a user: looks typed as a list, a tint picked in the colour dialog,
// tints added and removed, an inverted range and an unknown character refused, layers
// set; a light's stop lines moved along their lane, put on another lane, turned into a
// crosswalk stop, added and removed. Each edit is one undo step, and undoing them all
// gives back the same saved bytes. A walker type's reaction times, ages and time gap.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "PanelTestScene.h"
#include "TestRegistry.h"

#include "editor/panels/OutlinerPanel.h"
#include "editor/viewport/Viewport.h"
#include "simcore/io/SceneIO.h"

#include <QColorDialog>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QHeaderView>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTableWidget>
#include <QTest>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

void clickRow(MainWindow& window, QTableWidget* table, int row)
{
    showInPanel(window, table);
    QHeaderView* header = table->verticalHeader();
    const QPoint at(header->width() / 2, header->sectionViewportPosition(row) + header->sectionSize(row) / 2);
    QTest::mouseClick(header->viewport(), Qt::LeftButton, {}, at);
    QCOMPARE(table->currentRow(), row);
}

}  // namespace

class TestTypeAndLightRowsUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void aTypesLooksTintsCharacterAndLayers()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "type.yaml", tablesScene()));
        const QByteArray before = sceneYaml(window);
        const sim::AgentType& walker = window.document().scene().agentTypes[0];
        selectInOutliner(window, {{ItemKind::AgentType, 0}});
        QCOMPARE(field<QLineEdit>(window, "looks")->text(), QString("casual, formal"));

        typeInto(window, field<QLineEdit>(window, "looks"), "casual, formal, sporty");
        QCOMPARE(walker.variation.looks, (std::vector<std::string>{"casual", "formal", "sporty"}));
        QCOMPARE(window.document().undoStack()->count(), 1);

        auto* tints = field<QTableWidget>(window, "tints");
        QCOMPARE(tints->rowCount(), 2);
        QCOMPARE(tints->item(0, 0)->text(), QString("#ff0000"));
        showInPanel(window, tints);
        QTest::mouseClick(tints->viewport(), Qt::LeftButton, {}, tints->visualItemRect(tints->item(1, 0)).center());
        QCOMPARE(tints->currentRow(), 1);
        press(window, "pickTint");
        auto* dialog = window.findChild<QColorDialog*>("tintDialog");
        QVERIFY(dialog);
        QTRY_VERIFY(dialog->isVisible());
        QCOMPARE(dialog->currentColor(), QColor("#0000ff"));
        dialog->setCurrentColor(QColor("#00ff00"));
        QTest::mouseClick(dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok), Qt::LeftButton);
        QCOMPARE(walker.variation.tints[1], glm::vec3(0, 1, 0));
        QCOMPARE(tints->item(1, 0)->text(), QString("#00ff00"));
        press(window, "addTint");
        QCOMPARE(walker.variation.tints.size(), std::size_t(3));
        QCOMPARE(walker.variation.tints[2], glm::vec3(1));
        press(window, "removeTint");  // the new one, selected
        QCOMPARE(walker.variation.tints.size(), std::size_t(2));
        QCOMPARE(window.document().undoStack()->count(), 4);

        // A minimum above its maximum, a character that is not one: refused.
        typeInto(window, field<QDoubleSpinBox>(window, "heightMin"), "2");
        QCOMPARE(walker.variation.heightScale.x, 1.0f);
        QVERIFY2(lastMessage(window).contains("cannot exceed"), qPrintable(lastMessage(window)));
        auto* character = field<QComboBox>(window, "character");
        typeInto(window, character->lineEdit(), "robot");
        QCOMPARE(walker.character, std::string());
        QVERIFY2(lastMessage(window).contains("neither a built-in"), qPrintable(lastMessage(window)));
        QVERIFY(character->toolTip().contains("neither a built-in"));
        typeInto(window, field<QComboBox>(window, "character")->lineEdit(), "woman");
        QCOMPARE(walker.character, std::string("woman"));

        typeInto(window, field<QSpinBox>(window, "layer"), "3");
        typeInto(window, field<QLineEdit>(window, "collidesWith"), "0, 3");
        QCOMPARE(walker.layer, 3u);
        QCOMPARE(walker.collidesWith, 0b1001u);
        typeInto(window, field<QLineEdit>(window, "collidesWith"), "0, 40");
        QCOMPARE(walker.collidesWith, 0b1001u);
        QVERIFY2(lastMessage(window).contains("\"40\""), qPrintable(lastMessage(window)));
        QCOMPARE(field<QLineEdit>(window, "collidesWith")->text(), QString("0, 3"));
        QCOMPARE(window.document().undoStack()->count(), 7);

        // Two types: their looks differ.
        selectInOutliner(window, {{ItemKind::AgentType, 0}, {ItemKind::AgentType, 1}});
        QCOMPARE(field<QLineEdit>(window, "looks")->text(), QString("(mixed)"));
        QCOMPARE(field<QLineEdit>(window, "collidesWith")->text(), QString("(mixed)"));
        for (int k = 0; k < 7; ++k)
            undo(window);
        QCOMPARE(sceneYaml(window), before);
    }

    void fliersShowTheirMinSpeedBankingAndAltitude()
    {
        QByteArray yaml = tablesScene();
        yaml.replace("  - {name: runner, max_speed: 3, max_force: 6}\n",
                     "  - {name: runner, max_speed: 3, max_force: 6}\n"
                     "  - {name: gull, kind: flier, max_speed: 8, max_force: 20}\n");
        yaml.replace("groups:\n", "groups:\n  - {name: flock, type: gull, count: 3, circle: {center: [10, -20], radius: 2}, "
                                  "altitude: [5, 10]}\n");
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "gulls.yaml", yaml));
        const QByteArray before = sceneYaml(window);
        const sim::Scene& scene = window.document().scene();
        QWidget* panel = window.findChild<QWidget*>("properties");
        selectInOutliner(window, {{ItemKind::AgentType, 0}});  // walker: no flier rows
        QVERIFY(!field<QDoubleSpinBox>(window, "banking")->isVisibleTo(panel));
        QVERIFY(!field<QDoubleSpinBox>(window, "minSpeed")->isVisibleTo(panel));

        selectInOutliner(window, {{ItemKind::AgentType, 2}});  // gull
        QVERIFY(field<QDoubleSpinBox>(window, "banking")->isVisibleTo(panel));
        typeInto(window, field<QDoubleSpinBox>(window, "minSpeed"), "9");  // above max speed 8
        QCOMPARE(scene.agentTypes[2].minSpeed, 0.0f);
        QVERIFY2(lastMessage(window).contains("cannot exceed"), qPrintable(lastMessage(window)));
        typeInto(window, field<QDoubleSpinBox>(window, "minSpeed"), "2");
        typeInto(window, field<QDoubleSpinBox>(window, "banking"), "0.2");
        QCOMPARE(scene.agentTypes[2].minSpeed, 2.0f);
        QCOMPARE(scene.agentTypes[2].banking, 0.2f);

        selectInOutliner(window, {{ItemKind::Group, 0}});  // the flock
        QCOMPARE(field<QDoubleSpinBox>(window, "altitudeMin")->value(), 5.0);
        typeInto(window, field<QDoubleSpinBox>(window, "altitudeMax"), "4");  // below the minimum
        QCOMPARE(scene.groups[0].altitudeM, glm::vec2(5, 10));
        QVERIFY2(lastMessage(window).contains("cannot be below"), qPrintable(lastMessage(window)));
        typeInto(window, field<QDoubleSpinBox>(window, "altitudeMax"), "12");
        QCOMPARE(scene.groups[0].altitudeM, glm::vec2(5, 12));
        QCOMPARE(window.document().undoStack()->count(), 3);
        for (int k = 0; k < 3; ++k)
            undo(window);
        QCOMPARE(sceneYaml(window), before);
    }

    // A walker type's reaction time range (RiMEA test 5): typed in, an inverted range refused,
    // written to the file; a flier type shows no such rows. Its age range (RiMEA test 7): ages
    // off Weidmann's curve, an inverted range and words refused, "20 to 80" taken, nothing
    // for none. Each row's edits one undo step.
    void walkersSetTheirReactionTimesAndAges()
    {
        QByteArray yaml = tablesScene();
        yaml.replace("  - {name: runner, max_speed: 3, max_force: 6}\n",
                     "  - {name: runner, max_speed: 3, max_force: 6}\n"
                     "  - {name: gull, kind: flier, max_speed: 8, max_force: 20}\n");
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "reactions.yaml", yaml));
        const QByteArray before = sceneYaml(window);
        const sim::Scene& scene = window.document().scene();
        QWidget* panel = window.findChild<QWidget*>("properties");
        selectInOutliner(window, {{ItemKind::AgentType, 2}});  // gull: no reaction rows
        QVERIFY(!field<QDoubleSpinBox>(window, "reactionMax")->isVisibleTo(panel));

        selectInOutliner(window, {{ItemKind::AgentType, 0}});  // walker
        QVERIFY(field<QDoubleSpinBox>(window, "reactionMax")->isVisibleTo(panel));
        QCOMPARE(field<QDoubleSpinBox>(window, "reactionMin")->value(), 0.0);
        typeInto(window, field<QDoubleSpinBox>(window, "reactionMin"), "5");  // above its maximum, 0
        QCOMPARE(scene.agentTypes[0].variation.reactionS, glm::vec2(0.0f));
        QVERIFY2(lastMessage(window).contains("cannot exceed"), qPrintable(lastMessage(window)));
        typeInto(window, field<QDoubleSpinBox>(window, "reactionMax"), "30");
        typeInto(window, field<QDoubleSpinBox>(window, "reactionMin"), "5");
        QCOMPARE(scene.agentTypes[0].variation.reactionS, glm::vec2(5.0f, 30.0f));
        QCOMPARE(window.document().undoStack()->count(), 2);
        QVERIFY2(sceneYaml(window).contains("reaction: [5, 30]"), sceneYaml(window).constData());

        auto* ages = field<QLineEdit>(window, "ages");
        QCOMPARE(ages->text(), QString());
        const struct {
            const char* typed;
            const char* message;
        } refused[] = {{"5 to 30", "within 10 to 80"}, {"30 to 90", "within 10 to 80"},
                       {"60 to 20", "above the second"}, {"old", "Type two ages"}, {"20 to 40 to 60", "Type two ages"}};
        for (const auto& r : refused) {
            typeInto(window, ages, r.typed);
            QCOMPARE(scene.agentTypes[0].variation.ageYears, glm::vec2(0.0f));
            QVERIFY2(lastMessage(window).contains(r.message), qPrintable(lastMessage(window)));
        }
        typeInto(window, ages, "20 to 80");
        QCOMPARE(scene.agentTypes[0].variation.ageYears, glm::vec2(20.0f, 80.0f));
        QCOMPARE(ages->text(), QString("20 to 80"));
        QVERIFY2(sceneYaml(window).contains("age: [20, 80]"), sceneYaml(window).constData());
        QVERIFY(sim::parseScene(sceneYaml(window).toStdString(), "ages.yaml", "").ok());
        QCOMPARE(window.document().undoStack()->count(), 3);
        // Cleared again in the same row: the edit merges with the last, which then undoes nothing.
        typeInto(window, ages, "");
        QCOMPARE(scene.agentTypes[0].variation.ageYears, glm::vec2(0.0f));
        QVERIFY(!sceneYaml(window).contains("age:"));
        QCOMPARE(window.document().undoStack()->count(), 2);
        for (int k = 0; k < 2; ++k)
            undo(window);
        QCOMPARE(sceneYaml(window), before);
    }

    // A walker type's time gap (RiMEA test 16): typed in, written to the file and read back,
    // one undo step; a flier type shows no such row.
    void walkersKeepATimeGap()
    {
        QByteArray yaml = tablesScene();
        yaml.replace("  - {name: runner, max_speed: 3, max_force: 6}\n",
                     "  - {name: runner, max_speed: 3, max_force: 6}\n"
                     "  - {name: gull, kind: flier, max_speed: 8, max_force: 20}\n");
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "gaps.yaml", yaml));
        const QByteArray before = sceneYaml(window);
        const sim::Scene& scene = window.document().scene();
        QWidget* panel = window.findChild<QWidget*>("properties");
        selectInOutliner(window, {{ItemKind::AgentType, 2}});  // gull: no time gap
        QVERIFY(!field<QDoubleSpinBox>(window, "timeGap")->isVisibleTo(panel));

        selectInOutliner(window, {{ItemKind::AgentType, 0}});  // walker
        auto* gap = field<QDoubleSpinBox>(window, "timeGap");
        QVERIFY(gap->isVisibleTo(panel));
        QCOMPARE(gap->value(), 0.0);
        typeInto(window, gap, "1.06");
        QCOMPARE(scene.agentTypes[0].timeGapS, 1.06f);
        QCOMPARE(window.document().undoStack()->index(), 1);
        QVERIFY2(sceneYaml(window).contains("time_gap: 1.06"), sceneYaml(window).constData());
        QCOMPARE(sim::parseScene(sceneYaml(window).toStdString(), "gaps.yaml", "").scene.agentTypes[0].timeGapS, 1.06f);
        undo(window);
        QCOMPARE(scene.agentTypes[0].timeGapS, 0.0f);
        QCOMPARE(sceneYaml(window), before);
    }

    // A group's exits (RiMEA test 11), typed as a list: one exit, a goal that is not an exit,
    // an unknown name and a name twice are refused; two exits take the place of the group's
    // path in one undo step, the goal, path and leader rows hide while it chooses, and an
    // empty list shows them again; undo gives back the path.
    void aGroupChoosesAmongExits()
    {
        QByteArray yaml = tablesScene();
        yaml.replace("goals:\n", "goals:\n  - {name: north_door, position: [0, -30], radius: 1, exit: true}\n"
                                 "  - {name: south_door, position: [0, 30], radius: 1, exit: true}\n");
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "exits.yaml", yaml));
        const QByteArray before = sceneYaml(window);
        const sim::Scene& scene = window.document().scene();
        QWidget* panel = window.findChild<QWidget*>("properties");
        selectInOutliner(window, {{ItemKind::Group, 0}});  // loopers, on path loop
        auto* exits = field<QLineEdit>(window, "exits");
        showInPanel(window, exits);
        QCOMPARE(exits->text(), QString());
        QVERIFY(field<QComboBox>(window, "path")->isVisibleTo(panel));
        const struct {
            const char* typed;
            const char* message;
        } refused[] = {{"north_door", "at least two"}, {"north_door, east", "not an exit"},
                       {"north_door, back_door", "no goal named"}, {"north_door, north_door", "listed twice"}};
        for (const auto& r : refused) {
            typeInto(window, exits, r.typed);
            QVERIFY(scene.groups[0].exits.empty());
            QVERIFY2(lastMessage(window).contains(r.message), qPrintable(lastMessage(window)));
        }
        QCOMPARE(window.document().undoStack()->count(), 0);

        typeInto(window, exits, "north_door, south_door");
        QCOMPARE(scene.groups[0].exits, (std::vector<std::string>{"north_door", "south_door"}));
        QCOMPARE(scene.groups[0].path, std::string());
        QCOMPARE(window.document().undoStack()->count(), 1);
        QVERIFY(!field<QComboBox>(window, "path")->isVisibleTo(panel));
        QVERIFY(!field<QComboBox>(window, "goal")->isVisibleTo(panel));
        QVERIFY(!field<QComboBox>(window, "leader")->isVisibleTo(panel));
        QVERIFY2(sceneYaml(window).contains("exits: [north_door, south_door]"), sceneYaml(window).constData());
        QVERIFY(sim::parseScene(sceneYaml(window).toStdString(), "exits.yaml", "").ok());

        // A second edit of the same row merges into the first: one undo step gives back the path.
        typeInto(window, exits, "");
        QVERIFY(scene.groups[0].exits.empty());
        QVERIFY(field<QComboBox>(window, "goal")->isVisibleTo(panel));
        QCOMPARE(window.document().undoStack()->count(), 1);
        undo(window);
        QCOMPARE(sceneYaml(window), before);
        QCOMPARE(scene.groups[0].path, std::string("loop"));
    }

    void aLightsStopLinesAreEditedInTheirTable()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "light.yaml", trafficScene()));
        const QByteArray before = sceneYaml(window);
        const sim::TrafficLight& light = window.document().scene().trafficLights[0];
        selectInOutliner(window, {{ItemKind::TrafficLight, 0}});
        auto* table = field<QTableWidget>(window, "stopLines");
        QVERIFY(table);
        QCOMPARE(table->rowCount(), 2);
        QCOMPARE(field<QComboBox>(window, "stopTarget1")->currentText(), QString("zebra"));

        typeInto(window, field<QDoubleSpinBox>(window, "stopAt0"), "20");
        QCOMPARE(light.stopLines[0].atM, 20.0f);
        pick(window, "stopTarget0", "side", Scroll::ToWidget);
        QCOMPARE(light.stopLines[0].lane, std::string("side"));
        pick(window, "stopTarget1", "ladder", Scroll::ToWidget);
        QCOMPARE(light.stopLines[1].crosswalk, std::string("ladder"));
        pick(window, "stopKind0", "Crosswalk", Scroll::ToWidget);  // the first crosswalk
        QCOMPARE(light.stopLines[0], (sim::StopLine{"", 0.0f, "zebra"}));
        QCOMPARE(window.document().undoStack()->count(), 4);

        press(window, "addStopLine");  // on the first lane at 0 m
        QCOMPARE(light.stopLines.size(), std::size_t(3));
        QCOMPARE(light.stopLines[2], (sim::StopLine{"main", 0.0f, ""}));
        QCOMPARE(table->rowCount(), 3);
        clickRow(window, table, 0);
        press(window, "removeStopLine");
        QCOMPARE(light.stopLines.size(), std::size_t(2));
        QCOMPARE(light.stopLines[0].crosswalk, std::string("ladder"));
        QCOMPARE(window.document().undoStack()->count(), 6);

        for (int k = 0; k < 6; ++k)
            undo(window);
        QCOMPARE(sceneYaml(window), before);
        QTRY_COMPARE(field<QDoubleSpinBox>(window, "stopAt0")->value(), 30.0);
    }
};

THRONG_REGISTER_TEST(TestTypeAndLightRowsUi)
#include "TestTypeAndLightRowsUi.moc"
