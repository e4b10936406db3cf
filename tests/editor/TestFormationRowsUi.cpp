// A group's keeping together edited in Properties as a user does it: the Formation combo
// sets a column (its spacing row appears), the spacing and the column's width are typed,
// a spacing closer than two bodies is refused; typing companions "2 to 3" clears the
// formation in the same step, one undo brings the column back, and the saved file loads;
// a group choosing among exits refuses a formation with a message, and choosing exits
// clears a formation.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "TestRegistry.h"

#include "simcore/io/SceneIO.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QSpinBox>
#include <QTest>
#include <QUndoStack>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

const QByteArray kMarchers = R"(throng: 1
settings: {fps: 24, duration: 20, seed: 3}
agent_types:
  - {name: marcher, radius: 0.25, max_speed: 1.3}
goals:
  - {name: stage, position: [30, 0], radius: 2}
  - {name: north_door, position: [0, -30], radius: 1, exit: true}
  - {name: south_door, position: [0, 30], radius: 1, exit: true}
groups:
  - {name: band, type: marcher, count: 12, rect: {min: [-4, -3], max: [4, 3]}, goal: stage}
  - {name: leavers, type: marcher, count: 6, rect: {min: [-4, 6], max: [4, 9]}, exits: [north_door, south_door]}
)";

}  // namespace

class TestFormationRowsUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void aGroupMarchesInFormationOrWalksWithCompanions()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "band.yaml", kMarchers));
        const QByteArray before = sceneYaml(window);
        const sim::Scene& scene = window.document().scene();
        QUndoStack* stack = window.document().undoStack();
        QWidget* panel = window.findChild<QWidget*>("properties");
        selectInOutliner(window, {{ItemKind::Group, 0}});
        auto* spacing = field<QDoubleSpinBox>(window, "formationSpacing");
        QVERIFY(spacing);
        QVERIFY(!spacing->isVisibleTo(panel));  // no formation yet

        pick(window, "formation", "Column", Scroll::ToWidget);
        QVERIFY(scene.groups[0].formation.shape == sim::FormationShape::Column);
        QCOMPARE(stack->count(), 1);
        QTRY_VERIFY(spacing->isVisibleTo(panel));
        showInPanel(window, spacing);
        typeInto(window, spacing, "1.4");
        QCOMPARE(scene.groups[0].formation.spacingM, 1.4f);
        typeInto(window, spacing, "0.3");
        QCOMPARE(scene.groups[0].formation.spacingM, 1.4f);
        QVERIFY2(lastMessage(window).contains("two of its walkers' bodies"), qPrintable(lastMessage(window)));
        auto* width = field<QSpinBox>(window, "formationWidth");
        showInPanel(window, width);
        typeInto(window, width, "4");
        QCOMPARE(scene.groups[0].formation.width, 4u);
        const int steps = stack->count();

        auto* companions = field<QLineEdit>(window, "companions");
        showInPanel(window, companions);
        QCOMPARE(companions->text(), QString());
        typeInto(window, companions, "3 to 2");
        QCOMPARE(scene.groups[0].companions, glm::uvec2(0u));
        QVERIFY2(lastMessage(window).contains("not below the first"), qPrintable(lastMessage(window)));
        typeInto(window, companions, "2 to 3");
        QCOMPARE(scene.groups[0].companions, glm::uvec2(2, 3));
        QVERIFY(scene.groups[0].formation.shape == sim::FormationShape::None);
        QCOMPARE(stack->count(), steps + 1);
        QVERIFY(sim::parseScene(sceneYaml(window).toStdString(), "band.yaml", "").ok());
        QVERIFY2(sceneYaml(window).contains("companions: [2, 3]"), sceneYaml(window).constData());
        undo(window);
        QVERIFY(scene.groups[0].formation.shape == sim::FormationShape::Column);
        QCOMPARE(scene.groups[0].companions, glm::uvec2(0u));
        while (stack->canUndo())
            undo(window);
        QCOMPARE(sceneYaml(window), before);

        // Walkers that choose among exits walk on their own.
        selectInOutliner(window, {{ItemKind::Group, 1}});
        auto* formation = field<QComboBox>(window, "formation");
        showInPanel(window, formation);
        formation->setFocus();
        QTest::keyClicks(formation, "Wedge");
        QVERIFY(scene.groups[1].formation.shape == sim::FormationShape::None);
        QCOMPARE(formation->currentText(), QString("None"));
        QVERIFY2(lastMessage(window).contains("chooses among exits"), qPrintable(lastMessage(window)));
        QCOMPARE(stack->index(), 0);
        // ... and choosing exits takes a formation away in the same step.
        selectInOutliner(window, {{ItemKind::Group, 0}});
        pick(window, "formation", "Line", Scroll::ToWidget);
        auto* exits = field<QLineEdit>(window, "exits");
        showInPanel(window, exits);
        typeInto(window, exits, "north_door, south_door");
        QVERIFY(scene.groups[0].formation.shape == sim::FormationShape::None);
        QCOMPARE(scene.groups[0].exits.size(), std::size_t(2));
        QVERIFY(sim::parseScene(sceneYaml(window).toStdString(), "band.yaml", "").ok());
    }
};

THRONG_REGISTER_TEST(TestFormationRowsUi)
#include "TestFormationRowsUi.moc"
