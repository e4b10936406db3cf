// The action point tool driven like a user: its key picks it, the tool options take the
// action picked from its list and a typed duration, a drag on the viewport places the point with the
// drag's radius and facing, the outliner and properties show it, a property edit and
// the placement are undoable, the played frames show walkers playing the action there,
// and a saved file keeps it.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "TestRegistry.h"

#include "editor/panels/OutlinerPanel.h"
#include "editor/simulation/SimulationController.h"
#include "editor/viewport/Viewport.h"
#include "simcore/io/SceneIO.h"

#include <glm/geometric.hpp>

#include <QAbstractItemView>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QTest>

#include <cmath>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

// Five walkers east along z = 0 from x = -12 to a goal at x = 14, at 24 fps for 30 s.
const QByteArray kStreet = R"(throng: 1
settings: {fps: 24, duration: 30, seed: 6, bounds: {min: [-20, -12], max: [20, 12]}}
agent_types:
  - {name: walker, max_speed: 1.4, variation: {speed: [1, 1]}}
goals:
  - {name: east, position: [14, 0], radius: 2}
agents:
  - {type: walker, position: [-12, 0], heading: 0, goal: east}
  - {type: walker, position: [-14, 0.4], heading: 0, goal: east}
  - {type: walker, position: [-16, -0.4], heading: 0, goal: east}
  - {type: walker, position: [-18, 0.2], heading: 0, goal: east}
  - {type: walker, position: [-10, 0.3], heading: 0, goal: east}
)";

}  // namespace

class TestActionPointUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void placedWithADragPlayedByWalkersAndUndone()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "street.yaml", kStreet));
        const sim::Scene& scene = window.document().scene();
        QVERIFY(scene.actionPoints.empty());

        // I picks the tool; its options take the action and duration from the keyboard.
        window.viewport().setFocus();
        QTest::keyClick(&window.viewport(), Qt::Key_I);
        auto* tool = window.findChild<QAction*>("actionPointAction");
        QVERIFY(tool);
        QTRY_VERIFY(tool->isChecked());
        auto* action = window.findChild<QComboBox*>("actionPointClip");
        auto* duration = window.findChild<QDoubleSpinBox*>("actionPointDuration");
        QVERIFY(action && duration);
        QTRY_VERIFY(action->isVisible());
        // Opened with a click, "sit" picked in the list with the arrow keys and Return.
        QTest::mouseClick(action, Qt::LeftButton);
        QAbstractItemView* list = action->view();
        QTRY_VERIFY(list->isVisible());
        const int from = action->currentIndex(), to = action->findText("sit");
        QVERIFY(to > from);
        for (int k = from; k < to; ++k)
            QTest::keyClick(list, Qt::Key_Down);
        QTest::keyClick(list, Qt::Key_Return);
        QTRY_VERIFY(!list->isVisible());
        QCOMPARE(action->currentText(), QString("sit"));
        // Or typed on it: the letters pick an item and do not switch tools (W is the wall tool's).
        action->setFocus();
        QTest::keyClicks(action, "wa");
        QCOMPARE(action->currentText(), QString("wait"));
        QVERIFY(tool->isChecked());
        QTest::qWait(QApplication::keyboardInputInterval() + 100);  // a new search, as a pause starts one
        QTest::keyClicks(action, "sit");
        QCOMPARE(action->currentText(), QString("sit"));
        QVERIFY(tool->isChecked());
        duration->setFocus();
        duration->selectAll();
        QTest::keyClicks(duration, "2.5");
        QTest::keyClick(duration, Qt::Key_Return);

        // Pressed at the origin, dragged 2 m toward -z: radius 2, facing 90 degrees.
        dragOnGround(window, {{0, 0}, {0, -1}, {0, -2}});
        QCOMPARE(scene.actionPoints.size(), std::size_t(1));
        const sim::ActionPoint& p = scene.actionPoints[0];
        QVERIFY2(glm::length(p.position) < 0.3f, qPrintable(QString("%1 %2").arg(p.position.x).arg(p.position.y)));
        QVERIFY2(std::fabs(p.radiusM - 2.0f) < 0.3f, qPrintable(QString::number(p.radiusM)));
        QVERIFY(p.faces);
        QVERIFY2(std::fabs(p.facingDeg - 90.0f) <= 5.0f, qPrintable(QString::number(p.facingDeg)));
        QCOMPARE(QString::fromStdString(p.action), QString("sit"));
        QCOMPARE(p.durationS, 2.5f);
        QCOMPARE(window.outliner().kindRow(ItemKind::ActionPoint)->text(0), QString("Action Points (1)"));
        QVERIFY(window.document().undoStack()->text(window.document().undoStack()->count() - 1)
                    .startsWith("Add action point"));

        // Selected in the outliner, its properties show and take a typed facing.
        selectInOutliner(window, {{ItemKind::ActionPoint, 0}});
        QCOMPARE(field<QComboBox>(window, "action")->currentText(), QString("sit"));
        auto* facing = field<QDoubleSpinBox>(window, "facing");
        QVERIFY(facing && facing->isVisible());
        facing->setFocus();
        facing->selectAll();
        QTest::keyClicks(facing, "180");
        QTest::keyClick(facing, Qt::Key_Return);
        QCOMPARE(scene.actionPoints[0].facingDeg, 180.0f);
        const int steps = window.document().undoStack()->count();

        // Played: every walker comes through the disk and sits there 2.5 s, facing west.
        QVERIFY(playUntilRecorded(window, 24 * 24));
        const sim::FrameCache& cache = window.simulation().cache();
        for (std::size_t i = 0; i < scene.agents.size(); ++i) {
            std::size_t first = 0, frames = 0;
            for (std::size_t f = 0; f < cache.frameCount(); ++f)
                if (cache.frame(f)[i].clip == sim::Clip::Sit) {
                    first = frames == 0 ? f : first;
                    ++frames;
                }
            QVERIFY2(frames == 60 || frames == 61, qPrintable(QString("walker %1 sat %2 frames").arg(i).arg(frames)));
            const sim::AgentFrame& end = cache.frame(first + frames - 1)[i];
            QVERIFY2(std::fabs(std::fabs(end.headingRad) - 3.14159f) < 0.02f,
                     qPrintable(QString::number(end.headingRad)));
            QVERIFY(glm::length(glm::vec2(end.position.x, end.position.z)) < 2.0f + 0.1f);
        }

        // Undo takes the facing back, then the point; redo brings it back.
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(window.document().undoStack()->count(), steps);
        QCOMPARE(scene.actionPoints[0].facingDeg, std::round(p.facingDeg));
        QVERIFY(scene.actionPoints[0].facingDeg != 180.0f);
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QVERIFY(scene.actionPoints.empty());
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE(scene.actionPoints.size(), std::size_t(1));

        // Saved, it loads back the same.
        const sim::LoadResult again = sim::parseScene(sceneYaml(window).toStdString(), "saved.yaml", "");
        QVERIFY(again.ok());
        QVERIFY(again.scene.actionPoints == scene.actionPoints);
    }

    void deletingATypeAPointNamesIsRefusedAndRenamingFollows()
    {
        MainWindow window;
        const QByteArray yaml = R"(throng: 1
agent_types: [{name: walker}]
action_points:
  - {name: bench, position: [0, 5], action: sit, types: [walker]}
)";
        QVERIFY(showWithYaml(window, m_dir, "typed.yaml", yaml));
        const sim::Scene& scene = window.document().scene();
        QVERIFY(scene.agents.empty());
        QCOMPARE(field<QLabel>(window, "types"), nullptr);  // nothing selected yet
        selectInOutliner(window, {{ItemKind::ActionPoint, 0}});
        QCOMPARE(field<QLabel>(window, "types")->text(), QString("walker"));
        // The point names the type: deleting the type is refused and says why.
        selectInOutliner(window, {{ItemKind::AgentType, 0}});
        const QByteArray before = sceneYaml(window);
        QTest::keyClick(&window.viewport(), Qt::Key_Delete);
        QCOMPARE(sceneYaml(window), before);
        QVERIFY2(lastMessage(window).contains("action point bench"), qPrintable(lastMessage(window)));
        auto* name = field<QLineEdit>(window, "name");
        QVERIFY(name);
        name->setFocus();
        name->selectAll();
        QTest::keyClicks(name, "stroller");
        QTest::keyClick(name, Qt::Key_Return);
        QCOMPARE(scene.agentTypes[0].name, std::string("stroller"));
        QCOMPARE(scene.actionPoints[0].types, std::vector<std::string>{"stroller"});
        selectInOutliner(window, {{ItemKind::ActionPoint, 0}});
        QCOMPARE(field<QLabel>(window, "types")->text(), QString("stroller"));
    }
};

THRONG_REGISTER_TEST(TestActionPointUi)
#include "TestActionPointUi.moc"
