// The source tool driven like a user: its key picks it, a drag on the viewport draws a
// source line, the outliner lists it, a click on its line selects it, the properties panel
// takes a typed rate (a rate of 0 is refused), a goal, the arrivals and a cap, undo goes
// back to the scene's bytes and redo forward, and a saved file keeps it. Renaming what a
// source names follows into it, deleting it is refused, and the source moves and deletes.
// The viewport draws a source's line in its colour and outlines it when selected.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "TestRegistry.h"

#include "editor/panels/OutlinerPanel.h"
#include "editor/tools/SourceTool.h"
#include "editor/viewport/Viewport.h"
#include "editor/viewport/ViewportPalette.h"
#include "simcore/io/SceneIO.h"

#include <glm/geometric.hpp>

#include <QAbstractButton>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QImage>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QSpinBox>
#include <QTest>
#include <QTimer>
#include <QUndoStack>

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

// A street with two goals and a path, and no one in it yet.
const QByteArray kEmptyStreet = R"(throng: 1
settings: {fps: 24, duration: 30, seed: 6, bounds: {min: [-20, -12], max: [20, 12]}}
agent_types:
  - {name: walker, max_speed: 1.4}
goals:
  - {name: east, position: [14, 0], radius: 2}
  - {name: west, position: [-14, 0], radius: 2}
paths:
  - {name: kerb, points: [[-12, 8], [12, 8]]}
)";

QString describeEnds(const sim::Source& s)
{
    return QString("from (%1, %2) to (%3, %4)").arg(s.from.x).arg(s.from.y).arg(s.to.x).arg(s.to.y);
}

// Of the points of the line x = -10 from z = -2.5 to 2.5 (its middle, where the arrow
// starts, left out), how many the viewport shows in `colour`.
int sourceLinePixelsIn(MainWindow& window, glm::vec4 colour)
{
    const QImage shown = window.viewport().grabFramebuffer();
    int hits = 0;
    for (float z : {-2.5f, -1.5f, -1.0f, 1.0f, 1.5f, 2.5f})
        hits += sameColour(pixelAt(shown, window.viewport(), window.viewport().worldToPixel({-10.0f, 0.0f, z})),
                           colour, 40);
    return hits;
}

// Clicks `which` on the main window's offer of an agent type once it shows; `answered`
// turns true then. Gives up after about 5 s.
void answerTypeOfferForSource(QMessageBox::StandardButton which, bool& answered)
{
    auto* timer = new QTimer;
    timer->setInterval(20);
    auto tries = std::make_shared<int>(0);
    QObject::connect(timer, &QTimer::timeout, timer, [timer, which, &answered, tries] {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (box && box->objectName() == "createTypePrompt") {
            QTest::mouseClick(box->button(which), Qt::LeftButton);
            answered = true;
        }
        if (answered || ++*tries > 250)
            timer->deleteLater();
    });
    timer->start();
}

}  // namespace

class TestSourceUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void drawnEditedUndoneAndSaved()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "street.yaml", kEmptyStreet));
        const sim::Scene& scene = window.document().scene();
        const QByteArray original = sceneYaml(window);
        QUndoStack* stack = window.document().undoStack();
        const int stepsBefore = stack->count();

        // R picks the tool; a drag from (-10, -3) to (-10, 3) draws the source.
        window.viewport().setFocus();
        QTest::keyClick(&window.viewport(), Qt::Key_R);
        auto* tool = window.findChild<QAction*>("sourceAction");
        QVERIFY(tool);
        QTRY_VERIFY(tool->isChecked());
        dragOnGround(window, {{-10, -3}, {-10, 0}, {-10, 3}});
        QCOMPARE(scene.sources.size(), std::size_t(1));
        const sim::Source& drawn = scene.sources[0];
        QVERIFY2(glm::length(drawn.from - glm::vec2(-10, -3)) < 0.3f, qPrintable(describeEnds(drawn)));
        QVERIFY2(glm::length(drawn.to - glm::vec2(-10, 3)) < 0.3f, qPrintable(describeEnds(drawn)));
        QCOMPARE(drawn.name, std::string("source_1"));
        QCOMPARE(drawn.types.size(), std::size_t(1));
        QCOMPARE(drawn.types[0].type, std::string("walker"));
        QCOMPARE(drawn.rate, 1.0f);
        QVERIFY(drawn.arrivals == sim::Arrivals::Steady);
        QVERIFY(drawn.goal.empty() && drawn.path.empty());
        QCOMPARE(stack->count(), stepsBefore + 1);
        QVERIFY(stack->text(stack->count() - 1).startsWith("Add source"));
        QCOMPARE(window.outliner().kindRow(ItemKind::Source)->text(0), QString("Sources (1)"));
        QCOMPARE(window.outliner().kindRow(ItemKind::Source)->child(0)->text(0), QString("source_1"));

        // Q and a click on the line, away from its middle, select it.
        QTest::keyClick(&window.viewport(), Qt::Key_Q);
        QTRY_VERIFY(window.findChild<QAction*>("selectAction")->isChecked());
        clickOnGround(window, {-10, 2});
        QCOMPARE(window.document().selection(), (Selection{{ItemKind::Source, 0}}));

        // The panel: a typed rate, a refused rate of 0, the goal, Poisson arrivals, a cap.
        auto* rate = field<QDoubleSpinBox>(window, "rate");
        QVERIFY(rate);
        typeInto(window, rate, "2.5");
        QCOMPARE(scene.sources[0].rate, 2.5f);
        typeInto(window, rate, "0");
        QCOMPARE(scene.sources[0].rate, 2.5f);
        QVERIFY2(lastMessage(window).contains("rate"), qPrintable(lastMessage(window)));
        pick(window, "goal", "east", Scroll::ToWidget);
        QCOMPARE(scene.sources[0].goal, std::string("east"));
        pick(window, "arrivals", "Poisson", Scroll::ToWidget);
        QVERIFY(scene.sources[0].arrivals == sim::Arrivals::Poisson);
        typeInto(window, field<QSpinBox>(window, "cap"), "40");
        QCOMPARE(scene.sources[0].cap, std::uint32_t(40));
        // A path instead of the goal: one step, and the goal goes (a source has one or the other).
        pick(window, "path", "kerb", Scroll::ToWidget);
        QCOMPARE(scene.sources[0].path, std::string("kerb"));
        QVERIFY(scene.sources[0].goal.empty());
        QCOMPARE(stack->count(), stepsBefore + 6);
        const sim::Source edited = scene.sources[0];

        // Undo, from the viewport (a focused spin box keeps Ctrl+Z), back to the file's bytes.
        QVERIFY(clickToolButton(window, "select"));
        clickOnGround(window, {5, -9});
        QVERIFY(window.document().selection().empty());
        for (int k = 0; k < 6; ++k)
            undo(window);
        QCOMPARE(stack->count() - stack->index(), 6);
        QVERIFY(scene.sources.empty());
        QCOMPARE(sceneYaml(window), original);
        for (int k = 0; k < 6; ++k)
            QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE(scene.sources.size(), std::size_t(1));
        QVERIFY(scene.sources[0] == edited);

        // Saved with Ctrl+S, the file opens again with the source as it was.
        QTest::keyClick(&window.viewport(), Qt::Key_S, Qt::ControlModifier);
        QVERIFY(!window.document().isModified());
        MainWindow reopened;
        reopened.show();
        QVERIFY(reopened.openScene(window.document().filePath()));
        QCOMPARE(reopened.document().scene().sources.size(), std::size_t(1));
        QVERIFY(reopened.document().scene().sources[0] == edited);
    }

    void aClickDrawsATwoMetreLine()
    {
        MainWindow window;
        QVERIFY(showWithYaml(window, m_dir, "click.yaml", kEmptyStreet));
        const sim::Scene& scene = window.document().scene();
        window.viewport().setFocus();
        QTest::keyClick(&window.viewport(), Qt::Key_R);
        QTRY_VERIFY(window.findChild<QAction*>("sourceAction")->isChecked());
        clickOnGround(window, {4, -5});
        QCOMPARE(scene.sources.size(), std::size_t(1));
        const sim::Source& s = scene.sources[0];
        QVERIFY2(glm::length(0.5f * (s.from + s.to) - glm::vec2(4, -5)) < 0.3f, qPrintable(describeEnds(s)));
        QVERIFY2(std::abs(glm::length(s.to - s.from) - SourceTool::kClickLineM) < 1e-3f, qPrintable(describeEnds(s)));
        // A second one takes the next free name.
        clickOnGround(window, {4, 5});
        QCOMPARE(scene.sources.size(), std::size_t(2));
        QCOMPARE(scene.sources[1].name, std::string("source_2"));
    }

    // Without an agent type there is nothing to let in: the tool draws nothing and the
    // main window offers a type, as for the brushes; once there is one, a drag draws.
    void withoutAgentTypesTheToolOffersOne()
    {
        MainWindow window;
        const QByteArray yaml = "throng: 1\nsettings: {bounds: {min: [-20, -12], max: [20, 12]}}\n";
        QVERIFY(showWithYaml(window, m_dir, "typeless.yaml", yaml));
        const sim::Scene& scene = window.document().scene();
        QVERIFY(scene.agentTypes.empty());
        const QByteArray before = sceneYaml(window);
        QVERIFY(clickToolButton(window, "source"));
        bool answered = false;
        answerTypeOfferForSource(QMessageBox::No, answered);
        dragOnGround(window, {{-5, 0}, {5, 0}});
        QTRY_VERIFY(answered);
        QCOMPARE(sceneYaml(window), before);
        window.activateWindow();  // the prompt had the focus
        QVERIFY(QTest::qWaitForWindowActive(&window));
        answered = false;
        answerTypeOfferForSource(QMessageBox::Yes, answered);
        clickOnGround(window, {0, 0});
        QTRY_VERIFY(answered);
        QCOMPARE(scene.agentTypes.size(), std::size_t(1));
        QVERIFY(scene.sources.empty());
        window.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&window));
        dragOnGround(window, {{-5, 0}, {5, 0}});
        QCOMPARE(scene.sources.size(), std::size_t(1));
        QCOMPARE(scene.sources[0].types[0].type, scene.agentTypes[0].name);
    }

    // A source's exits, typed as a list: a goal that is not an exit is refused; two exits take
    // the place of its goal in one undo step, its goal and path rows hide while it chooses,
    // the saved file loads with the same source, and undo gives back the goal.
    void aSourceChoosesAmongExits()
    {
        MainWindow window;
        const QByteArray yaml = R"(throng: 1
settings: {fps: 24, duration: 20, seed: 2, bounds: {min: [-20, -12], max: [20, 12]}}
agent_types: [{name: walker}]
goals:
  - {name: east, position: [14, 0], radius: 2}
  - {name: north_door, position: [0, -10], radius: 1, exit: true}
  - {name: south_door, position: [0, 10], radius: 1, exit: true}
sources:
  - {name: from_west, type: walker, line: [[-10, -3], [-10, 3]], rate: 0.5, goal: east}
)";
        QVERIFY(showWithYaml(window, m_dir, "exits.yaml", yaml));
        const QByteArray before = sceneYaml(window);
        const sim::Scene& scene = window.document().scene();
        QWidget* panel = window.findChild<QWidget*>("properties");
        selectInOutliner(window, {{ItemKind::Source, 0}});
        auto* exits = field<QLineEdit>(window, "exits");
        QVERIFY(exits);
        showInPanel(window, exits);
        QVERIFY(field<QComboBox>(window, "goal")->isVisibleTo(panel));
        typeInto(window, exits, "north_door, east");
        QVERIFY(scene.sources[0].exits.empty());
        QVERIFY2(lastMessage(window).contains("not an exit"), qPrintable(lastMessage(window)));
        typeInto(window, exits, "north_door, south_door");
        QCOMPARE(scene.sources[0].exits, (std::vector<std::string>{"north_door", "south_door"}));
        QVERIFY(scene.sources[0].goal.empty());
        QCOMPARE(window.document().undoStack()->count(), 1);
        QVERIFY(!field<QComboBox>(window, "goal")->isVisibleTo(panel));
        QVERIFY(!field<QComboBox>(window, "path")->isVisibleTo(panel));
        const QByteArray saved = sceneYaml(window);
        QVERIFY2(saved.contains("exits: [north_door, south_door]"), saved.constData());
        const sim::LoadResult again = sim::parseScene(saved.toStdString(), "exits.yaml", "");
        QVERIFY(again.ok());
        QVERIFY(again.scene.sources == scene.sources);
        undo(window);
        QCOMPARE(sceneYaml(window), before);
        QCOMPARE(scene.sources[0].goal, std::string("east"));
    }

    void namesFollowDeletesAreRefusedAndTheSourceMovesAndGoes()
    {
        MainWindow window;
        const QByteArray yaml = R"(throng: 1
settings: {fps: 24, duration: 20, seed: 2, bounds: {min: [-20, -12], max: [20, 12]}}
agent_types: [{name: walker}, {name: tourist}]
goals:
  - {name: east, position: [14, 0], radius: 2}
paths:
  - {name: kerb, points: [[-12, 8], [12, 8]]}
sources:
  - {name: from_west, type: walker, line: [[-10, -3], [-10, 3]], rate: 0.5, goal: east}
  - name: platform
    types: {walker: 3, tourist: 1}
    rect: {min: [-6, 6], max: [-2, 9]}
    rate: 1
    path: kerb
)";
        QVERIFY(showWithYaml(window, m_dir, "refs.yaml", yaml));
        const sim::Scene& scene = window.document().scene();
        QCOMPARE(scene.sources.size(), std::size_t(2));

        // Drawn in its own colour, and in the selection's once selected.
        QTest::qWait(50);
        QVERIFY2(sourceLinePixelsIn(window, palette::kSource) >= 5, "the source's line is drawn");
        selectInOutliner(window, {{ItemKind::Source, 0}});
        QTest::qWait(50);
        QVERIFY2(sourceLinePixelsIn(window, palette::kSelection) >= 5, "the selected source is outlined");

        // The mix shows read only, without the single-type combo box.
        selectInOutliner(window, {{ItemKind::Source, 1}});
        auto* mix = field<QLabel>(window, "types");
        QVERIFY(mix);
        QTRY_VERIFY(mix->isVisible());
        QCOMPARE(mix->text(), QString("walker 3, tourist 1"));
        QVERIFY(!field<QComboBox>(window, "type")->isVisible());

        // The goal a source walks to, and the path the other follows, cannot go.
        selectInOutliner(window, {{ItemKind::Goal, 0}});
        const QByteArray before = sceneYaml(window);
        QTest::keyClick(&window.viewport(), Qt::Key_Delete);
        QCOMPARE(sceneYaml(window), before);
        QVERIFY2(lastMessage(window).contains("source from_west"), qPrintable(lastMessage(window)));
        selectInOutliner(window, {{ItemKind::Path, 0}});
        QTest::keyClick(&window.viewport(), Qt::Key_Delete);
        QCOMPARE(sceneYaml(window), before);
        QVERIFY2(lastMessage(window).contains("source platform"), qPrintable(lastMessage(window)));

        // Renaming the goal and a type renames them in the sources.
        selectInOutliner(window, {{ItemKind::Goal, 0}});
        typeInto(window, field<QLineEdit>(window, "name"), "exit_east");
        QCOMPARE(scene.sources[0].goal, std::string("exit_east"));
        selectInOutliner(window, {{ItemKind::AgentType, 1}});
        typeInto(window, field<QLineEdit>(window, "name"), "visitor");
        const std::vector<sim::SourceType>& mixed = scene.sources[1].types;
        QVERIFY(std::any_of(mixed.begin(), mixed.end(), [](const sim::SourceType& t) {
            return t.type == "visitor" && t.weight == 1.0f;
        }));
        QVERIFY(std::none_of(mixed.begin(), mixed.end(), [](const sim::SourceType& t) { return t.type == "tourist"; }));

        // Dragged with the select tool, both ends move; Delete removes it; undo brings it back.
        QVERIFY(clickToolButton(window, "select"));
        dragOnGround(window, {{-10, 1}, {-9, 1}, {-8, 1}});
        const sim::Source& moved = scene.sources[0];
        QVERIFY2(glm::length(moved.from - glm::vec2(-8, -3)) < 0.3f, qPrintable(describeEnds(moved)));
        QVERIFY2(glm::length(moved.to - glm::vec2(-8, 3)) < 0.3f, qPrintable(describeEnds(moved)));
        QCOMPARE(window.document().selection(), (Selection{{ItemKind::Source, 0}}));
        const QByteArray placed = sceneYaml(window);
        QTest::keyClick(&window.viewport(), Qt::Key_Delete);
        QCOMPARE(scene.sources.size(), std::size_t(1));
        QCOMPARE(scene.sources[0].name, std::string("platform"));
        undo(window);
        QCOMPARE(sceneYaml(window), placed);
    }
};

THRONG_REGISTER_TEST(TestSourceUi)
#include "TestSourceUi.moc"
