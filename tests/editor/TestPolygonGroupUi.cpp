// A polygon spawn group drawn with the Group tool as a user does it: S, Polygon picked in
// the options bar with the keyboard, five corners of a concave outline clicked, Enter.
// The document then holds one polygon group with those corners and its count, the view
// shows its members inside the outline, Ctrl+Z takes it away, a crossing outline is
// refused with a reason, and the saved file reads back as a polygon.
#include "EditorTestSupport.h"
#include "EditorUiDriver.h"
#include "TestRegistry.h"

#include "editor/tools/GroupTool.h"
#include "editor/tools/ToolManager.h"
#include "simcore/io/SceneIO.h"
#include "simcore/scene/GroundPolygon.h"

#include <glm/geometric.hpp>

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QSpinBox>
#include <QTableWidget>
#include <QTest>

#include <vector>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {

// A 16 m x 12 m block with a V-shaped notch cut from its far edge down to (0, 0): five
// corners, concave at the notch's tip; 192 m² less the notch's 48 m² = 144 m².
const std::vector<glm::vec2> kCorners{{-8, -6}, {8, -6}, {8, 6}, {0, 0}, {-8, 6}};
constexpr float kPickM = 0.3f;  // a click lands within this of the ground point aimed at

GroupTool* groupTool(MainWindow& window)
{
    return qobject_cast<GroupTool*>(window.tools().activeTool());
}

void chooseShape(MainWindow& window, const QString& text)
{
    auto* shape = window.findChild<QComboBox*>("groupShape");
    QVERIFY(shape);
    // Arrow keys, not letters: a letter is a tool's shortcut.
    shape->setFocus();
    while (shape->currentText() != text && shape->currentIndex() + 1 < shape->count())
        QTest::keyClick(shape, Qt::Key_Down);
    QCOMPARE(shape->currentText(), text);
}

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

void clickCorners(MainWindow& window, const std::vector<glm::vec2>& corners)
{
    for (const glm::vec2 c : corners) {
        QTest::mouseMove(&window.viewport(), pixelOf(window, c));
        QTest::mouseClick(&window.viewport(), Qt::LeftButton, Qt::NoModifier, pixelOf(window, c));
    }
}

}  // namespace

class TestPolygonGroupUi : public QObject {
    Q_OBJECT

private slots:
    void aConcavePolygonIsClickedClosedShownUndoneAndSaved()
    {
        MainWindow window;
        showNewWindow(window);
        window.viewport().frameAll();
        QTest::keyClick(&window.viewport(), Qt::Key_S);
        QVERIFY(groupTool(window));
        chooseShape(window, "Polygon");
        auto* amount = window.findChild<QComboBox*>("groupAmount");
        amount->setFocus();
        QTest::keyClick(amount, Qt::Key_Up);
        QCOMPARE(amount->currentText(), QString("Count"));
        typeInto(window.findChild<QSpinBox*>("groupCount"), "60");

        window.viewport().setFocus();
        clickCorners(window, kCorners);
        QCOMPARE(groupTool(window)->corners().size(), kCorners.size());
        QVERIFY(window.document().scene().groups.empty());  // still a preview
        QTest::keyClick(&window.viewport(), Qt::Key_Enter);

        const sim::Scene& scene = window.document().scene();
        QCOMPARE(scene.groups.size(), std::size_t(1));
        const sim::SpawnGroup& g = scene.groups[0];
        QCOMPARE(g.shape, sim::AreaShape::Polygon);
        QCOMPARE(g.count, 60u);
        QCOMPARE(g.type, std::string("pedestrian"));
        QCOMPARE(g.points.size(), kCorners.size());
        for (std::size_t i = 0; i < kCorners.size(); ++i)
            QVERIFY2(glm::distance(g.points[i], kCorners[i]) < kPickM,
                     qPrintable(QString("corner %1 at (%2, %3)").arg(i).arg(g.points[i].x).arg(g.points[i].y)));
        QVERIFY(groupTool(window)->corners().empty());
        QCOMPARE(window.document().selection(), (Selection{{ItemKind::Group, 0}}));
        QCOMPARE(window.document().undoStack()->count(), 1);

        // The view shows the 60 members, each inside the outline (none in the notch).
        QTRY_COMPARE(window.viewport().agentCount(), std::size_t(60));
        QCOMPARE(window.viewport().frameIndex(), std::size_t(0));  // where they spawned
        const ShownAgents& shown = window.viewport().shownAgents();
        QCOMPARE(shown.size(), std::size_t(60));
        for (std::size_t i = 0; i < shown.size(); ++i) {
            const glm::vec2 p(shown.feet(i).x, shown.feet(i).z);
            QVERIFY2(sim::polygonContains(g.points, p) ||
                         glm::distance(sim::nearestOnPolygonOutline(g.points, p), p) < 1e-3f,
                     qPrintable(QString("member %1 at (%2, %3) is outside the polygon").arg(i).arg(p.x).arg(p.y)));
        }

        // Saved through the document, the file reads back as the same polygon group.
        QTemporaryDir dir;
        const QString path = dir.filePath("polygon.yaml");
        QVERIFY(window.document().saveAs(path).ok);
        QFile file(path);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QVERIFY(file.readAll().contains("shape: polygon"));
        const sim::LoadResult again = sim::loadScene(path.toStdString());
        QVERIFY2(again.ok(), again.diagnostics.empty() ? "" : again.diagnostics[0].format().c_str());
        QCOMPARE(again.scene.groups.size(), std::size_t(1));
        QCOMPARE(again.scene.groups[0].shape, sim::AreaShape::Polygon);
        QVERIFY(again.scene.groups[0].points == g.points);

        // One undo step takes the whole group away.
        undo(window);
        QCOMPARE(scene.groups.size(), std::size_t(0));
        QTRY_COMPARE(window.viewport().agentCount(), std::size_t(0));
    }

    // By density the count follows the polygon's area; Backspace drops the last corner and
    // Escape the whole outline, without touching the document.
    void densityBackspaceAndEscape()
    {
        MainWindow window;
        showNewWindow(window);
        window.viewport().frameAll();
        QTest::keyClick(&window.viewport(), Qt::Key_S);
        chooseShape(window, "Polygon");
        auto* amount = window.findChild<QComboBox*>("groupAmount");
        QCOMPARE(amount->currentText(), QString("Density"));
        typeInto(window.findChild<QDoubleSpinBox*>("groupDensity"), "0.5");
        window.viewport().setFocus();
        clickCorners(window, {{-8, -6}, {8, -6}, {8, 6}, {12, 12}});
        QTest::keyClick(&window.viewport(), Qt::Key_Backspace);
        QCOMPARE(groupTool(window)->corners().size(), std::size_t(3));
        clickCorners(window, {{0, 0}, {-8, 6}});
        QTest::keyClick(&window.viewport(), Qt::Key_Return);
        const sim::Scene& scene = window.document().scene();
        QCOMPARE(scene.groups.size(), std::size_t(1));
        const double area = sim::polygonArea(scene.groups[0].points);
        QVERIFY(std::abs(area - 144.0) < 144.0 * 0.05);  // 192 m² less the 48 m² notch
        QCOMPARE(double(scene.groups[0].count), std::round(area * 0.5));
        // Escape throws a half-drawn outline away.
        clickCorners(window, {{10, 0}, {14, 0}, {14, 4}});
        QCOMPARE(groupTool(window)->corners().size(), std::size_t(3));
        QTest::keyClick(&window.viewport(), Qt::Key_Escape);
        QVERIFY(groupTool(window)->corners().empty());
        QCOMPARE(scene.groups.size(), std::size_t(1));
        QCOMPARE(window.document().undoStack()->count(), 1);
    }

    // A bow tie crosses itself: Enter is refused with the reason in the status text, the
    // corners stay for mending, and Backspace plus a new corner close it.
    void aSelfCrossingPolygonIsRefusedWithAReason()
    {
        MainWindow window;
        showNewWindow(window);
        window.viewport().frameAll();
        QTest::keyClick(&window.viewport(), Qt::Key_S);
        chooseShape(window, "Polygon");
        window.viewport().setFocus();
        clickCorners(window, {{-6, -6}, {6, 6}, {6, -6}, {-6, 6}});
        QTest::keyClick(&window.viewport(), Qt::Key_Enter);
        QVERIFY(window.document().scene().groups.empty());
        QVERIFY(groupTool(window)->refusal().contains("crosses itself"));
        QVERIFY(groupTool(window)->statusText().contains("crosses itself"));
        QCOMPARE(groupTool(window)->corners().size(), std::size_t(4));
        // Too few corners is refused the same way.
        QTest::keyClick(&window.viewport(), Qt::Key_Backspace);
        QTest::keyClick(&window.viewport(), Qt::Key_Backspace);
        QTest::keyClick(&window.viewport(), Qt::Key_Enter);
        QVERIFY(window.document().scene().groups.empty());
        QVERIFY(groupTool(window)->refusal().contains("at least 3 corners"));
        clickCorners(window, {{-6, 6}});
        QTest::keyClick(&window.viewport(), Qt::Key_Enter);
        QCOMPARE(window.document().scene().groups.size(), std::size_t(1));
        QVERIFY(groupTool(window)->refusal().isEmpty());
    }

    // Properties turns a rectangle group into a polygon on its corners and edits them in
    // the corner table; an edit that would make the outline cross itself is refused.
    void propertiesTurnARectangleIntoAPolygonAndEditItsCorners()
    {
        MainWindow window;
        QTemporaryDir dir;
        QVERIFY(showWithYaml(window, dir, "rect.yaml", "throng: 1\nagent_types:\n  - {name: walker, radius: 0.3}\n"
                                                     "groups:\n  - {name: yard, type: walker, count: 20, "
                                                     "rect: {min: [-10, -5], max: [0, 5]}}\n"));
        const sim::SpawnGroup& g = window.document().scene().groups[0];
        selectInOutliner(window, {{ItemKind::Group, 0}});
        QVERIFY(!field<QTableWidget>(window, "points")->isVisibleTo(window.findChild<QWidget*>("properties")));
        pick(window, "shape", "Polygon");
        QCOMPARE(g.shape, sim::AreaShape::Polygon);
        QVERIFY(g.points == (std::vector<glm::vec2>{{-10, -5}, {0, -5}, {0, 5}, {-10, 5}}));
        QCOMPARE(window.document().undoStack()->count(), 1);
        auto* table = field<QTableWidget>(window, "points");
        QTRY_VERIFY(table->isVisible());
        QCOMPARE(table->rowCount(), 4);
        // (0, -5) to (-20, -5): the edge from it would cross the left side.
        editCell(window, table, 1, 0, "-20");
        QTRY_VERIFY2(lastMessage(window).contains("crosses itself"), qPrintable(lastMessage(window)));
        QCOMPARE(g.points[1], glm::vec2(0, -5));
        QCOMPARE(window.document().undoStack()->count(), 1);
        editCell(window, field<QTableWidget>(window, "points"), 2, 0, "4");
        QTRY_COMPARE(g.points[2], glm::vec2(4, 5));
        QCOMPARE(window.document().undoStack()->count(), 2);
        QVERIFY(sceneYaml(window).contains("shape: polygon"));
    }
};

THRONG_REGISTER_TEST(TestPolygonGroupUi)
#include "TestPolygonGroupUi.moc"
