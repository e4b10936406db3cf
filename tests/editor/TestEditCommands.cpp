// Every edit command done, undone and redone as the history view would: the scene after
// undo equals the scene before, redo brings the edit back, and the merging commands
// make one step of a stroke or a drag.
#include "TestRegistry.h"

#include "editor/SceneDocument.h"
#include "editor/commands/AddSceneItemCommand.h"
#include "editor/commands/ChangeValueCommand.h"
#include "editor/commands/EraseAgentsCommand.h"
#include "editor/commands/MoveItemsCommand.h"
#include "editor/commands/PaintAgentsCommand.h"

#include <QSignalSpy>
#include <QTest>

using namespace throng;
using namespace throng::editor;

namespace {

sim::Agent walkerAt(std::uint32_t id, float x, float z)
{
    sim::Agent a;
    a.id = id;
    a.type = "walker";
    a.position = {x, 0.0f, z};
    return a;
}

// A document holding agents 1..5 at x = 0..4, built through commands so it is "opened".
void fillFive(SceneDocument& doc)
{
    std::vector<sim::Agent> five;
    for (std::uint32_t i = 0; i < 5; ++i)
        five.push_back(walkerAt(i + 1, float(i), 0.0f));
    PaintAgentsCommand(doc, five, -1).redo();
}

}  // namespace

class TestEditCommands : public QObject {
    Q_OBJECT

private slots:
    void paintAddsUndoRemovesRedoRestores()
    {
        SceneDocument doc;
        QSignalSpy changed(&doc, &SceneDocument::sceneChanged);
        doc.undoStack()->push(new PaintAgentsCommand(doc, {walkerAt(1, 2, 3), walkerAt(2, 4, 5)}, 1));
        QCOMPARE(doc.scene().agents.size(), std::size_t(2));
        QCOMPARE(doc.scene().agents[1].position, glm::vec3(4, 0, 5));
        QVERIFY(changed.count() >= 1);
        QVERIFY(doc.isModified());
        doc.undoStack()->undo();
        QVERIFY(doc.scene().agents.empty());
        QVERIFY(!doc.isModified());
        doc.undoStack()->redo();
        QCOMPARE(doc.scene().agents.size(), std::size_t(2));
        QCOMPARE(doc.nextAgentId(), std::uint32_t(3));
    }

    void dabsOfOneStrokeMergeIntoOneStep()
    {
        SceneDocument doc;
        doc.undoStack()->push(new PaintAgentsCommand(doc, {walkerAt(1, 0, 0)}, 7));
        doc.undoStack()->push(new PaintAgentsCommand(doc, {walkerAt(2, 1, 0), walkerAt(3, 2, 0)}, 7));
        doc.undoStack()->push(new PaintAgentsCommand(doc, {walkerAt(4, 9, 0)}, 8));
        QCOMPARE(doc.undoStack()->count(), 2);
        QCOMPARE(doc.undoStack()->command(0)->text(), QString("Paint 3 agent(s)"));
        doc.undoStack()->undo();
        QCOMPARE(doc.scene().agents.size(), std::size_t(3));
        doc.undoStack()->undo();
        QVERIFY(doc.scene().agents.empty());
    }

    void eraseRestoresAgentsAtTheirPlaces()
    {
        SceneDocument doc;
        fillFive(doc);
        const std::vector<sim::Agent> before = doc.scene().agents;
        // Two dabs of one stroke: indices of the first dab, then of the scene after it.
        doc.undoStack()->push(new EraseAgentsCommand(doc, {3, 1}, 4));
        QCOMPARE(doc.scene().agents.size(), std::size_t(3));
        doc.undoStack()->push(new EraseAgentsCommand(doc, {0}, 4));
        QCOMPARE(doc.undoStack()->count(), 1);
        QCOMPARE(doc.scene().agents.size(), std::size_t(2));
        QCOMPARE(doc.scene().agents[0].id, std::uint32_t(3));
        QCOMPARE(doc.scene().agents[1].id, std::uint32_t(5));
        doc.undoStack()->undo();
        QVERIFY(doc.scene().agents == before);
        doc.undoStack()->redo();
        QCOMPARE(doc.scene().agents.size(), std::size_t(2));
    }

    void addedWallGoesAwayWithUndo()
    {
        SceneDocument doc;
        sim::Wall wall{"wall_1", {{0, 0}, {5, 0}, {5, 5}}};
        doc.undoStack()->push(new AddSceneItemCommand<sim::Wall>(doc, &sim::Scene::walls, wall, "Add wall"));
        QCOMPARE(doc.scene().walls.size(), std::size_t(1));
        QVERIFY(doc.scene().walls[0] == wall);
        doc.setSelection({{ItemKind::Wall, 0}});
        doc.undoStack()->undo();
        QVERIFY(doc.scene().walls.empty());
        QVERIFY2(doc.selection().empty(), "the removed wall must leave the selection");
        doc.undoStack()->redo();
        QVERIFY(doc.scene().walls[0] == wall);
    }

    void valueChangesOfOneKeyMergeAndAZeroNetChangeIsObsolete()
    {
        SceneDocument doc;
        fillFive(doc);
        auto locate = [](sim::Scene& s) -> float& { return s.agents[2].headingDeg; };
        const SceneChange heading = SceneChange::of({ItemKind::Agent, 2}, SceneField::Heading);
        QUndoStack* stack = doc.undoStack();
        stack->push(new ChangeValueCommand<float>(doc, "h", locate, 30.0f, "Heading", heading));
        stack->push(new ChangeValueCommand<float>(doc, "h", locate, 45.0f, "Heading", heading));
        QCOMPARE(stack->count(), 1);
        QCOMPARE(doc.scene().agents[2].headingDeg, 45.0f);
        stack->undo();
        QCOMPARE(doc.scene().agents[2].headingDeg, 0.0f);
        stack->redo();
        QCOMPARE(doc.scene().agents[2].headingDeg, 45.0f);
        // Back to where the step began: the merged step does nothing and leaves the stack.
        stack->push(new ChangeValueCommand<float>(doc, "h2", locate, 10.0f, "Heading", heading));
        stack->push(new ChangeValueCommand<float>(doc, "h2", locate, 45.0f, "Heading", heading));
        QCOMPARE(stack->count(), 1);
        QCOMPARE(doc.scene().agents[2].headingDeg, 45.0f);
    }

    // A polygon group moves by its corners (and nothing else of it); the moves of one
    // drag merge into one step.
    void movingAPolygonGroupMovesItsCorners()
    {
        SceneDocument doc;
        sim::SpawnGroup g;
        g.name = "yard";
        g.type = "walker";
        g.count = 10;
        g.shape = sim::AreaShape::Polygon;
        g.points = {{0, 0}, {10, 0}, {10, 4}, {4, 4}, {4, 10}, {0, 10}};
        doc.undoStack()->push(new AddSceneItemCommand<sim::SpawnGroup>(doc, &sim::Scene::groups, g, "Add group"));
        QVERIFY(MoveItemsCommand::movable(ItemKind::Group));
        QUndoStack* stack = doc.undoStack();
        stack->push(new MoveItemsCommand(doc, {{ItemKind::Group, 0}}, {2, -1}, 7));
        stack->push(new MoveItemsCommand(doc, {{ItemKind::Group, 0}}, {1, 3}, 7));
        QCOMPARE(stack->count(), 2);
        const std::vector<glm::vec2> moved{{3, 2}, {13, 2}, {13, 6}, {7, 6}, {7, 12}, {3, 12}};
        QVERIFY(doc.scene().groups[0].points == moved);
        QCOMPARE(doc.scene().groups[0].min, glm::vec2(0.0f));
        QCOMPARE(doc.scene().groups[0].center, glm::vec2(0.0f));
        stack->undo();
        QVERIFY(doc.scene().groups[0] == g);
        stack->redo();
        QVERIFY(doc.scene().groups[0].points == moved);
    }

    // A source moves by its own points: a line by its ends, a rectangle by its corners
    // (the unused pair stays put); the moves of one drag merge into one step.
    void movingSourcesMovesTheirOwnPoints()
    {
        SceneDocument doc;
        sim::Source line;
        line.name = "gate";
        line.types = {{"walker", 1.0f}};
        line.from = {0, 0};
        line.to = {0, 4};
        sim::Source box = line;
        box.name = "platform";
        box.shape = sim::SourceShape::Rect;
        box.min = {5, 5};
        box.max = {8, 6};
        QUndoStack* stack = doc.undoStack();
        stack->push(new AddSceneItemCommand<sim::Source>(doc, &sim::Scene::sources, line, "Add source"));
        stack->push(new AddSceneItemCommand<sim::Source>(doc, &sim::Scene::sources, box, "Add source"));
        QVERIFY(MoveItemsCommand::movable(ItemKind::Source));
        const Selection both{{ItemKind::Source, 0}, {ItemKind::Source, 1}};
        stack->push(new MoveItemsCommand(doc, both, {1, 0}, 3));
        stack->push(new MoveItemsCommand(doc, both, {1, 2}, 3));
        QCOMPARE(stack->count(), 3);
        const sim::Scene& s = doc.scene();
        QCOMPARE(s.sources[0].from, glm::vec2(2, 2));
        QCOMPARE(s.sources[0].to, glm::vec2(2, 6));
        QCOMPARE(s.sources[0].min, glm::vec2(0.0f));
        QCOMPARE(s.sources[1].min, glm::vec2(7, 7));
        QCOMPARE(s.sources[1].max, glm::vec2(10, 8));
        QCOMPARE(s.sources[1].from, glm::vec2(0, 0));
        stack->undo();
        QVERIFY(s.sources[0] == line);
        QVERIFY(s.sources[1] == box);
        stack->redo();
        QCOMPARE(s.sources[1].max, glm::vec2(10, 8));
    }
};

THRONG_REGISTER_TEST(TestEditCommands)
#include "TestEditCommands.moc"
