// What each edit command tells the views it changed (issue 27): the items, the fields and
// whether the simulation reads them, row by row over the commands; undo and redo say the
// same as the first do. Where a row says the simulation does not read the change, the
// scene before and after the edit simulate to the same frames, bit for bit: the editor
// keeps every recorded frame on the strength of that answer, so a wrong "not read" would
// show a user a crowd that the edited scene no longer makes.
#include "TestRegistry.h"

#include "editor/SceneChange.h"
#include "editor/SceneDocument.h"
#include "editor/brain/BrainCommands.h"
#include "editor/commands/AddSceneItemCommand.h"
#include "editor/commands/ChangeAgentsCommand.h"
#include "editor/commands/ChangeValuesCommand.h"
#include "editor/commands/DeleteItemsCommand.h"
#include "editor/commands/EraseAgentsCommand.h"
#include "editor/commands/MoveItemsCommand.h"
#include "editor/commands/NameReferences.h"
#include "editor/commands/PaintAgentsCommand.h"
#include "editor/panels/PropertyChange.h"
#include "simcore/io/SceneIO.h"
#include "simcore/world/World.h"

#include <QTest>

#include <functional>
#include <string>
#include <vector>

using namespace throng;
using namespace throng::editor;

namespace {

// Walkers (with looks and tints) and runners; six placed walkers heading east, agent 6
// following agent 1; a group on path "loop" that follows agent 1 too; a spare path
// "lone"; a wall, an obstacle, a goal and the walkers' brain.
constexpr const char* kSceneYaml = R"(throng: 1
settings: {fps: 24, duration: 10, seed: 9, bounds: {min: [-30, -30], max: [30, 30]}}
brains:
  - name: go
    nodes:
      - {id: 1, type: input, label: top speed, position: [0, 0], params: {sensor: attribute, name: max_speed}}
      - {id: 2, type: input.constant, position: [0, 120], params: {value: 0.8}}
      - {id: 3, type: math.multiply, position: [200, 0]}
      - {id: 4, type: output, position: [400, 0], params: {channel: speed}}
    links: [{from: [1, 0], to: [3, 0]}, {from: [2, 0], to: [3, 1]}, {from: [3, 0], to: [4, 0]}]
agent_types:
  - {name: walker, max_speed: 1.4, max_force: 3, brain: go,
     variation: {looks: [casual, formal], tints: [[1, 0, 0], [0, 0, 1]], height_scale: [0.9, 1.1]}}
  - {name: runner, max_speed: 3, max_force: 6}
goals:
  - {name: east, position: [25, 0], radius: 1}
paths:
  - {name: loop, radius: 1, points: [[-20, -20], [20, -20], [20, -10]]}
  - {name: lone, radius: 1, points: [[-20, 20], [-10, 20]]}
walls:
  - {name: fence, points: [[0, 5], [0, 12]]}
obstacles:
  - {name: post, center: [8, -3], radius: 0.5}
groups:
  - {name: loopers, type: walker, count: 12, rect: {min: [-20, -22], max: [-14, -18]}, path: loop, leader: 1}
agents:
  - {id: 1, type: walker, position: [-10, 0, 0], goal: east}
  - {id: 2, type: walker, position: [-6, 0, 1], goal: east}
  - {id: 3, type: walker, position: [-2, 0, -1], goal: east}
  - {id: 4, type: walker, position: [2, 0, 0], goal: east}
  - {id: 5, type: walker, position: [6, 0, 2], goal: east}
  - {id: 6, type: walker, position: [10, 0, -2], goal: east, leader: 1}
)";

sim::Scene testScene()
{
    sim::LoadResult loaded = sim::parseScene(kSceneYaml, "changes.yaml", ".");
    if (!loaded.ok())
        qFatal("the test scene does not load: %s", loaded.diagnostics.front().format().c_str());
    return loaded.scene;
}

// The placed agents `indices` as they are, each changed by `edit`.
std::vector<sim::Agent> edited(const SceneDocument& doc, const std::vector<std::size_t>& indices,
                               const std::function<void(sim::Agent&)>& edit)
{
    std::vector<sim::Agent> out;
    for (std::size_t i : indices) {
        out.push_back(doc.scene().agents[i]);
        edit(out.back());
    }
    return out;
}

// A property edit as the properties panel makes it: one value of the items `indices`.
template <class T>
QUndoCommand* propertyEdit(SceneDocument& doc, ItemKind kind, const QString& key, std::vector<std::size_t> indices,
                           std::function<T&(sim::Scene&, std::size_t)> locate, T value)
{
    std::vector<typename ChangeValuesCommand<T>::Locate> locates;
    for (std::size_t i : indices)
        locates.push_back([locate, i](sim::Scene& s) -> T& { return locate(s, i); });
    std::vector<T> values(indices.size(), value);
    return new ChangeValuesCommand<T>(doc, key, std::move(locates), std::move(values), "edit",
                                      propertyChange(kind, key, indices));
}

// A rename as the properties panel makes it: the name and every reference to it.
QUndoCommand* rename(SceneDocument& doc, SceneItem item, const std::string& name)
{
    const std::vector<NameUse> uses = nameUses(doc.scene(), item.kind, nameOf(doc.scene(), item));
    std::vector<ChangeValuesCommand<std::string>::Locate> locates{nameLocate(item)};
    for (const NameUse& use : uses)
        locates.push_back(use.locate);
    std::vector<std::string> values(locates.size(), name);
    return new ChangeValuesCommand<std::string>(doc, QString(), std::move(locates), std::move(values), "rename",
                                                renameChange(item, uses));
}

SceneChange agents(std::vector<std::size_t> indices, SceneField field)
{
    return SceneChange::of(ItemKind::Agent, std::move(indices), field);
}

struct Case {
    const char* name;
    std::function<QUndoCommand*(SceneDocument&)> make;
    SceneChange expected;
    bool read;  // what expected.simulationReads must be, spelled out
};

std::vector<Case> cases()
{
    using F = SceneField;
    using K = ItemKind;
    std::vector<Case> c;
    c.push_back({"paint two agents", [](SceneDocument& d) {
        sim::Agent a = d.scene().agents[0];
        a.id = 100;
        sim::Agent b = a;
        b.id = 101;
        b.position.x += 1.0f;
        return new PaintAgentsCommand(d, {a, b}, 1);
    }, agents({6, 7}, F::Items), true});
    c.push_back({"erase agents", [](SceneDocument& d) { return new EraseAgentsCommand(d, {3, 1}, 2); },
                 SceneChange::ofAll(K::Agent, F::Items), true});
    c.push_back({"vary tint, look and height", [](SceneDocument& d) {
        return new ChangeAgentsCommand(d, {0, 2}, edited(d, {0, 2}, [](sim::Agent& a) {
            a.tint = 1;
            a.look = 1;
            a.heightScale = 1.2f;
        }), 3, "Vary");
    }, agents({0, 2}, F::Look), false});
    c.push_back({"assign a group", [](SceneDocument& d) {
        return new ChangeAgentsCommand(d, {1, 4}, edited(d, {1, 4}, [](sim::Agent& a) { a.group = "front"; }), 4, "Assign");
    }, agents({1, 4}, F::Group), false});
    c.push_back({"comb headings", [](SceneDocument& d) {
        return new ChangeAgentsCommand(d, {3}, edited(d, {3}, [](sim::Agent& a) { a.headingDeg = 90.0f; }), 5, "Comb");
    }, agents({3}, F::Heading), true});
    c.push_back({"assign a type with a look", [](SceneDocument& d) {
        return new ChangeAgentsCommand(d, {5}, edited(d, {5}, [](sim::Agent& a) {
            a.type = "runner";
            a.look = 0;
        }), 6, "Assign");
    }, agents({5}, F::Type) | agents({5}, F::Look), true});
    c.push_back({"move a wall and an agent", [](SceneDocument& d) {
        return new MoveItemsCommand(d, {{K::Wall, 0}, {K::Agent, 4}}, {1.0f, 0.0f}, 7);
    }, SceneChange::of({K::Wall, 0}, F::Position) | agents({4}, F::Position), true});
    c.push_back({"add a wall", [](SceneDocument& d) {
        return new AddSceneItemCommand<sim::Wall>(d, &sim::Scene::walls, sim::Wall{"w2", {{5, 5}, {5, 9}}}, "Add wall");
    }, SceneChange::of({K::Wall, 1}, F::Items), true});
    c.push_back({"add a goal", [](SceneDocument& d) {
        sim::Goal g;
        g.name = "west";
        g.position = {-25, 0};
        return new AddSceneItemCommand<sim::Goal>(d, &sim::Scene::goals, g, "Add goal");
    }, SceneChange::of({K::Goal, 1}, F::Items), true});
    c.push_back({"delete a path", [](SceneDocument& d) { return new DeleteItemsCommand(d, {{K::Path, 1}}); },
                 SceneChange::ofAll(K::Path, F::Items), true});
    c.push_back({"delete a leader", [](SceneDocument& d) { return new DeleteItemsCommand(d, {{K::Agent, 0}}); },
                 SceneChange::ofAll(K::Agent, F::Items) | SceneChange::of({K::Group, 0}, F::Route), true});
    c.push_back({"delete a wall and an obstacle", [](SceneDocument& d) {
        return new DeleteItemsCommand(d, {{K::Wall, 0}, {K::Obstacle, 0}});
    }, SceneChange::ofAll(K::Wall, F::Items) | SceneChange::ofAll(K::Obstacle, F::Items), true});
    c.push_back({"edit a brain's parameter", [](SceneDocument& d) {
        sim::BrainGraph after = d.scene().brains[0];
        after.nodes[1].params[0].numbers = {0.5f};
        return new EditBrainCommand(d, 0, d.scene().brains[0], after, "Edit");
    }, SceneChange::of({K::Brain, 0}, F::Brain), true});
    c.push_back({"move and relabel brain nodes", [](SceneDocument& d) {
        sim::BrainGraph after = d.scene().brains[0];
        after.nodes[0].position += glm::vec2(40.0f, 80.0f);
        after.nodes[3].position = {0.0f, 300.0f};
        after.nodes[0].label = "how fast";
        return new EditBrainCommand(d, 0, d.scene().brains[0], after, "Move");
    }, SceneChange::of({K::Brain, 0}, F::BrainLayout), false});
    c.push_back({"add a brain for runners", [](SceneDocument& d) {
        EditBrainsCommand::State before{d.scene().brains, d.scene().agentTypes, {}}, after = before;
        after.brains.push_back(d.scene().brains[0]);
        after.brains.back().name = "dash";
        after.agentTypes[1].brain = "dash";
        return new EditBrainsCommand(d, before, after, "Add brain");
    }, SceneChange::ofAll(K::Brain, F::Items) | SceneChange::ofAll(K::AgentType, F::Brain), true});
    c.push_back({"rename a wall", [](SceneDocument& d) { return rename(d, {K::Wall, 0}, "hedge"); },
                 SceneChange::of({K::Wall, 0}, F::Name), false});
    c.push_back({"rename an obstacle", [](SceneDocument& d) { return rename(d, {K::Obstacle, 0}, "bollard"); },
                 SceneChange::of({K::Obstacle, 0}, F::Name), false});
    c.push_back({"rename a path nothing follows", [](SceneDocument& d) { return rename(d, {K::Path, 1}, "spur"); },
                 SceneChange::of({K::Path, 1}, F::Name), false});
    c.push_back({"rename a path a group follows", [](SceneDocument& d) { return rename(d, {K::Path, 0}, "ring"); },
                 SceneChange::of({K::Path, 0}, F::Name) | SceneChange::of({K::Group, 0}, F::Route), true});
    // A brain may name goals in a goal node: the World looks goals up by name.
    c.push_back({"rename a goal", [](SceneDocument& d) { return rename(d, {K::Goal, 0}, "sunrise"); },
                 SceneChange::of({K::Goal, 0}, F::Name) | agents({0, 1, 2, 3, 4, 5}, F::Route), true});
    // A resumed run matches a group's members by its name.
    c.push_back({"rename a group", [](SceneDocument& d) { return rename(d, {K::Group, 0}, "rounders"); },
                 SceneChange::of({K::Group, 0}, F::Name), true});
    c.push_back({"a placed agent's tint in Properties", [](SceneDocument& d) {
        return propertyEdit<int>(d, K::Agent, "tint", {2, 3}, [](sim::Scene& s, std::size_t i) -> int& {
            return s.agents[i].tint;
        }, 0);
    }, agents({2, 3}, F::Look), false});
    c.push_back({"a type's tints in Properties", [](SceneDocument& d) {
        using Tints = std::vector<glm::vec3>;
        return propertyEdit<Tints>(d, K::AgentType, "tints/4", {0}, [](sim::Scene& s, std::size_t i) -> Tints& {
            return s.agentTypes[i].variation.tints;
        }, Tints{{0, 1, 0}});
    }, SceneChange::of({K::AgentType, 0}, F::Look), false});
    c.push_back({"a type's height range in Properties", [](SceneDocument& d) {
        return propertyEdit<float>(d, K::AgentType, "heightMax", {0}, [](sim::Scene& s, std::size_t i) -> float& {
            return s.agentTypes[i].variation.heightScale.y;
        }, 1.4f);
    }, SceneChange::of({K::AgentType, 0}, F::Look), false});
    c.push_back({"a type's character in Properties", [](SceneDocument& d) {
        return propertyEdit<std::string>(d, K::AgentType, "character", {0}, [](sim::Scene& s, std::size_t i) -> std::string& {
            return s.agentTypes[i].character;
        }, std::string("bird"));
    }, SceneChange::of({K::AgentType, 0}, F::Look), false});
    c.push_back({"a type's speed factor in Properties", [](SceneDocument& d) {
        return propertyEdit<float>(d, K::AgentType, "speedFactorMax", {0}, [](sim::Scene& s, std::size_t i) -> float& {
            return s.agentTypes[i].variation.speedFactor.y;
        }, 1.3f);
    }, SceneChange::of({K::AgentType, 0}, F::Parameters), true});
    c.push_back({"a wall's points in Properties", [](SceneDocument& d) {
        using Points = std::vector<glm::vec2>;
        return propertyEdit<Points>(d, K::Wall, "points/2", {0}, [](sim::Scene& s, std::size_t i) -> Points& {
            return s.walls[i].points;
        }, Points{{0, 5}, {0, 14}});
    }, SceneChange::of({K::Wall, 0}, F::Position), true});
    c.push_back({"the frame rate in Properties", [](SceneDocument& d) {
        return propertyEdit<float>(d, K::Settings, "fps", {0}, [](sim::Scene& s, std::size_t) -> float& {
            return s.settings.fps;
        }, 30.0f);
    }, SceneChange::of({K::Settings, 0}, F::Settings), true});
    return c;
}

// Whether the two scenes simulate to the same frames, bit for bit, for `steps` steps.
bool simulateAlike(const sim::Scene& a, const sim::Scene& b, int steps, QString& why)
{
    sim::World x(a), y(b);
    std::vector<sim::AgentFrame> fx, fy;
    for (int s = 0; s <= steps; ++s) {
        if (s > 0) {
            x.step();
            y.step();
        }
        x.snapshot(fx);
        y.snapshot(fy);
        if (fx.size() != fy.size()) {
            why = QString("step %1: %2 agents against %3").arg(s).arg(fx.size()).arg(fy.size());
            return false;
        }
        for (std::size_t i = 0; i < fx.size(); ++i) {
            const sim::AgentFrame &p = fx[i], &q = fy[i];
            if (p.position != q.position || p.headingRad != q.headingRad || p.speed != q.speed || p.phase != q.phase ||
                p.clip != q.clip || p.out != q.out || p.arrived != q.arrived) {
                why = QString("step %1, agent %2 differs").arg(s).arg(i);
                return false;
            }
        }
    }
    return true;
}

}  // namespace

class TestSceneChanges : public QObject {
    Q_OBJECT

private slots:
    void eachCommandSaysWhatItChanged_data()
    {
        QTest::addColumn<int>("row");
        const std::vector<Case> all = cases();
        for (std::size_t k = 0; k < all.size(); ++k)
            QTest::newRow(all[k].name) << int(k);
    }

    void eachCommandSaysWhatItChanged()
    {
        QFETCH(int, row);
        const Case c = cases()[std::size_t(row)];
        QCOMPARE(c.expected.simulationReads, c.read);
        SceneDocument doc;
        doc.reset(testScene());
        const sim::Scene before = doc.scene();
        std::vector<SceneChange> told;
        QObject::connect(&doc, &SceneDocument::sceneChanged, &doc, [&told](const SceneChange& change) {
            told.push_back(change);
        });
        doc.undoStack()->push(c.make(doc));
        QVERIFY2(!(doc.scene() == before), "the row's command changes nothing");
        QCOMPARE(told.size(), std::size_t(1));
        QVERIFY2(told[0] == c.expected,
                 qPrintable(QString("told %1\nexpected %2").arg(describe(told[0]), describe(c.expected))));
        const sim::Scene after = doc.scene();

        doc.undoStack()->undo();
        QVERIFY(doc.scene() == before);
        QCOMPARE(told.size(), std::size_t(2));
        QVERIFY2(told[1] == c.expected, qPrintable(QString("undo told %1").arg(describe(told[1]))));
        doc.undoStack()->redo();
        QVERIFY(doc.scene() == after);
        QCOMPARE(told.size(), std::size_t(3));
        QVERIFY2(told[2] == c.expected, qPrintable(QString("redo told %1").arg(describe(told[2]))));

        if (!c.read) {
            QString why;
            QVERIFY2(simulateAlike(before, after, 48, why),
                     qPrintable("said not read by the simulation, but the frames differ: " + why));
        }
    }

    // A stroke's dabs merge into one command: its undo names every agent of the stroke.
    void aMergedStrokeNamesAllItsAgents()
    {
        SceneDocument doc;
        doc.reset(testScene());
        std::vector<SceneChange> told;
        QObject::connect(&doc, &SceneDocument::sceneChanged, &doc, [&told](const SceneChange& change) {
            told.push_back(change);
        });
        auto vary = [&doc](std::size_t i) {
            return new ChangeAgentsCommand(doc, {i}, edited(doc, {i}, [](sim::Agent& a) { a.tint = 0; }), 11, "Vary");
        };
        doc.undoStack()->push(vary(1));
        doc.undoStack()->push(vary(4));
        doc.undoStack()->push(new ChangeAgentsCommand(doc, {2}, edited(doc, {2}, [](sim::Agent& a) {
            a.headingDeg = 45.0f;
        }), 11, "Vary"));
        QCOMPARE(doc.undoStack()->count(), 1);
        QCOMPARE(told.size(), std::size_t(3));
        QVERIFY(told[0] == agents({1}, SceneField::Look));
        doc.undoStack()->undo();
        const SceneChange whole = agents({1, 2, 4}, SceneField::Look) | agents({1, 2, 4}, SceneField::Heading);
        QVERIFY2(told.back() == whole, qPrintable(describe(told.back())));
        QVERIFY(told.back().simulationReads);
    }

    void unionsAndWholeKinds()
    {
        const SceneChange look = agents({4, 1}, SceneField::Look);
        QCOMPARE(look.items.size(), std::size_t(2));
        QCOMPARE(look.items[0].index, std::size_t(1));
        QVERIFY(!look.simulationReads);
        QVERIFY(look.touches({ItemKind::Agent, 4}));
        QVERIFY(!look.touches({ItemKind::Agent, 2}));
        QVERIFY(!look.touches(ItemKind::Wall));

        // The union reads when either part does, and names both parts' items and fields.
        SceneChange both = look | SceneChange::of({ItemKind::Wall, 2}, SceneField::Position);
        QVERIFY(both.simulationReads);
        QVERIFY(both.has(SceneField::Look) && both.has(SceneField::Position) && !both.has(SceneField::Items));
        QVERIFY(both.touches(ItemKind::Wall) && both.touches({ItemKind::Agent, 1}));
        QVERIFY(!both.touches({ItemKind::Wall, 0}));

        // Every item of a kind stands for each of them.
        both |= SceneChange::ofAll(ItemKind::Agent, SceneField::Items);
        QCOMPARE(both.items.size(), std::size_t(2));
        QVERIFY(both.touches({ItemKind::Agent, 123456}));
        QVERIFY(!(agents({1}, SceneField::Look) | agents({1}, SceneField::Group)).simulationReads);
        QVERIFY((agents({1}, SceneField::Look) | agents({1}, SceneField::Heading)).simulationReads);
    }

    void propertyKeysNameTheirField_data()
    {
        QTest::addColumn<int>("kind");
        QTest::addColumn<QString>("key");
        QTest::addColumn<int>("field");
        QTest::addColumn<bool>("read");
        using F = SceneField;
        using K = ItemKind;
        auto row = [](const char* name, K kind, const char* key, F field, bool read) {
            QTest::newRow(name) << int(kind) << QString(key) << int(field) << read;
        };
        row("agent x", K::Agent, "x", F::Position, true);
        row("agent heading", K::Agent, "heading", F::Heading, true);
        row("agent type", K::Agent, "type", F::Type, true);
        row("agent brain", K::Agent, "brain", F::Brain, true);
        row("agent leader", K::Agent, "leader", F::Route, true);
        row("agent look", K::Agent, "look", F::Look, false);
        row("agent tint", K::Agent, "tint", F::Look, false);
        row("agent height", K::Agent, "heightScale", F::Look, false);
        row("agent group", K::Agent, "group", F::Group, false);
        row("type radius", K::AgentType, "radius", F::Parameters, true);
        row("type kind", K::AgentType, "kind", F::Parameters, true);
        row("type behaviours", K::AgentType, "behaviours", F::Parameters, true);
        row("type phase offset", K::AgentType, "phaseMin", F::Parameters, true);
        row("type reaction time", K::AgentType, "reactionMax", F::Parameters, true);
        row("type looks", K::AgentType, "looks", F::Look, false);
        row("type height range", K::AgentType, "heightMin", F::Look, false);
        row("group count", K::Group, "count", F::Parameters, true);
        row("group exits", K::Group, "exits", F::Route, true);
        row("group corner", K::Group, "minX", F::Position, true);
        row("group corners", K::Group, "points/7", F::Position, true);
        row("group shape", K::Group, "shape", F::Shape, true);
        row("path radius", K::Path, "radius", F::Shape, true);
        row("path planned", K::Path, "planned", F::Shape, true);
        row("obstacle width", K::Obstacle, "width", F::Shape, true);
        row("goal exit", K::Goal, "exit", F::Parameters, true);
        row("light green", K::TrafficLight, "green", F::Parameters, true);
        row("light stop lines", K::TrafficLight, "stopLines/2", F::Route, true);
        row("lane speed limit", K::Lane, "speedLimit", F::Parameters, true);
        row("lane width", K::Lane, "width", F::Shape, true);
        row("crosswalk end", K::Crosswalk, "toZ", F::Position, true);
        row("vehicle lane", K::Vehicle, "lane", F::Route, true);
        row("vehicle start", K::Vehicle, "at", F::Position, true);
        row("vehicle speed", K::Vehicle, "speed", F::Parameters, true);
        row("hero type", K::Hero, "type", F::Type, true);
        row("seed", K::Settings, "seed", F::Settings, true);
        row("a key nobody knows", K::AgentType, "somethingNew", F::Parameters, true);
    }

    void propertyKeysNameTheirField()
    {
        QFETCH(int, kind);
        QFETCH(QString, key);
        QFETCH(int, field);
        QFETCH(bool, read);
        const SceneChange change = propertyChange(ItemKind(kind), key, {0, 3});
        QCOMPARE(int(propertyField(ItemKind(kind), key)), field);
        QCOMPARE(change.fields, std::uint32_t(field));
        QCOMPARE(change.simulationReads, read);
        QVERIFY(change.touches({ItemKind(kind), 3}));
    }
};

THRONG_REGISTER_TEST(TestSceneChanges)
#include "TestSceneChanges.moc"
