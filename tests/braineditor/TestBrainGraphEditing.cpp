// Editing a brain as a user does: Tab and typing adds a node, the Add Node menu adds one
// by category, dragging from an output to an input draws the link, a link of the wrong
// type or a loop without memory is refused with a message, Delete removes, undo/redo
// restore the graph exactly, a node drag is one undo step, parameters are typed inline.
#include "BrainTestScenes.h"
#include "BrainUiDriver.h"
#include "TestRegistry.h"

#include "editor/brain/BrainGraphModel.h"
#include "editor/brain/BrainScene.h"
#include "editor/brain/BrainView.h"
#include "editor/brain/LinkItem.h"
#include "editor/brain/NodeItem.h"
#include "editor/brain/NodePalette.h"
#include "editor/brain/PortItem.h"

#include <QImage>
#include <QLineEdit>
#include <QListWidget>
#include <QMenu>
#include <QTest>
#include <QToolButton>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {
const QByteArray kEmptyBrain = "throng: 1\nbrains: [{name: b, nodes: [], links: []}]\n";
}

class TestBrainGraphEditing : public QObject {
    Q_OBJECT

private slots:
    void typingInThePaletteAddsTheNodeUnderTheMouse()
    {
        QTemporaryDir dir;
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.open(dir, kEmptyBrain));
        ui.panel().view().setTransform({});
        ui.panel().view().centerOn(0, 0);
        // Typing narrows the list: "triang" leaves only the triangle membership.
        QTest::mouseMove(ui.panel().view().viewport(), ui.pixel({-100, -50}));
        QTest::keyClick(&ui.panel().view(), Qt::Key_Tab);
        NodePalette& palette = ui.panel().palette();
        QVERIFY(palette.isVisible());
        QVERIFY(palette.shownTypes().size() > 30);
        QTest::keyClicks(palette.search(), "triang");
        QCOMPARE(palette.shownTypes(), QStringList{"fuzz.triangle"});
        QTest::keyClick(palette.search(), Qt::Key_Return);
        QVERIFY(!palette.isVisible());
        QCOMPARE(ui.nodeCount(), 1);
        const sim::BrainNode& n = ui.panel().model().graph().nodes[0];
        QCOMPARE(n.type, std::string("fuzz.triangle"));
        QVERIFY(std::abs(n.position.x + 100.0f) < 2.0f && std::abs(n.position.y + 50.0f) < 2.0f);
        // Escape closes the palette without adding anything.
        QTest::keyClick(&ui.panel().view(), Qt::Key_Tab);
        QTest::keyClicks(palette.search(), "output");
        QTest::keyClick(palette.search(), Qt::Key_Escape);
        QCOMPARE(ui.nodeCount(), 1);
        // And the categorised menu: math > math.add.
        auto* add = ui.panel().findChild<QToolButton*>("addNodeButton");
        QAction* mathAdd = nullptr;
        for (QAction* category : add->menu()->actions())
            if (category->text() == "math")
                for (QAction* a : category->menu()->actions())
                    if (a->text() == "math.add")
                        mathAdd = a;
        QVERIFY(mathAdd);
        mathAdd->trigger();
        QCOMPARE(ui.panel().model().graph().nodes.back().type, std::string("math.add"));
    }

    // A scene without brains, or a brain without nodes, is no blank canvas: the view says
    // how to start, and the first node typed in makes the brain.
    void anEmptyGraphSaysHowToStart()
    {
        QTemporaryDir dir;
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.open(dir, "throng: 1\n"));
        BrainView& view = ui.panel().view();
        QVERIFY(window.document().scene().brains.empty());
        QVERIFY2(view.hint().contains("no brains yet") && view.hint().contains("Tab"), qPrintable(view.hint()));
        // Drawn where the user looks, and legible: pixels across the middle of the view far
        // brighter than the graph's ground (its top-left corner).
        auto hintPixels = [&] {
            const QImage image = view.viewport()->grab().toImage();
            const int ground = qGray(image.pixel(0, 0));
            int count = 0;
            for (int y = image.height() / 3; y < 2 * image.height() / 3; ++y)
                for (int x = 0; x < image.width(); ++x)
                    count += qGray(image.pixel(x, y)) > ground + 80;
            return count;
        };
        QVERIFY2(hintPixels() > 200, qPrintable(QString::number(hintPixels())));
        // Tab and a node's name: a new brain holds the node, and the hint is gone.
        QVERIFY(ui.addByTyping({0, 0}, "triang") != 0);
        QCOMPARE(window.document().scene().brains.size(), std::size_t(1));
        QCOMPARE(ui.nodeCount(), 1);
        QVERIFY(view.hint().isEmpty());
        // Its last node deleted, the brain says it has none.
        NodeItem* node = ui.panel().scene().nodeItems().front();
        ui.click(node->mapToScene(node->boundingRect().center()));
        QVERIFY(node->isSelected());
        ui.key(Qt::Key_Delete);
        QCOMPARE(ui.nodeCount(), 0);
        const QString name = QString::fromStdString(window.document().scene().brains[0].name);
        QVERIFY2(view.hint().contains("'" + name + "' has no nodes yet"), qPrintable(view.hint()));
        QVERIFY(hintPixels() > 200);
        // Undone step by step (the delete, the node, the new brain), the hints follow.
        QTest::keyClick(&window, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(ui.nodeCount(), 1);
        QVERIFY(view.hint().isEmpty());
        QTest::keyClick(&window, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(ui.nodeCount(), 0);
        QVERIFY(view.hint().contains("has no nodes yet"));
        QTest::keyClick(&window, Qt::Key_Z, Qt::ControlModifier);
        QVERIFY(window.document().scene().brains.empty());
        QVERIFY2(view.hint().contains("no brains yet"), qPrintable(view.hint()));
    }

    void draggingFromPortToPortLinksThem()
    {
        QTemporaryDir dir;
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.open(dir, kEmptyBrain));
        const sim::NodeId in = ui.addByTyping({0, 0}, "input.constant");
        const sim::NodeId out = ui.addByTyping({300, 0}, "rule.not");
        QVERIFY(in && out);
        ui.dragLink(in, 0, out, 0);
        QCOMPARE(ui.linkCount(), 1);
        QCOMPARE(ui.panel().model().graph().links[0], (sim::BrainLink{in, 0, out, 0}));
        QCOMPARE(int(ui.panel().scene().linkItems().size()), 1);
        const LinkItem* link = ui.panel().scene().linkItems()[0];
        QCOMPARE(link->to(), ui.panel().scene().nodeItem(out)->inputPort(0)->centre());
        // The same drag again: the input is taken, so it is refused with a message.
        ui.dragLink(in, 0, out, 0);
        QCOMPARE(ui.linkCount(), 1);
        QVERIFY2(ui.panel().statusText().contains("already connected"), qPrintable(ui.panel().statusText()));
    }

    void aTypeMismatchIsRefusedVisibly()
    {
        QTemporaryDir dir;
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.open(dir, kEmptyBrain));
        const sim::NodeId near = ui.addByTyping({0, 0}, "input");
        QVERIFY(ui.editParam(near, "sensor", "neighbour_distance"));
        const sim::NodeId out = ui.addByTyping({300, 0}, "output");
        QCOMPARE(ui.panel().scene().nodeItem(near)->outputPort(0)->kind(), sim::PortKind::PerNeighbour);
        // While hovering, the target port turns red; on release nothing is linked.
        PortItem* target = ui.panel().scene().nodeItem(out)->inputPort(0);
        QWidget* vp = ui.panel().view().viewport();
        const QPoint a = ui.pixel(ui.panel().scene().nodeItem(near)->outputPort(0)->centre());
        QTest::mouseMove(vp, a);
        QTest::mousePress(vp, Qt::LeftButton, {}, a);
        QTest::mouseMove(vp, (a + ui.pixel(target->centre())) / 2);
        QTest::mouseMove(vp, ui.pixel(target->centre()));
        QCOMPARE(target->pen().color(), QColor(230, 40, 40));
        QTest::mouseRelease(vp, Qt::LeftButton, {}, ui.pixel(target->centre()));
        QCOMPARE(ui.linkCount(), 0);
        QVERIFY2(ui.panel().statusText().contains("type mismatch"), qPrintable(ui.panel().statusText()));
        // Through a filter it is accepted.
        const sim::NodeId filter = ui.addByTyping({150, 200}, "filter");
        ui.dragLink(near, 0, filter, 0);
        ui.dragLink(filter, 0, out, 0);
        QCOMPARE(ui.linkCount(), 2);
    }

    void aLoopNeedsAMemoryNode()
    {
        QTemporaryDir dir;
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.open(dir, kEmptyBrain));
        const sim::NodeId a = ui.addByTyping({0, 0}, "rule.not");
        const sim::NodeId b = ui.addByTyping({300, 0}, "math.abs");
        ui.dragLink(a, 0, b, 0);
        ui.dragLink(b, 0, a, 0);
        QCOMPARE(ui.linkCount(), 1);
        QVERIFY2(ui.panel().statusText().contains("loop"), qPrintable(ui.panel().statusText()));
        const sim::NodeId memory = ui.addByTyping({150, 250}, "state.memory");
        ui.dragLink(b, 0, memory, 0);
        ui.dragLink(memory, 0, a, 0);
        QCOMPARE(ui.linkCount(), 3);
    }

    void deleteUndoAndRedoRestoreTheGraph()
    {
        QTemporaryDir dir;
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.open(dir, kWalkBrainScene));
        const sim::BrainGraph original = ui.panel().model().graph();
        NodeItem* trapezoid = ui.panel().scene().nodeItem(2);
        ui.click(trapezoid->mapToScene(QPointF(100, 8)));
        QVERIFY(trapezoid->isSelected());
        ui.key(Qt::Key_Delete);
        QCOMPARE(ui.nodeCount(), 5);
        QCOMPARE(ui.linkCount(), 2);  // its three links went with it
        QVERIFY(!ui.panel().scene().nodeItem(2));
        window.document().undoStack()->undo();
        QCOMPARE(ui.panel().model().graph(), original);
        QVERIFY(ui.panel().scene().nodeItem(2));
        QCOMPARE(int(ui.panel().scene().linkItems().size()), 5);
        window.document().undoStack()->redo();
        QCOMPARE(ui.nodeCount(), 5);
        QCOMPARE(ui.linkCount(), 2);
        // A link is selected by clicking its curve, and deleted alone.
        LinkItem* link = ui.panel().scene().linkItems()[0];
        ui.panel().scene().clearSelection();
        ui.click(link->path().pointAtPercent(0.5));
        QVERIFY(link->isSelected());
        ui.key(Qt::Key_Delete);
        QCOMPARE(ui.linkCount(), 1);
        QCOMPARE(ui.nodeCount(), 5);
    }

    void aNodeDragIsOneUndoStep()
    {
        QTemporaryDir dir;
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.open(dir, kWalkBrainScene));
        QUndoStack* stack = window.document().undoStack();
        const int steps = stack->count();
        NodeItem* node = ui.panel().scene().nodeItem(6);
        const QPointF start = node->pos();
        ui.drag(node->mapToScene(QPointF(100, 8)), node->mapToScene(QPointF(100, 8)) + QPointF(0, 120));
        QCOMPARE(stack->count(), steps + 1);
        const sim::BrainNode* moved = window.document().scene().brains[0].findNode(6);
        QVERIFY(std::abs(moved->position.y - float(start.y() + 120)) < 2.0f);
        // The link into it follows the node.
        for (LinkItem* link : ui.panel().scene().linkItems())
            if (ui.panel().model().graph().links[std::size_t(link->index())].toNode == 6)
                QCOMPARE(link->to(), ui.panel().scene().nodeItem(6)->inputPort(0)->centre());
        stack->undo();
        QCOMPARE(ui.panel().scene().nodeItem(6)->pos(), start);
    }

    void parametersAreTypedInline()
    {
        QTemporaryDir dir;
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.open(dir, kWalkBrainScene));
        QVERIFY(ui.editParam(6, "scale", "2.5"));
        QCOMPARE(ui.panel().scene().nodeItem(6)->paramText(3), QString("2.5"));
        QCOMPARE(window.document().scene().brains[0].findNode(6)->params[1].numbers, std::vector<float>{2.5f});
        // A list of the wrong length is refused and says why.
        QVERIFY(ui.editParam(4, "points", "1 2"));
        QVERIFY2(ui.panel().statusText().contains("3 numbers"), qPrintable(ui.panel().statusText()));
        QCOMPARE(ui.panel().scene().nodeItem(4)->paramText(0), QString("0 0.7 1.4"));
    }
};

THRONG_REGISTER_TEST(TestBrainGraphEditing)
#include "TestBrainGraphEditing.moc"
