// Opening a scene shows its brain in the Brains dock as a user sees it: one node per
// node with its typed ports and parameters inline, one curve per link from port to
// port, and a graph written without positions laid out in columns that read left to
// right, with no node on top of another.
#include "BrainTestScenes.h"
#include "BrainUiDriver.h"
#include "TestRegistry.h"

#include "editor/brain/BrainGraphModel.h"
#include "editor/brain/BrainScene.h"
#include "editor/brain/BrainView.h"
#include "editor/brain/LinkItem.h"
#include "editor/brain/NodeItem.h"
#include "editor/brain/PortItem.h"

#include <QComboBox>
#include <QDockWidget>
#include <QTest>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

class TestBrainGraphView : public QObject {
    Q_OBJECT

private slots:
    void theDockShowsNodesPortsParamsAndLinks()
    {
        QTemporaryDir dir;
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.open(dir, kWalkBrainScene));
        QVERIFY(window.brainEditor().isVisible());
        BrainEditorPanel& panel = ui.panel();
        QCOMPARE(panel.findChild<QComboBox*>("brainList")->currentText(), QString("walk"));
        BrainScene& scene = panel.scene();
        QCOMPARE(int(scene.nodeItems().size()), 6);
        QCOMPARE(int(scene.linkItems().size()), 5);
        // rule.and with two inputs connected offers a third, free one; an output has no outputs.
        QCOMPARE(scene.nodeItem(5)->inputCount(), 3);
        QCOMPARE(scene.nodeItem(5)->outputCount(), 1);
        QCOMPARE(scene.nodeItem(6)->inputCount(), 1);
        QCOMPARE(scene.nodeItem(6)->outputCount(), 0);
        // Parameters inline: the sensor name, the trapezoid's points, the output's channel.
        QCOMPARE(scene.nodeItem(1)->paramText(0), QString("goal_distance"));
        QCOMPARE(scene.nodeItem(2)->paramText(0), QString("0 3 1e+03 1e+03"));
        QCOMPARE(scene.nodeItem(6)->paramText(0), QString("speed"));
        // Each link is drawn from its output port to its input port.
        for (LinkItem* link : scene.linkItems()) {
            const sim::BrainLink& l = panel.model().graph().links[std::size_t(link->index())];
            QCOMPARE(link->from(), scene.nodeItem(l.fromNode)->outputPort(int(l.fromPort))->centre());
            QCOMPARE(link->to(), scene.nodeItem(l.toNode)->inputPort(int(l.toPort))->centre());
        }
        // The view shows the whole graph after opening.
        const QRectF visible = panel.view().mapToScene(panel.view().viewport()->rect()).boundingRect();
        for (NodeItem* n : scene.nodeItems())
            QVERIFY2(visible.contains(n->sceneBoundingRect()), qPrintable(QString::number(n->id())));
    }

    void aGraphWithoutPositionsIsLaidOutLeftToRight()
    {
        QTemporaryDir dir;
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.open(dir, kWalkBrainScene));
        BrainScene& scene = ui.panel().scene();
        // Every link runs from left to right.
        for (const sim::BrainLink& l : ui.panel().model().graph().links)
            QVERIFY(scene.nodeItem(l.fromNode)->x() < scene.nodeItem(l.toNode)->x());
        // No two nodes overlap.
        const std::vector<NodeItem*> nodes = scene.nodeItems();
        for (std::size_t i = 0; i < nodes.size(); ++i)
            for (std::size_t j = i + 1; j < nodes.size(); ++j)
                QVERIFY2(!nodes[i]->sceneBoundingRect().intersects(nodes[j]->sceneBoundingRect()),
                         qPrintable(QString("%1 %2").arg(nodes[i]->id()).arg(nodes[j]->id())));
        // Showing the layout does not edit the scene; the first edit keeps it.
        QVERIFY(!window.document().isModified());
        QCOMPARE(window.document().scene().brains[0].nodes[3].position.x, 0.0f);
        const QPointF before = scene.nodeItem(4)->pos();
        ui.drag(scene.nodeItem(6)->mapToScene(QPointF(60, 8)), scene.nodeItem(6)->mapToScene(QPointF(60, 108)));
        QCOMPARE(window.document().scene().brains[0].nodes[3].position.x, float(before.x()));
        QCOMPARE(scene.nodeItem(4)->pos(), before);
    }

    void theShippedPedestrianBrainOpensFromItsFile()
    {
        QTemporaryDir dir;
        QFile::copy(THRONG_SOURCE_DIR "/resources/brains/pedestrian.brain.yaml", dir.filePath("pedestrian.brain.yaml"));
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.open(dir, "throng: 1\nbrains: [{name: pedestrian, file: pedestrian.brain.yaml}]\n"
                             "agent_types: [{name: walker, brain: pedestrian}]\n"));
        const sim::BrainGraph& g = window.document().scene().brains[0];
        QVERIFY(g.nodes.size() > 5);
        QCOMPARE(ui.panel().scene().nodeItems().size(), g.nodes.size());
        QCOMPARE(ui.panel().scene().linkItems().size(), g.links.size());
        QVERIFY(ui.panel().errors().empty());
    }
};

THRONG_REGISTER_TEST(TestBrainGraphView)
#include "TestBrainGraphView.moc"
