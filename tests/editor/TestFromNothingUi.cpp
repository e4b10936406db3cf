// From File > New to a saved crowd without touching YAML, driven like a user: agent types
// made, duplicated and deleted from the outliner, a spawn group drawn, agents painted, a
// wall and a goal drawn, the crowd played and the scene saved through the Save As dialog,
// and the file accepted by throng-cli check.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "TestRegistry.h"

#include "editor/simulation/SimulationController.h"
#include "editor/tools/GroupTool.h"
#include "editor/tools/ToolManager.h"
#include "simcore/io/SceneIO.h"

#include <glm/geometric.hpp>

#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QLineEdit>
#include <QMenu>
#include <QMessageBox>
#include <QProcess>
#include <QPushButton>
#include <QTest>
#include <QTimer>
#include <QToolButton>

#include <algorithm>
#include <functional>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

std::vector<std::string> typeNames(MainWindow& window)
{
    std::vector<std::string> names;
    for (const sim::AgentType& t : window.document().scene().agentTypes)
        names.push_back(t.name);
    return names;
}

}  // namespace

class TestFromNothingUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
    }

    void newSceneHasAPedestrianTypeAndTheBrushPaintsAtOnce()
    {
        MainWindow window;
        showNewWindow(window);
        QTest::keyClick(&window, Qt::Key_N, Qt::ControlModifier);
        QCOMPARE(typeNames(window), std::vector<std::string>{"pedestrian"});
        QCOMPARE(window.document().scene().agentTypes.front().kind, sim::AgentKind::Pedestrian);
        QVERIFY(!window.document().isModified());
        window.viewport().frameAll();
        QVERIFY(clickToolButton(window, "crowdBrush"));
        dragOnGround(window, {{-10, 0}, {10, 0}});
        const auto& agents = window.document().scene().agents;
        QVERIFY2(agents.size() >= 10, qPrintable(QString::number(agents.size())));
        QVERIFY(std::all_of(agents.begin(), agents.end(), [](const sim::Agent& a) { return a.type == "pedestrian"; }));
    }

    void typesAreMadeFromPresetsDuplicatedDeletedAndUndone()
    {
        MainWindow window;
        showNewWindow(window);
        // The button's face makes a pedestrian; its arrow offers the presets.
        auto* add = window.findChild<QToolButton*>("newTypeButton");
        QVERIFY(add);
        QTest::mouseClick(add, Qt::LeftButton);
        QCOMPARE(typeNames(window), (std::vector<std::string>{"pedestrian", "pedestrian_2"}));
        bool picked = false;
        whenShown([&] { return picked = clickPopupItem("Bird"); });
        QTest::mouseClick(add, Qt::LeftButton, Qt::NoModifier, QPoint(add->width() - 4, add->height() / 2));
        QTRY_VERIFY(picked);
        QCOMPARE(typeNames(window), (std::vector<std::string>{"pedestrian", "pedestrian_2", "bird"}));
        const sim::AgentType& bird = window.document().scene().agentTypes[2];
        QCOMPARE(bird.kind, sim::AgentKind::Flier);
        QCOMPARE(bird.character, std::string("bird"));
        QVERIFY(bird.minSpeed > 0.0f);
        // What was made is selected: Properties shows the bird's name.
        QCOMPARE(window.document().selection(), (Selection{{ItemKind::AgentType, 2}}));
        auto* name = field<QLineEdit>(window, "name");
        QVERIFY(name);
        QCOMPARE(name->text(), QString("bird"));
        // Duplicate the bird, then delete the copy from the outliner's bar; undo brings it back.
        QTest::mouseClick(window.findChild<QToolButton*>("duplicateTypeButton"), Qt::LeftButton);
        QCOMPARE(typeNames(window).back(), std::string("bird_copy"));
        QCOMPARE(window.document().scene().agentTypes.back().maxSpeed, bird.maxSpeed);
        QCOMPARE(window.document().selection(), (Selection{{ItemKind::AgentType, 3}}));
        QTest::mouseClick(window.findChild<QToolButton*>("deleteItemsButton"), Qt::LeftButton);
        QCOMPARE(typeNames(window), (std::vector<std::string>{"pedestrian", "pedestrian_2", "bird"}));
        undo(window);
        QCOMPARE(typeNames(window), (std::vector<std::string>{"pedestrian", "pedestrian_2", "bird", "bird_copy"}));
        // Every preset is offered, each with a different kind or speed.
        QStringList offered;
        for (QAction* a : add->defaultAction()->menu()->actions())
            offered << a->text();
        QCOMPARE(offered, (QStringList{"Pedestrian", "Runner", "Car", "Bird", "Rider"}));
    }

    void aSceneWithoutTypesOffersOneWhenTheBrushIsUsed()
    {
        MainWindow window;
        showNewWindow(window);
        window.viewport().frameAll();
        selectInOutliner(window, {{ItemKind::AgentType, 0}});
        QTest::mouseClick(window.findChild<QToolButton*>("deleteItemsButton"), Qt::LeftButton);
        QVERIFY(window.document().scene().agentTypes.empty());
        QVERIFY(clickToolButton(window, "crowdBrush"));
        // First the user declines: nothing is made and nothing is painted.
        bool answered = false;
        auto answer = [&](QMessageBox::StandardButton which) {
            return [&answered, which] {
                auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
                if (!box || box->objectName() != "createTypePrompt")
                    return false;
                QTest::mouseClick(box->button(which), Qt::LeftButton);
                return answered = true;
            };
        };
        whenShown(answer(QMessageBox::No));
        dragOnGround(window, {{-5, 0}, {5, 0}});
        QTRY_VERIFY(answered);
        QVERIFY(window.document().scene().agentTypes.empty());
        QVERIFY(window.document().scene().agents.empty());
        // Then accepts: a pedestrian type exists and the next stroke paints.
        answered = false;
        whenShown(answer(QMessageBox::Yes));
        clickOnGround(window, {0, 0});
        QTRY_VERIFY(answered);
        QCOMPARE(typeNames(window), std::vector<std::string>{"pedestrian"});
        dragOnGround(window, {{-8, 0}, {8, 0}});
        QVERIFY(!window.document().scene().agents.empty());
        // The same offer comes from the spawn group tool.
        window.activateWindow();  // the prompt had the focus
        QVERIFY(QTest::qWaitForWindowActive(&window));
        undo(window);
        undo(window);
        QVERIFY2(window.document().scene().agentTypes.empty(), qPrintable(QString("%1 steps, at %2: %3").arg(window.document().undoStack()->count()).arg(window.document().undoStack()->index()).arg(window.document().undoStack()->text(window.document().undoStack()->index()-1))));
        QVERIFY(clickToolButton(window, "group"));
        answered = false;
        whenShown(answer(QMessageBox::Yes));
        clickOnGround(window, {0, 0});
        QTRY_VERIFY(answered);
        QCOMPARE(typeNames(window), std::vector<std::string>{"pedestrian"});
    }

    void groupToolDrawsRectanglesAndCirclesByCountOrDensity()
    {
        MainWindow window;
        showNewWindow(window);
        window.viewport().frameAll();
        QTest::keyClick(&window.viewport(), Qt::Key_S);
        QVERIFY(window.viewport().tool() && window.viewport().tool()->objectKey() == "group");
        // By density: 0.5 per m² over an 8 m × 10 m rectangle is 40 agents.
        auto* density = window.findChild<QDoubleSpinBox*>("groupDensity");
        QVERIFY(density);
        typeInto(density, "0.5");
        dragOnGround(window, {{-10, -5}, {-2, 5}});
        const sim::Scene& scene = window.document().scene();
        QCOMPARE(scene.groups.size(), std::size_t(1));
        const sim::SpawnGroup& rect = scene.groups[0];
        QCOMPARE(rect.shape, sim::AreaShape::Rect);
        QCOMPARE(rect.type, std::string("pedestrian"));
        QVERIFY2(glm::length(rect.min - glm::vec2(-10, -5)) < 0.3f && glm::length(rect.max - glm::vec2(-2, 5)) < 0.3f,
                 qPrintable(QString("%1 %2 .. %3 %4").arg(rect.min.x).arg(rect.min.y).arg(rect.max.x).arg(rect.max.y)));
        const double area = double(rect.max.x - rect.min.x) * double(rect.max.y - rect.min.y);
        const std::size_t rectCount = rect.count;  // `rect` goes with the next group
        QCOMPARE(double(rectCount), std::round(area * 0.5));
        QTRY_COMPARE(window.viewport().agentCount(), rectCount);
        QCOMPARE(window.document().selection(), (Selection{{ItemKind::Group, 0}}));
        // By count, a circle: centre, then radius.
        auto* shape = window.findChild<QComboBox*>("groupShape");
        QVERIFY2(shape, qPrintable(window.tools().activeTool()->objectKey()));
        // Arrow keys, not letters: a letter is a tool's shortcut.
        shape->setFocus();
        QTest::keyClick(shape, Qt::Key_Down);
        QCOMPARE(shape->currentText(), QString("Circle"));
        auto* amount = window.findChild<QComboBox*>("groupAmount");
        amount->setFocus();
        QTest::keyClick(amount, Qt::Key_Up);
        QCOMPARE(amount->currentText(), QString("Count"));
        typeInto(window.findChild<QSpinBox*>("groupCount"), "25");
        dragOnGround(window, {{10, 0}, {14, 0}});
        QCOMPARE(scene.groups.size(), std::size_t(2));
        const sim::SpawnGroup& circle = scene.groups[1];
        QCOMPARE(circle.shape, sim::AreaShape::Circle);
        QCOMPARE(circle.count, 25u);
        QVERIFY(std::abs(circle.radiusM - 4.0f) < 0.3f);
        QVERIFY(glm::length(circle.center - glm::vec2(10, 0)) < 0.3f);
        QTRY_COMPARE(window.viewport().agentCount(), rectCount + 25);
        // Escape during a drag leaves nothing; one undo takes one group back.
        QTest::mousePress(&window.viewport(), Qt::LeftButton, Qt::NoModifier, pixelOf(window, {0, 10}));
        QTest::mouseMove(&window.viewport(), pixelOf(window, {4, 14}));
        QTest::keyClick(&window.viewport(), Qt::Key_Escape);
        QTest::mouseRelease(&window.viewport(), Qt::LeftButton, Qt::NoModifier, pixelOf(window, {4, 14}));
        QCOMPARE(scene.groups.size(), std::size_t(2));
        undo(window);
        QCOMPARE(scene.groups.size(), std::size_t(1));
    }

    // A new scene's first spawn group must not move the camera: the user aims the next click
    // at the ground as the view showed it. (The view used to frame the group once its
    // agents came, as it frames a scene just opened, and the goal clicked beside the group
    // landed inside it.)
    void theFirstGroupDrawnKeepsTheViewWhereTheUserWorks()
    {
        MainWindow window;
        showNewWindow(window);
        QTest::keyClick(&window, Qt::Key_N, Qt::ControlModifier);
        QTRY_VERIFY(!window.viewport().grabFramebuffer().isNull());  // painted: the new scene framed
        // Where the goal is to go, seen before any agent is there.
        const glm::vec2 goalSpot(30.0f, 20.0f);
        const QPoint goalPixel = pixelOf(window, goalSpot);
        const QPoint cornerA = pixelOf(window, {-30, -20}), cornerB = pixelOf(window, {-20, -10});
        QVERIFY(window.viewport().rect().contains(goalPixel) && window.viewport().rect().contains(cornerA));
        QVERIFY(clickToolButton(window, "group"));
        typeInto(window.findChild<QDoubleSpinBox*>("groupDensity"), "0.5");
        QTest::mousePress(&window.viewport(), Qt::LeftButton, Qt::NoModifier, cornerA);
        QTest::mouseMove(&window.viewport(), (cornerA + cornerB) / 2);
        QTest::mouseMove(&window.viewport(), cornerB);
        QTest::mouseRelease(&window.viewport(), Qt::LeftButton, Qt::NoModifier, cornerB);
        QCOMPARE(window.document().scene().groups.size(), std::size_t(1));
        const std::size_t members = window.document().scene().groups[0].count;
        QVERIFY(members > 10);
        // The members come with frame 0 of the edited scene, from the simulation's thread;
        // the view paints them.
        QTRY_COMPARE(window.viewport().agentCount(), members);
        QVERIFY(!window.viewport().grabFramebuffer().isNull());
        QCOMPARE(pixelOf(window, goalSpot), goalPixel);
        QVERIFY(clickToolButton(window, "goal"));
        QTest::mouseClick(&window.viewport(), Qt::LeftButton, Qt::NoModifier, goalPixel);
        QCOMPARE(window.document().scene().goals.size(), std::size_t(1));
        const glm::vec2 placed = window.document().scene().goals[0].position;
        QVERIFY2(glm::length(placed - goalSpot) < 0.5f, qPrintable(QString("%1 %2").arg(placed.x).arg(placed.y)));
    }

    // The whole first hour: New, a type, agents, a wall, a goal, Play, Save, check.
    void fromFileNewToACheckedSceneFile()
    {
        MainWindow window;
        showNewWindow(window);
        QTest::keyClick(&window, Qt::Key_N, Qt::ControlModifier);
        window.viewport().frameAll();
        bool picked = false;
        auto* add = window.findChild<QToolButton*>("newTypeButton");
        whenShown([&] { return picked = clickPopupItem("Runner"); });
        QTest::mouseClick(add, Qt::LeftButton, Qt::NoModifier, QPoint(add->width() - 4, add->height() / 2));
        QTRY_VERIFY(picked);
        // A spawn group of pedestrians on the west side.
        QVERIFY(clickToolButton(window, "group"));
        typeInto(window.findChild<QDoubleSpinBox*>("groupDensity"), "0.4");
        dragOnGround(window, {{-20, -6}, {-12, 6}});
        // A stroke of the crowd brush.
        QVERIFY(clickToolButton(window, "crowdBrush"));
        dragOnGround(window, {{-20, 10}, {-12, 10}});
        const std::size_t painted = window.document().scene().agents.size();
        QVERIFY(painted > 0);
        // A wall with a gap in the middle: two segments, each finished with Return.
        QVERIFY(clickToolButton(window, "wall"));
        for (const auto& line : {std::vector<glm::vec2>{{0, -20}, {0, -2}}, std::vector<glm::vec2>{{0, 2}, {0, 20}}}) {
            for (glm::vec2 p : line)
                clickOnGround(window, p);
            QTest::keyClick(&window.viewport(), Qt::Key_Return);
        }
        QCOMPARE(window.document().scene().walls.size(), std::size_t(2));
        // A goal east of the wall, and the group and the painted agents sent to it.
        QVERIFY(clickToolButton(window, "goal"));
        clickOnGround(window, {15, 0});
        QCOMPARE(window.document().scene().goals.size(), std::size_t(1));
        const QString goal = QString::fromStdString(window.document().scene().goals[0].name);
        selectInOutliner(window, {{ItemKind::Group, 0}});
        pick(window, "goal", goal, Scroll::ToWidget);
        QCOMPARE(window.document().scene().groups[0].goal, goal.toStdString());
        // Play: the group walks east toward the gap. (The group's members and the painted
        // agents show once the simulation's thread brings frame 0 of the edited scene.)
        QTRY_VERIFY(window.viewport().agentCount() > painted);
        QVERIFY(playToFrame(window, 120));
        const sim::FrameCache& cache = window.simulation().cache();
        auto meanX = [&](std::size_t frame) {
            double sum = 0.0;
            std::size_t n = 0;
            for (const sim::AgentFrame& a : cache.frame(frame))
                if (a.position.z > -7.0f && a.position.z < 7.0f && a.position.x < 0.0f) {
                    sum += a.position.x;
                    ++n;
                }
            return n > 0 ? sum / double(n) : 0.0;
        };
        QVERIFY2(meanX(120) > meanX(0) + 2.0, qPrintable(QString("%1 -> %2").arg(meanX(0)).arg(meanX(120))));
        // Save As through its dialog, then the command line checks the file.
        const QString path = m_dir.filePath("first-hour.yaml");
        bool saved = false;
        whenShown([&] {
            auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget());
            if (!dialog || dialog->objectName() != "saveSceneDialog")
                return false;
            auto* name = dialog->findChild<QLineEdit*>("fileNameEdit");
            if (!name)
                return false;
            name->setText(path);
            QTest::keyClick(name, Qt::Key_Return);
            return saved = true;
        });
        window.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&window));
        QTest::keyClick(&window, Qt::Key_S, Qt::ControlModifier | Qt::ShiftModifier);
        QTRY_VERIFY2(saved, qPrintable(QApplication::activeModalWidget() ? QApplication::activeModalWidget()->objectName() + " " + QApplication::activeModalWidget()->metaObject()->className() : QString("no modal")));
        QTRY_VERIFY(QFile::exists(path));
        QCOMPARE(window.document().filePath(), path);
        QVERIFY(!window.document().isModified());
        QProcess check;
        check.start(QStringLiteral(THRONG_CLI_PATH), {"check", path});
        QVERIFY(check.waitForFinished(60000));
        QVERIFY2(check.exitCode() == 0, check.readAllStandardOutput() + check.readAllStandardError());
        const sim::LoadResult loaded = sim::loadScene(path.toStdString());
        QVERIFY(loaded.ok());
        QCOMPARE(loaded.scene.agentTypes.size(), std::size_t(2));
        QCOMPARE(loaded.scene.groups.size(), std::size_t(1));
        QCOMPARE(loaded.scene.walls.size(), std::size_t(2));
        QCOMPARE(loaded.scene.agents.size(), painted);
    }
};

THRONG_REGISTER_TEST(TestFromNothingUi)
#include "TestFromNothingUi.moc"
