// Several brains per scene: new, rename (the agent types and agents that use it follow), duplicate,
// delete, export to a .brain.yaml and import it back (laid out when it has no positions;
// a broken file says file:line:col), each one undo step.
#include "BrainTestScenes.h"
#include "BrainUiDriver.h"
#include "TestRegistry.h"

#include "editor/brain/BrainGraphModel.h"
#include "editor/brain/BrainScene.h"
#include "editor/brain/NodeItem.h"

#include <QComboBox>
#include <QFile>
#include <QTest>
#include <QToolButton>

using namespace throng;
using namespace throng::editor;
using namespace throng::editor::test;

class TestBrainLibrary : public QObject {
    Q_OBJECT

private slots:
    void renameDuplicateAndDelete()
    {
        QTemporaryDir dir;
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.open(dir, kWalkBrainScene));
        const sim::Scene& s = window.document().scene();
        QVERIFY(ui.panel().renameBrain("stroller"));
        QCOMPARE(s.brains[0].name, std::string("stroller"));
        QCOMPARE(s.agentTypes[0].brain, std::string("stroller"));
        QCOMPARE(ui.panel().findChild<QComboBox*>("brainList")->currentText(), QString("stroller"));
        window.document().undoStack()->undo();
        QCOMPARE(s.agentTypes[0].brain, std::string("walk"));
        window.document().undoStack()->redo();

        QTest::mouseClick(ui.panel().findChild<QToolButton*>("duplicateBrainButton"), Qt::LeftButton);
        QCOMPARE(s.brains.size(), std::size_t(2));
        QCOMPARE(s.brains[1].name, std::string("stroller copy"));
        QCOMPARE(s.brains[1].nodes, s.brains[0].nodes);
        QCOMPARE(s.brains[1].links, s.brains[0].links);
        QCOMPARE(ui.panel().model().brainIndex(), 1);
        // A name in use is refused.
        QVERIFY(!ui.panel().renameBrain("stroller"));
        QVERIFY(ui.panel().statusText().contains("already has"));
        ui.panel().deleteBrain();
        QCOMPARE(s.brains.size(), std::size_t(1));
        QCOMPARE(s.agentTypes[0].brain, std::string("stroller"));
    }

    // An agent with a brain of its own (the assign brush's) follows a rename, falls back
    // to its type's brain when that brain is deleted, and undo gives it back.
    void agentsWithTheBrainFollowRenameAndDelete()
    {
        QByteArray yaml = kWalkBrainScene;
        yaml.replace("position: [0, 0, 3], goal: g}", "position: [0, 0, 3], goal: g, brain: walk}");
        QTemporaryDir dir;
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.open(dir, yaml));
        const sim::Scene& s = window.document().scene();
        QCOMPARE(s.agents[1].brain, std::string("walk"));
        QVERIFY(ui.panel().renameBrain("amble"));
        QCOMPARE(s.agents[1].brain, std::string("amble"));
        QVERIFY(s.agents[0].brain.empty());
        ui.panel().deleteBrain();
        QVERIFY(s.brains.empty());
        QVERIFY(s.agents[1].brain.empty());
        window.document().undoStack()->undo();
        QCOMPARE(s.agents[1].brain, std::string("amble"));
        window.document().undoStack()->undo();
        QCOMPARE(s.agents[1].brain, std::string("walk"));
    }

    void exportThenImportGivesTheSameGraph()
    {
        QTemporaryDir dir;
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.open(dir, kWalkBrainScene));
        const QString path = dir.filePath("walk.brain.yaml");
        // Export writes the scene's graph: it has no positions yet (the layout is only shown).
        QVERIFY(ui.panel().exportBrain(path));
        QVERIFY(QFile::exists(path));
        QVERIFY(ui.panel().importBrain(path));
        const sim::Scene& s = window.document().scene();
        QCOMPARE(s.brains.size(), std::size_t(2));
        QCOMPARE(s.brains[1].name, std::string("walk 2"));
        QCOMPARE(s.brains[1].links, s.brains[0].links);
        QCOMPARE(s.brains[1].nodes.size(), s.brains[0].nodes.size());
        for (std::size_t i = 0; i < s.brains[0].nodes.size(); ++i) {
            QCOMPARE(s.brains[1].nodes[i].type, s.brains[0].nodes[i].type);
            QCOMPARE(s.brains[1].nodes[i].params, s.brains[0].nodes[i].params);
        }
        // The import had no positions: it is laid out, every link left to right.
        for (const sim::BrainLink& l : s.brains[1].links)
            QVERIFY(s.brains[1].findNode(l.fromNode)->position.x < s.brains[1].findNode(l.toNode)->position.x);
        window.document().undoStack()->undo();
        QCOMPARE(s.brains.size(), std::size_t(1));
    }

    void aBrokenFileSaysWhere()
    {
        QTemporaryDir dir;
        MainWindow window;
        BrainUi ui(window);
        QVERIFY(ui.open(dir, kWalkBrainScene));
        const QString path = dir.filePath("bad.brain.yaml");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("throng_brain: 1\nnodes:\n  - {id: 1, type: input}\n  - {id: 1, type: output}\n");
        f.close();
        QVERIFY(!ui.panel().importBrain(path));
        QVERIFY2(ui.panel().statusText().contains("bad.brain.yaml:4:"), qPrintable(ui.panel().statusText()));
        QCOMPARE(window.document().scene().brains.size(), std::size_t(1));
    }
};

THRONG_REGISTER_TEST(TestBrainLibrary)
#include "TestBrainLibrary.moc"
