// The assign brush's brain and group, driven like a user: pick a brain and type a group
// name in the tool options, drag over part of a row of walkers, and check what the user
// would: those agents name the brain and the group, undo restores them and redo again,
// the outliner lists the group and selects its agents, and when played the painted
// agents obey their new brain (it asks for speed 0, so they stay) while the rest walk.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "TestRegistry.h"

#include "editor/panels/OutlinerPanel.h"
#include "editor/simulation/SimulationController.h"
#include "editor/viewport/Viewport.h"

#include <glm/geometric.hpp>

#include <QComboBox>
#include <QLineEdit>
#include <QTest>

#include <algorithm>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

// 20 walkers in a row along z = 0 from x = -10 to 9, all heading for a goal far east;
// their type's brain "go" walks at max speed, "stay" asks for speed 0.
QByteArray rowScene()
{
    QByteArray yaml = R"(throng: 1
settings: {fps: 24, duration: 10, seed: 4, bounds: {min: [-30, -30], max: [60, 30]}}
brains:
  - name: go
    nodes:
      - {id: 1, type: input, params: {sensor: attribute, name: max_speed}}
      - {id: 2, type: output, params: {channel: speed}}
    links: [{from: [1, 0], to: [2, 0]}]
  - name: stay
    nodes:
      - {id: 1, type: input.constant, params: {value: 0}}
      - {id: 2, type: output, params: {channel: speed}}
    links: [{from: [1, 0], to: [2, 0]}]
agent_types: [{name: walker, max_speed: 1.4, max_force: 3, brain: go, variation: {speed: [1, 1]}}]
goals: [{name: east, position: [50, 0], radius: 1}]
agents:
)";
    for (int k = 0; k < 20; ++k)
        yaml += QByteArray("  - {id: ") + QByteArray::number(k + 1) + ", type: walker, position: [" +
                QByteArray::number(k - 10) + ", 0, 0], goal: east}\n";
    return yaml;
}

// The stroke runs from x = -10 to -6 along the row; the brush radius is 3 m.
constexpr glm::vec2 kFrom(-10, 0), kTo(-6, 0);
bool underStroke(const sim::Agent& a) { return a.position.x <= -3.2f; }
bool clearOfStroke(const sim::Agent& a) { return a.position.x >= -2.8f; }

}  // namespace

class TestAssignBrainUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void assignBrushPaintsBrainAndGroupThatThePlaybackObeys()
    {
        MainWindow window;
        QVERIFY(showWithSceneFile(window, writeScene(m_dir, "row.yaml", rowScene())));
        const std::vector<sim::Agent> before = window.document().scene().agents;
        QCOMPARE(before.size(), std::size_t(20));

        QVERIFY(clickToolButton(window, "assignBrush"));
        auto* brain = window.findChild<QComboBox*>("assignBrain");
        auto* group = window.findChild<QComboBox*>("assignGroup");
        QVERIFY(brain && group);
        brain->setCurrentIndex(brain->findText("stay"));
        group->lineEdit()->selectAll();
        QTest::keyClicks(group->lineEdit(), "parked");
        dragOnGround(window, {kFrom, kTo});

        const std::vector<sim::Agent> after = window.document().scene().agents;
        std::size_t painted = 0;
        for (std::size_t i = 0; i < after.size(); ++i) {
            if (underStroke(after[i])) {
                QCOMPARE(after[i].brain, std::string("stay"));
                QCOMPARE(after[i].group, std::string("parked"));
                QCOMPARE(after[i].goal, before[i].goal);  // goal left as it was ("(keep)")
                ++painted;
            } else if (clearOfStroke(after[i])) {
                QVERIFY(after[i] == before[i]);
            }
        }
        QCOMPARE(painted, std::size_t(7));  // x = -10 ... -4
        QCOMPARE(window.document().undoStack()->count(), 1);

        // One undo step restores every agent; redo paints them again.
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QTRY_VERIFY(window.document().scene().agents == before);
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QTRY_VERIFY(window.document().scene().agents == after);

        // The outliner lists the group; clicking it selects exactly its agents.
        OutlinerPanel& outliner = window.outliner();
        const auto inGroup = std::size_t(std::count_if(after.begin(), after.end(),
                                                       [](const sim::Agent& a) { return a.group == "parked"; }));
        QVERIFY(inGroup >= painted);
        QTreeWidgetItem* row = outliner.agentGroupRow("parked");
        QVERIFY(row);
        QVERIFY2(row->text(0).contains(QString::number(inGroup)), qPrintable(row->text(0)));
        row->parent()->setExpanded(true);
        outliner.scrollToItem(row);
        QTest::mouseClick(outliner.viewport(), Qt::LeftButton, {}, outliner.visualItemRect(row).center());
        Selection selected = window.document().selection();
        QCOMPARE(selected.size(), inGroup);
        for (const SceneItem& item : selected) {
            QCOMPARE(item.kind, ItemKind::Agent);
            QCOMPARE(after[item.index].group, std::string("parked"));
        }

        // Played for 2 s: the painted agents run "stay" and stay; the others walk east.
        SimulationController& sim = window.simulation();
        QTest::qWait(50);  // the window hands the edited scene to the simulation on its next turn
        QTRY_VERIFY_WITH_TIMEOUT(sim.recordedFrames() > 0, 30000);
        sim.play();
        QTRY_VERIFY_WITH_TIMEOUT(sim.currentFrame() >= 48, 30000);
        sim.pause();
        const std::size_t f = sim.currentFrame();
        std::size_t stayed = 0, walked = 0;
        for (std::size_t i = 0; i < after.size(); ++i) {
            const float moved = glm::distance(sim.cache().at(0, i).position, sim.cache().at(f, i).position);
            if (underStroke(after[i])) {
                QVERIFY2(moved < 0.05f, qPrintable(QString("agent %1 moved %2 m").arg(i).arg(moved)));
                ++stayed;
            } else if (clearOfStroke(after[i])) {
                QVERIFY2(moved > 1.5f, qPrintable(QString("agent %1 moved %2 m").arg(i).arg(moved)));
                ++walked;
            }
        }
        QCOMPARE(stayed, painted);
        QVERIFY(walked >= 12);
    }
};

THRONG_REGISTER_TEST(TestAssignBrainUi)
#include "TestAssignBrainUi.moc"
