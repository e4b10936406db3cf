// Every fuzz node draws its membership curve; dragging a handle edits the parameter it
// stands for (a triangle's peak, a gaussian's width), as one undo step.
#include "BrainTestScenes.h"
#include "BrainUiDriver.h"
#include "TestRegistry.h"

#include "editor/brain/BrainGraphModel.h"
#include "editor/brain/BrainScene.h"
#include "editor/brain/FuzzCurve.h"
#include "editor/brain/FuzzCurveItem.h"
#include "editor/brain/NodeItem.h"

#include <QTest>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

namespace {
std::vector<float> points(MainWindow& window, sim::NodeId node)
{
    return paramNumbers(window.document().scene().brains[0].findNode(node)->params, "points");
}
}  // namespace

class TestFuzzCurveEditing : public QObject {
    Q_OBJECT

private slots:
    void everyFuzzNodeDrawsItsCurve()
    {
        QTemporaryDir dir;
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.open(dir, kWalkBrainScene));
        BrainScene& scene = ui.panel().scene();
        QVERIFY(scene.nodeItem(2)->fuzzCurve());
        QVERIFY(scene.nodeItem(4)->fuzzCurve());
        QVERIFY(!scene.nodeItem(5)->fuzzCurve());
        // The triangle [0, 0.7, 1.4]: its peak handle sits at the top, right of the foot at 0.
        FuzzCurveItem* curve = scene.nodeItem(4)->fuzzCurve();
        QCOMPARE(curve->handleCount(), 3);
        QVERIFY(curve->handleScenePos(1).y() < curve->handleScenePos(0).y() - 30);
        QVERIFY(curve->handleScenePos(1).x() > curve->handleScenePos(0).x() + 30);
        QCOMPARE(curve->handleScenePos(2).y(), curve->handleScenePos(0).y());
    }

    void draggingThePeakMovesIt()
    {
        QTemporaryDir dir;
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.open(dir, kWalkBrainScene));
        QUndoStack* stack = window.document().undoStack();
        const int steps = stack->count();
        FuzzCurveItem* curve = ui.panel().scene().nodeItem(4)->fuzzCurve();
        const QPointF peak = curve->handleScenePos(1);
        const QPointF foot = curve->handleScenePos(2);
        // Halfway from the peak to the right foot: b goes from 0.7 to about 1.05.
        ui.drag(peak, QPointF((peak.x() + foot.x()) / 2, peak.y()));
        const std::vector<float> p = points(window, 4);
        QCOMPARE(p.size(), std::size_t(3));
        QCOMPARE(p[0], 0.0f);
        QCOMPARE(p[2], 1.4f);
        QVERIFY2(std::abs(p[1] - 1.05f) < 0.05f, qPrintable(QString::number(double(p[1]))));
        QCOMPARE(stack->count(), steps + 1);
        // The node did not move: the drag was the handle's.
        QCOMPARE(ui.panel().scene().nodeItem(4)->pos().x(), double(window.document().scene().brains[0].findNode(4)->position.x));
        stack->undo();
        QCOMPARE(points(window, 4), (std::vector<float>{0.0f, 0.7f, 1.4f}));
        // The peak cannot pass the right foot.
        curve = ui.panel().scene().nodeItem(4)->fuzzCurve();
        ui.drag(curve->handleScenePos(1), curve->handleScenePos(2) + QPointF(40, 0));
        QCOMPARE(points(window, 4)[1], 1.4f);
    }

    void aGaussianWidthHandleSetsTheWidth()
    {
        QTemporaryDir dir;
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.open(dir, "throng: 1\nbrains:\n  - name: b\n    nodes:\n"
                             "      - {id: 1, type: fuzz.gaussian, position: [0, 0], params: {centre: 2, width: 1}}\n"));
        FuzzCurveItem* curve = ui.panel().scene().nodeItem(1)->fuzzCurve();
        QCOMPARE(curve->handleCount(), 2);
        const QPointF centre = curve->handleScenePos(0), width = curve->handleScenePos(1);
        // Twice as far from the centre: width 2.
        ui.drag(width, QPointF(centre.x() + 2 * (width.x() - centre.x()), width.y()));
        const float w = paramNumbers(window.document().scene().brains[0].nodes[0].params, "width")[0];
        QVERIFY2(std::abs(w - 2.0f) < 0.1f, qPrintable(QString::number(double(w))));
    }
};

THRONG_REGISTER_TEST(TestFuzzCurveEditing)
#include "TestFuzzCurveEditing.moc"
