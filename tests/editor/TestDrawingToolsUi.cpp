// The lane, flow-stroke, hero, goal and traffic-light tools driven like a user: pick the
// tool on the tool bar, click or drag on the viewport, and check what was drawn (points,
// direction, timing, radius, stop lines), the outliner, and that undo takes it back. And
// every tool that adds to the set selects what it drew, for Properties.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "TestRegistry.h"

#include "editor/SceneItem.h"
#include "editor/panels/OutlinerPanel.h"
#include "editor/viewport/Viewport.h"

#include <glm/geometric.hpp>

#include <QDoubleSpinBox>
#include <QFile>
#include <QFileDialog>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QTest>

#include <algorithm>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

QString describe(glm::vec2 p)
{
    return QString("(%1, %2)").arg(p.x).arg(p.y);
}

void writeText(const QString& path, const QByteArray& text)
{
    QFile file(path);
    QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
    file.write(text);
}

// Picks `path` in the hero tool's import dialog as a user would.
bool importThroughDialog(MainWindow& window, const QString& path)
{
    auto* button = window.findChild<QPushButton*>("heroImportButton");
    if (!button)
        return false;
    QTest::mouseClick(button, Qt::LeftButton);
    QFileDialog* dialog = nullptr;
    for (int i = 0; i < 50 && !dialog; ++i) {
        for (QFileDialog* d : window.findChildren<QFileDialog*>("heroImportDialog"))
            if (d->isVisible())
                dialog = d;
        if (!dialog)
            QTest::qWait(20);
    }
    if (!dialog)
        return false;
    dialog->selectFile(path);
    static_cast<QDialog*>(dialog)->accept();  // the Open button
    return true;
}

bool hasStopLine(const sim::TrafficLight& light, const std::string& crosswalk)
{
    return std::any_of(light.stopLines.begin(), light.stopLines.end(),
                       [&](const sim::StopLine& s) { return s.crosswalk == crosswalk; });
}

}  // namespace

class TestDrawingToolsUi : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

private slots:
    void laneDrawnWithClicksKeepsItsDirectionAndWidth()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        QVERIFY(clickToolButton(window, "lane"));
        window.findChild<QDoubleSpinBox*>("laneWidth")->setValue(5.0);
        const std::vector<glm::vec2> points{{-40, -30}, {-20, -30}, {-20, -20}};
        for (glm::vec2 p : points)
            clickOnGround(window, p);
        QTest::keyClick(&window.viewport(), Qt::Key_Return);
        const auto& lanes = window.document().scene().lanes;
        QCOMPARE(lanes.size(), std::size_t(5));
        QCOMPARE(lanes.back().points.size(), points.size());
        for (std::size_t i = 0; i < points.size(); ++i)  // in the order clicked: the direction of travel
            QVERIFY2(glm::length(lanes.back().points[i] - points[i]) < 0.3f, qPrintable(describe(lanes.back().points[i])));
        QCOMPARE(lanes.back().widthM, 5.0f);
        QCOMPARE(window.outliner().kindRow(ItemKind::Lane)->text(0), QString("Lanes (5)"));
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(lanes.size(), std::size_t(4));
        QCOMPARE(window.outliner().kindRow(ItemKind::Lane)->text(0), QString("Lanes (4)"));
    }

    void flowStrokeFollowsTheDrag()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        QVERIFY(window.document().scene().flowStrokes.empty());
        QVERIFY(clickToolButton(window, "flowStroke"));
        dragOnGround(window, {{-40, -30}, {-20, -30}, {-20, -20}});
        const auto& strokes = window.document().scene().flowStrokes;
        QCOMPARE(strokes.size(), std::size_t(1));
        const std::vector<glm::vec2>& p = strokes[0].points;
        QVERIFY2(p.size() >= 15 && p.size() <= 40, qPrintable(QString::number(p.size())));
        QVERIFY2(glm::length(p.front() - glm::vec2(-40, -30)) < 0.3f, qPrintable(describe(p.front())));
        QVERIFY2(glm::length(p.back() - glm::vec2(-20, -20)) < 0.3f, qPrintable(describe(p.back())));
        QVERIFY(p[1].x > p[0].x);  // drawn eastward first: that is the way the crowd is sent
        for (glm::vec2 q : p)      // on the dragged corner, nowhere else
            QVERIFY2((std::abs(q.y + 30) < 0.3f && q.x <= -19.7f) || (std::abs(q.x + 20) < 0.3f && q.y >= -30.3f),
                     qPrintable(describe(q)));
        QCOMPARE(strokes[0].widthM, 4.0f);
        QCOMPARE(window.document().undoStack()->count(), 1);
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QVERIFY(strokes.empty());
    }

    void heroWayIsTimedByItsSpeed()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        QVERIFY(clickToolButton(window, "hero"));
        window.findChild<QDoubleSpinBox*>("heroSpeed")->setValue(2.0);
        clickOnGround(window, {-40, -30});
        clickOnGround(window, {-20, -30});
        clickOnGround(window, {-20, -20});
        QTest::keyClick(&window.viewport(), Qt::Key_Return);
        const auto& heroes = window.document().scene().heroes;
        QCOMPARE(heroes.size(), std::size_t(2));
        const sim::Hero& hero = heroes.back();
        QCOMPARE(hero.type, std::string("hero"));
        QVERIFY(hero.id != heroes.front().id && hero.id > 0);
        QCOMPARE(hero.keyframes.size(), std::size_t(3));
        // 20 m then 10 m at 2 m/s: keyed at 0, 10 and 15 s.
        QCOMPARE(hero.keyframes[0].timeS, 0.0f);
        QVERIFY2(std::abs(hero.keyframes[1].timeS - 10.0f) < 0.2f, qPrintable(QString::number(hero.keyframes[1].timeS)));
        QVERIFY2(std::abs(hero.keyframes[2].timeS - 15.0f) < 0.2f, qPrintable(QString::number(hero.keyframes[2].timeS)));
        QVERIFY(glm::length(glm::vec2(hero.keyframes[2].position.x, hero.keyframes[2].position.z) - glm::vec2(-20, -20)) < 0.3f);
        QCOMPARE(window.outliner().kindRow(ItemKind::Hero)->text(0), QString("Heroes (2)"));
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(heroes.size(), std::size_t(1));
    }

    void heroImportedFromAKeyframeFile()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        QVERIFY(clickToolButton(window, "hero"));
        const QString good = m_dir.filePath("scenes/run.xyz");  // beside the scene's copy
        writeText(good, "# x y z per frame\n-30 0 -30\n-29.5 0 -30\n-29 0 -30.25\n");
        QVERIFY(importThroughDialog(window, good));
        const auto& heroes = window.document().scene().heroes;
        QTRY_COMPARE(heroes.size(), std::size_t(2));
        const sim::Hero& hero = heroes.back();
        QCOMPARE(hero.keyframes.size(), std::size_t(3));
        const float fps = window.document().scene().settings.fps;
        QCOMPARE(hero.keyframes[2].position, glm::vec3(-29, 0, -30.25f));
        QVERIFY(std::abs(hero.keyframes[2].timeS - 2.0f / fps) < 1e-5f);
        QCOMPARE(hero.keyframesFile, std::string("run.xyz"));  // beside the scene, named relative to it

        // A bad line is reported with its file, line and column; nothing is added.
        const QString bad = m_dir.filePath("bad.xyz");
        writeText(bad, "1 0 2\n3 oops 4\n");
        QVERIFY(importThroughDialog(window, bad));
        QMessageBox* box = nullptr;
        QTRY_VERIFY((box = window.findChild<QMessageBox*>("heroImportError")) != nullptr);
        QVERIFY2(box->text().contains("bad.xyz:2:3"), qPrintable(box->text()));
        box->close();
        QCOMPARE(heroes.size(), std::size_t(2));
    }

    void goalPlacedWithADragTakesItsRadius()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        const std::size_t before = window.document().scene().goals.size();
        QVERIFY(clickToolButton(window, "goal"));
        dragOnGround(window, {{-30, -30}, {-27, -30}});
        clickOnGround(window, {-20, -35});
        const auto& goals = window.document().scene().goals;
        QCOMPARE(goals.size(), before + 2);
        const sim::Goal& dragged = goals[before];
        const sim::Goal& clicked = goals[before + 1];
        QVERIFY(glm::length(dragged.position - glm::vec2(-30, -30)) < 0.3f);
        QVERIFY2(std::abs(dragged.radiusM - 3.0f) < 0.3f, qPrintable(QString::number(dragged.radiusM)));
        QCOMPARE(clicked.radiusM, 1.5f);  // a click: the default radius
        QVERIFY(dragged.name != clicked.name);
        QCOMPARE(window.outliner().kindRow(ItemKind::Goal)->text(0), QString("Goals (%1)").arg(before + 2));
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(goals.size(), before + 1);
    }

    void whatAToolDrawsIsSelectedForItsProperties()
    {
        // Each tool that adds to the set selects what it drew, so Properties shows it at
        // once: a source just drawn is given its goal there, with no change of tool.
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        const auto* title = window.findChild<QLabel*>("propertiesTitle");
        QVERIFY(title);
        const QString nothing = title->text();
        QVERIFY2(nothing.startsWith("Nothing selected"), qPrintable(nothing));
        const sim::Scene& scene = window.document().scene();
        struct Drawing {
            QString tool;
            ItemKind kind;
            std::vector<glm::vec2> points;
            bool clicked;  // clicked point by point (and Return after two or more); else dragged
        };
        const std::vector<Drawing> drawings{
            {"wall", ItemKind::Wall, {{-44, -44}, {-36, -44}}, true},
            {"path", ItemKind::Path, {{-44, -40}, {-36, -40}}, true},
            {"lane", ItemKind::Lane, {{-44, -36}, {-36, -36}}, true},
            {"hero", ItemKind::Hero, {{-44, -32}, {-36, -32}}, true},
            {"obstacle", ItemKind::Obstacle, {{-44, -26}, {-43, -26}}, false},
            {"goal", ItemKind::Goal, {{-38, -26}, {-36, -26}}, false},
            {"actionPoint", ItemKind::ActionPoint, {{-32, -26}, {-31, -26}}, false},
            {"source", ItemKind::Source, {{-44, -20}, {-40, -20}}, false},
            {"flowStroke", ItemKind::FlowStroke, {{-44, -16}, {-36, -16}}, false},
            {"measure", ItemKind::Measurement, {{-44, -12}, {-38, -12}}, false},
            {"trafficLight", ItemKind::TrafficLight, {{-30, -40}}, true},
        };
        for (const Drawing& d : drawings) {
            QVERIFY2(clickToolButton(window, d.tool), qPrintable(d.tool));
            const std::size_t before = itemCount(scene, d.kind);
            if (d.clicked) {
                for (glm::vec2 p : d.points)
                    clickOnGround(window, p);
                if (d.points.size() > 1)
                    QTest::keyClick(&window.viewport(), Qt::Key_Return);
            } else {
                dragOnGround(window, d.points);
            }
            QVERIFY2(itemCount(scene, d.kind) == before + 1, qPrintable(d.tool + " drew nothing"));
            const SceneItem made{d.kind, before};
            QVERIFY2(window.document().selection() == Selection{made},
                     qPrintable(d.tool + ": " + QString::number(window.document().selection().size()) + " selected"));
            QCOMPARE(title->text(), itemLabel(scene, made));
            QVERIFY(!title->text().isEmpty());
            if (d.kind == ItemKind::Source) {
                // Its agents need somewhere to go: the goal drawn a moment ago.
                const QString goal = QString::fromStdString(scene.goals.back().name);
                pick(window, "goal", goal, Scroll::ToWidget);
                QCOMPARE(QString::fromStdString(scene.sources.back().goal), goal);
            }
        }
        // The light is selected, so a Ctrl+click on a crosswalk attaches it at once.
        QVERIFY(window.document().selection() == (Selection{{ItemKind::TrafficLight, scene.trafficLights.size() - 1}}));
        // Undo takes the last drawing back, and its selection with it.
        const std::size_t lights = scene.trafficLights.size();
        QTest::keyClick(&window.viewport(), Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(scene.trafficLights.size(), lights - 1);
        QVERIFY(window.document().selection().empty());
        QCOMPARE(title->text(), nothing);
    }

    void stopLinesMoveBetweenSignalsAndPhasesAreEdited()
    {
        MainWindow window;
        QVERIFY(showWithScene(window, m_dir, "crossroads.yaml"));
        QVERIFY(clickToolButton(window, "trafficLight"));
        const auto& lights = window.document().scene().trafficLights;
        clickOnGround(window, {14, -14});  // every crossing is taken: the new signal controls none
        QCOMPARE(lights.size(), std::size_t(3));
        QVERIFY(lights[2].stopLines.empty());
        QVERIFY(hasStopLine(lights[0], "cw_east"));

        clickOnGround(window, {7, 7});  // north_south's head: selects it, places nothing
        QCOMPARE(lights.size(), std::size_t(3));
        QVERIFY(window.document().selection() == (Selection{{ItemKind::TrafficLight, 0}}));
        QTest::mouseClick(&window.viewport(), Qt::LeftButton, Qt::ControlModifier, pixelOf(window, {10.5f, 0.0f}));
        QVERIFY(!hasStopLine(lights[0], "cw_east"));
        QCOMPARE(lights[0].stopLines.size(), std::size_t(3));

        clickOnGround(window, {14, -14});  // the new signal
        QVERIFY(window.document().selection() == (Selection{{ItemKind::TrafficLight, 2}}));
        QTest::mouseClick(&window.viewport(), Qt::LeftButton, Qt::ControlModifier, pixelOf(window, {10.5f, 2.0f}));
        QVERIFY(hasStopLine(lights[2], "cw_east"));
        // A lane: attached at the distance along it where it was clicked (eastbound starts at x = -50).
        QTest::mouseClick(&window.viewport(), Qt::LeftButton, Qt::ControlModifier, pixelOf(window, {-30.0f, 3.0f}));
        QVERIFY(std::none_of(lights[2].stopLines.begin(), lights[2].stopLines.end(),
                             [](const sim::StopLine& s) { return s.lane == "eastbound"; }));  // east_west has it

        // Phases in the properties panel, one undo step.
        auto* green = window.findChild<QWidget*>("properties")->findChild<QDoubleSpinBox*>("green");
        QVERIFY(green);
        green->selectAll();
        QTest::keyClicks(green, "31");
        QTest::keyClick(green, Qt::Key_Return);
        QCOMPARE(lights[2].greenS, 31.0f);

        QUndoStack* stack = window.document().undoStack();
        QCOMPARE(stack->count(), 4);  // place, detach, attach, green
        stack->undo();
        QCOMPARE(lights[2].greenS, 20.0f);
        stack->undo();
        QVERIFY(!hasStopLine(lights[2], "cw_east"));
        stack->undo();
        QVERIFY(hasStopLine(lights[0], "cw_east"));
        stack->redo();
        QVERIFY(!hasStopLine(lights[0], "cw_east"));
    }
};

THRONG_REGISTER_TEST(TestDrawingToolsUi)
#include "TestDrawingToolsUi.moc"
