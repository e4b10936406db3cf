// The brain editor's undo commands on their own: an edit of one brain and an edit of the
// brain list each redo, undo back to exactly the original and redo again; mergeable
// edits of the same brain fold into one step, and a net change of nothing disappears.
#include "TestRegistry.h"

#include "editor/SceneDocument.h"
#include "editor/brain/BrainCommands.h"

#include <QTest>

using namespace throng;
using namespace throng::editor;

namespace {

sim::BrainGraph twoNodes(std::string name = "b")
{
    sim::BrainGraph g;
    g.name = std::move(name);
    g.nodes = {{1, "input", "", {0, 0}, {{"sensor", "speed", {}}}}, {2, "output", "", {300, 0}, {}}};
    return g;
}

class SeedBrain : public QUndoCommand {
public:
    SeedBrain(SceneDocument& d) : m_doc(d) {}
    void redo() override { m_doc.modify(brains(), [](sim::Scene& s) { s.brains = {twoNodes()}; }); }
    void undo() override { m_doc.modify(brains(), [](sim::Scene& s) { s.brains.clear(); }); }

private:
    // The brain list as a whole.
    static SceneChange brains() { return SceneChange::ofAll(ItemKind::Brain, SceneField::Items); }

    SceneDocument& m_doc;
};

}  // namespace

class TestBrainCommands : public QObject {
    Q_OBJECT

private slots:
    void editBrainRedoUndoRedo()
    {
        SceneDocument doc;
        doc.undoStack()->push(new SeedBrain(doc));
        sim::BrainGraph after = twoNodes();
        after.links.push_back({1, 0, 2, 0});
        doc.undoStack()->push(new EditBrainCommand(doc, 0, twoNodes(), after, "Link"));
        QCOMPARE(doc.scene().brains[0].links.size(), std::size_t(1));
        doc.undoStack()->undo();
        QCOMPARE(doc.scene().brains[0], twoNodes());
        doc.undoStack()->redo();
        QCOMPARE(doc.scene().brains[0], after);
    }

    void mergeableEditsAreOneStep()
    {
        SceneDocument doc;
        doc.undoStack()->push(new SeedBrain(doc));
        const int steps = doc.undoStack()->count();
        sim::BrainGraph a = twoNodes(), b = twoNodes();
        a.nodes[1].position = {310, 0};
        b.nodes[1].position = {320, 0};
        doc.undoStack()->push(new EditBrainCommand(doc, 0, twoNodes(), a, "Nudge", true));
        doc.undoStack()->push(new EditBrainCommand(doc, 0, a, b, "Nudge", true));
        QCOMPARE(doc.undoStack()->count(), steps + 1);
        QCOMPARE(doc.scene().brains[0].nodes[1].position.x, 320.0f);
        doc.undoStack()->undo();
        QCOMPARE(doc.scene().brains[0], twoNodes());
        // Back where it started: the merged step vanishes.
        doc.undoStack()->redo();
        doc.undoStack()->push(new EditBrainCommand(doc, 0, b, twoNodes(), "Nudge", true));
        QCOMPARE(doc.undoStack()->count(), steps);
        QCOMPARE(doc.scene().brains[0], twoNodes());
        // Unmergeable edits stay separate.
        doc.undoStack()->push(new EditBrainCommand(doc, 0, twoNodes(), a, "Move"));
        doc.undoStack()->push(new EditBrainCommand(doc, 0, a, b, "Move"));
        QCOMPARE(doc.undoStack()->count(), steps + 2);
    }

    void editBrainListRedoUndoRedo()
    {
        SceneDocument doc;
        doc.undoStack()->push(new SeedBrain(doc));
        doc.modify(SceneChange::ofAll(ItemKind::AgentType, SceneField::Items),
                   [](sim::Scene& s) { s.agentTypes.push_back({}); });
        EditBrainsCommand::State before{doc.scene().brains, doc.scene().agentTypes, {}}, after = before;
        after.brains.push_back(twoNodes("walker brain"));
        after.agentTypes[0].brain = after.brains.back().name;
        doc.undoStack()->push(new EditBrainsCommand(doc, before, after, "Add brain c"));
        QCOMPARE(doc.scene().brains.size(), std::size_t(2));
        QCOMPARE(doc.scene().agentTypes[0].brain, std::string("walker brain"));
        doc.undoStack()->undo();
        QCOMPARE(doc.scene().brains, before.brains);
        QCOMPARE(doc.scene().agentTypes, before.agentTypes);
        doc.undoStack()->redo();
        QCOMPARE(doc.scene().brains, after.brains);
    }
};

THRONG_REGISTER_TEST(TestBrainCommands)
#include "TestBrainCommands.moc"
