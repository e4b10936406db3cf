// Opening one scene after another shows the second scene's brain as it is: a node that
// takes the id of a fuzz node of the brain shown before has no membership curve over its
// parameters, and every fuzz node's curve is one undo step per handle drag.
#include "BrainUiDriver.h"
#include "TestRegistry.h"

#include "editor/brain/BrainGraphModel.h"
#include "editor/brain/BrainScene.h"
#include "editor/brain/BrainView.h"
#include "editor/brain/FuzzCurve.h"
#include "editor/brain/FuzzCurveItem.h"
#include "editor/brain/NodeItem.h"

#include <QAbstractButton>
#include <QTest>
#include <QUndoStack>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {
const QString kScenes = QStringLiteral(THRONG_SOURCE_DIR "/resources/scenes/");

int curveChildren(const NodeItem* node)
{
    int curves = 0;
    for (const QGraphicsItem* child : node->childItems())
        curves += child->type() == FuzzCurveItem::Type ? 1 : 0;
    return curves;
}

const std::vector<sim::BrainParam>& paramsOf(MainWindow& window, int brain, sim::NodeId node)
{
    return window.document().scene().brains[std::size_t(brain)].findNode(node)->params;
}
}  // namespace

class TestBrainStateAcrossScenes : public QObject {
    Q_OBJECT

private slots:
    void theNextSceneShowsNoCurveOfTheCavalryBrain_data()
    {
        QTest::addColumn<QString>("next");
        QTest::newRow("murmuration") << "murmuration.yaml";
        QTest::newRow("crossroads") << "crossroads.yaml";
    }

    void theNextSceneShowsNoCurveOfTheCavalryBrain()
    {
        QFETCH(QString, next);
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.openPath(kScenes + "cavalry.yaml"));
        BrainScene& scene = ui.panel().scene();
        // The rider brain: nodes 3, 4, 5 and 10 are fuzz nodes with their curves.
        for (sim::NodeId id : {3u, 4u, 5u, 10u})
            QVERIFY(scene.nodeItem(id) && scene.nodeItem(id)->fuzzCurve());
        QVERIFY(ui.openPath(kScenes + next));
        const sim::BrainGraph& shown = ui.panel().model().graph();
        QCOMPARE(shown.name, window.document().scene().brains[0].name);
        QCOMPARE(scene.nodeItems().size(), shown.nodes.size());
        int plain = 0;
        for (const sim::BrainNode& n : shown.nodes) {
            NodeItem* item = scene.nodeItem(n.id);
            QVERIFY(item);
            const QString what = QStringLiteral("node %1 (%2)").arg(n.id).arg(QString::fromStdString(n.type));
            if (isFuzzType(n.type)) {
                QVERIFY2(item->fuzzCurve() && curveChildren(item) == 1, qPrintable(what));
                continue;
            }
            ++plain;
            QVERIFY2(!item->fuzzCurve(), qPrintable(what));
            QVERIFY2(curveChildren(item) == 0, qPrintable(what));
            // Each parameter row is drawn inside the node with no curve over it.
            for (int row = 0; item->paramSpec(row); ++row) {
                const QPointF at = item->mapToScene(item->paramRect(row).center());
                QVERIFY2(item->boundingRect().contains(item->paramRect(row)), qPrintable(what));
                const QList<QGraphicsItem*> there = scene.items(at);
                QVERIFY2(there.contains(item), qPrintable(what));
                for (const QGraphicsItem* other : there)
                    QVERIFY2(other->type() != FuzzCurveItem::Type, qPrintable(what + QStringLiteral(" row %1").arg(row)));
            }
        }
        QVERIFY(plain > 5);
    }

    void everyCurveHandleDragIsOneUndoStep()
    {
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.openPath(kScenes + "cavalry.yaml"));
        QVERIFY(ui.openPath(kScenes + "murmuration.yaml"));
        BrainView& view = ui.panel().view();
        view.resetTransform();
        QUndoStack* stack = window.document().undoStack();
        // The boid brain's file puts nodes 100 units apart, over the curves of the fuzz
        // nodes above them; Layout spaces them so every curve can be reached.
        auto* layout = ui.panel().findChild<QAbstractButton*>("layoutBrainButton");
        QVERIFY(layout);
        QTest::mouseClick(layout, Qt::LeftButton);
        const sim::BrainGraph shown = ui.panel().model().graph();
        int dragged = 0;
        for (const sim::BrainNode& n : shown.nodes) {
            if (!isFuzzType(n.type))
                continue;
            const QString what = QStringLiteral("node %1 (%2)").arg(n.id).arg(QString::fromStdString(n.type));
            const std::vector<sim::BrainParam> before = paramsOf(window, 0, n.id);
            FuzzCurveItem* curve = ui.panel().scene().nodeItem(n.id)->fuzzCurve();
            QVERIFY2(curve, qPrintable(what));
            // The first handle the user can grab (not under a link).
            int grab = 0;
            while (grab < curve->handleCount() &&
                   ui.panel().scene().itemAt(curve->handleScenePos(grab), view.transform()) != curve)
                ++grab;
            QVERIFY2(grab < curve->handleCount(), qPrintable(what));
            const QPointF handle = curve->handleScenePos(grab);
            view.centerOn(handle);
            const int steps = stack->index();
            // 20 pixels toward the middle of the curve: room for the handle in every shape
            // (of two handles on one spot the press takes the later, which goes right).
            const double middle = curve->mapToScene(curve->boundingRect().center()).x();
            ui.drag(handle, handle + QPointF(handle.x() < middle ? 20.0 : -20.0, 0.0));
            QVERIFY2(stack->index() == steps + 1 && stack->count() == steps + 1, qPrintable(what));
            QVERIFY2(!(paramsOf(window, 0, n.id) == before), qPrintable(what));
            QCOMPARE(ui.panel().scene().nodeItem(n.id)->pos(),
                     QPointF(double(n.position.x), double(n.position.y)));
            stack->undo();
            QCOMPARE(stack->index(), steps);
            QVERIFY2(paramsOf(window, 0, n.id) == before, qPrintable(what));
            QCOMPARE(ui.panel().scene().nodeItem(n.id)->fuzzCurve()->params(), before);
            ++dragged;
        }
        QCOMPARE(dragged, 3);  // the boid brain's two trapezoids and its sigmoid
    }
};

THRONG_REGISTER_TEST(TestBrainStateAcrossScenes)
#include "TestBrainStateAcrossScenes.moc"
