// The graph tools a brain author reaches for: box select, copy/paste and duplicate with
// the links between the copies, frame all (F) and frame selection (Shift+F), a comment
// backdrop, collapsing a selection into a macro and expanding it back, and a link
// dropped on empty space that offers only compatible nodes.
#include "BrainTestScenes.h"
#include "BrainUiDriver.h"
#include "TestRegistry.h"

#include "editor/brain/BrainGraphModel.h"
#include "editor/brain/BrainScene.h"
#include "editor/brain/BrainView.h"
#include "editor/brain/NodeItem.h"
#include "editor/brain/NodePalette.h"
#include "editor/brain/PortItem.h"
#include "simcore/brain/BrainCompiler.h"

#include <QApplication>
#include <QLineEdit>
#include <QWheelEvent>
#include <QTest>

#include <set>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {
QRectF visibleRect(BrainEditorPanel& panel)
{
    return panel.view().mapToScene(panel.view().viewport()->rect()).boundingRect();
}
}  // namespace

class TestBrainGraphTools : public QObject {
    Q_OBJECT

private slots:
    void boxSelectCopyPasteAndDuplicate()
    {
        QTemporaryDir dir;
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.open(dir, kWalkBrainScene));
        BrainScene& scene = ui.panel().scene();
        // A box round the two inputs and their fuzz nodes (the first two columns).
        QRectF box;
        for (sim::NodeId id : {1u, 2u, 3u, 4u})
            box |= scene.nodeItem(id)->sceneBoundingRect();
        ui.drag(box.topLeft() - QPointF(20, 20), box.bottomRight() + QPointF(20, 20));
        QCOMPARE(scene.selectedNodes(), (std::vector<sim::NodeId>{1, 2, 3, 4}));
        ui.key(Qt::Key_C, Qt::ControlModifier);
        ui.key(Qt::Key_V, Qt::ControlModifier);
        QCOMPARE(ui.nodeCount(), 10);
        // The two links among the copies came along; the copies are selected.
        QCOMPARE(ui.linkCount(), 7);
        QCOMPARE(scene.selectedNodes(), (std::vector<sim::NodeId>{7, 8, 9, 10}));
        QCOMPARE(ui.panel().model().graph().links[5], (sim::BrainLink{7, 0, 8, 0}));
        ui.key(Qt::Key_D, Qt::ControlModifier);
        QCOMPARE(ui.nodeCount(), 14);
        QCOMPARE(ui.linkCount(), 9);
        window.document().undoStack()->undo();
        QCOMPARE(ui.nodeCount(), 10);
    }

    void frameAllAndFrameSelection()
    {
        QTemporaryDir dir;
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.open(dir, kWalkBrainScene));
        BrainEditorPanel& panel = ui.panel();
        panel.view().zoomBy(3.0);
        panel.view().centerOn(5000, 5000);
        ui.key(Qt::Key_F);
        for (NodeItem* n : panel.scene().nodeItems())
            QVERIFY(visibleRect(panel).contains(n->sceneBoundingRect()));
        // Shift+F fills the view with the selected node.
        panel.scene().nodeItem(6)->setSelected(true);
        ui.key(Qt::Key_F, Qt::ShiftModifier);
        const QRectF node = panel.scene().nodeItem(6)->sceneBoundingRect();
        QVERIFY(visibleRect(panel).contains(node));
        QVERIFY(!visibleRect(panel).contains(panel.scene().nodeItem(1)->sceneBoundingRect()));
    }

    void wheelZoomsAndMiddleDragPans()
    {
        QTemporaryDir dir;
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.open(dir, kWalkBrainScene));
        BrainView& view = ui.panel().view();
        const double zoom = view.zoom();
        QWidget* vp = view.viewport();
        const QPoint centre = vp->rect().center();
        QWheelEvent wheel(centre, vp->mapToGlobal(centre), {}, {0, 240}, Qt::NoButton, Qt::NoModifier, Qt::NoScrollPhase, false);
        QApplication::sendEvent(vp, &wheel);
        QVERIFY2(std::abs(view.zoom() - zoom * 1.44) < 1e-6, qPrintable(QString::number(view.zoom() / zoom)));
        // A middle drag of 100 px to the right moves the graph 100 px right on screen.
        NodeItem* node = ui.panel().scene().nodeItem(1);
        const QPoint before = view.mapFromScene(node->pos());
        QTest::mousePress(vp, Qt::MiddleButton, {}, centre);
        QTest::mouseMove(vp, centre + QPoint(50, 0));
        QTest::mouseMove(vp, centre + QPoint(100, 0));
        QTest::mouseRelease(vp, Qt::MiddleButton, {}, centre + QPoint(100, 0));
        QCOMPARE(view.mapFromScene(node->pos()), before + QPoint(100, 0));
    }

    void aCommentBackdropSitsBehindTheNodes()
    {
        QTemporaryDir dir;
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.open(dir, kWalkBrainScene));
        const sim::NodeId note = ui.addByTyping(ui.panel().scene().nodeItem(1)->pos() - QPointF(0, 200), "note");
        QVERIFY(ui.editParam(note, "text", "Slow down near the goal"));
        NodeItem* item = ui.panel().scene().nodeItem(note);
        QCOMPARE(item->paramText(0), QString("Slow down near the goal"));
        QVERIFY(item->zValue() < ui.panel().scene().nodeItem(1)->zValue());
        QVERIFY(ui.panel().errors().empty());
    }

    void collapseIntoAMacroAndExpandBack()
    {
        QTemporaryDir dir;
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.open(dir, kWalkBrainScene));
        BrainScene& scene = ui.panel().scene();
        const sim::BrainGraph before = ui.panel().model().graph();
        for (sim::NodeId id : {2u, 4u, 5u})
            scene.nodeItem(id)->setSelected(true);
        ui.key(Qt::Key_G, Qt::ControlModifier);
        const sim::Scene& s = window.document().scene();
        QCOMPARE(s.brains.size(), std::size_t(2));
        QCOMPARE(ui.nodeCount(), 4);  // two inputs, the output and the macro
        const sim::BrainNode& macro = ui.panel().model().graph().nodes.back();
        QCOMPARE(macro.type, std::string("macro"));
        QVERIFY2(ui.panel().errors().empty(), ui.panel().errors().empty() ? "" : ui.panel().errors()[0].message.c_str());
        // The macro computes what the nodes did: same outputs for the same inputs.
        const sim::BrainCompileResult withMacro = sim::compileBrain(ui.panel().model().graph(), s.brains);
        QVERIFY(withMacro.ok());
        // Undo brings the nodes back in one step; redo collapses again; expand inlines it.
        window.document().undoStack()->undo();
        QCOMPARE(ui.panel().model().graph(), before);
        window.document().undoStack()->redo();
        scene.clearSelection();
        scene.nodeItem(macro.id)->setSelected(true);
        ui.key(Qt::Key_G, Qt::ControlModifier | Qt::ShiftModifier);
        QCOMPARE(ui.nodeCount(), 6);
        QCOMPARE(ui.linkCount(), 5);
        std::multiset<std::string> types, typesBefore;
        for (const sim::BrainNode& n : ui.panel().model().graph().nodes)
            types.insert(n.type);
        for (const sim::BrainNode& n : before.nodes)
            typesBefore.insert(n.type);
        QCOMPARE(types, typesBefore);
        QVERIFY(ui.panel().errors().empty());
    }

    void aLinkDroppedOnEmptySpaceOffersCompatibleNodes()
    {
        QTemporaryDir dir;
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.open(dir, "throng: 1\nbrains:\n  - name: b\n    nodes:\n"
                             "      - {id: 1, type: input, position: [0, 0], params: {sensor: neighbour_distance}}\n"));
        PortItem* out = ui.panel().scene().nodeItem(1)->outputPort(0);
        const QPointF empty = out->centre() + QPointF(250, 0);
        ui.drag(out->centre(), empty);
        NodePalette& palette = ui.panel().palette();
        QVERIFY(palette.isVisible());
        const QStringList offered = palette.shownTypes();
        // A per-neighbour value may feed a filter or a fuzz set, never an output or a memory.
        QVERIFY(offered.contains("filter"));
        QVERIFY(offered.contains("fuzz.triangle"));
        QVERIFY(!offered.contains("output"));
        QVERIFY(!offered.contains("state.memory"));
        QTest::keyClicks(palette.search(), "filter");
        QTest::keyClick(palette.search(), Qt::Key_Return);
        QCOMPARE(ui.nodeCount(), 2);
        QCOMPARE(ui.linkCount(), 1);
        QCOMPARE(ui.panel().model().graph().links[0], (sim::BrainLink{1, 0, 2, 0}));
        // Adding and linking was one step.
        window.document().undoStack()->undo();
        QCOMPARE(ui.nodeCount(), 1);
    }
};

THRONG_REGISTER_TEST(TestBrainGraphTools)
#include "TestBrainGraphTools.moc"
