// The layout layer (issue 29) on a real recording: two groups crossing a square (twelve
// walkers heading east, eight heading north, one placed agent in a group of its own). Each
// operation measured where a user would look: the trajectories CSV. Moved agents are
// where the layer puts them and the others byte for byte where they were; a retimed
// agent's first step comes later by the offset; deleted agents leave the CSV and are
// invisible in USD and scaled away in glTF; a turn
// keeps distances to its pivot; a mirror reflects the walk; Expand spreads the group about
// its centre. Selections by id, group, type and lasso; operations that select nobody are
// named; the check after the edits finds the overlaps and wall crossings they make; the
// file round trip keeps the layer; bad entries fail with file:line messages;
// a re-simulation with another seed keeps the layer by agent id.
#include "TestRegistry.h"

#include "GltfReadBack.h"
#include "export/GltfExporter.h"
#include "export/TrajectoryCsv.h"
#include "export/UsdExporter.h"
#include "simcore/io/SceneIO.h"
#include "simcore/layout/LayoutApply.h"
#include "simcore/layout/LayoutCheck.h"
#include "simcore/world/World.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <glm/geometric.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

using namespace throng;

namespace {

const char* kSquare = R"(throng: 1
settings: {fps: 10, duration: 8, seed: 4, bounds: {min: [-30, -30], max: [30, 30]}}
agent_types:
  - {name: walker, radius: 0.3}
  - {name: runner, radius: 0.3, max_speed: 3}
goals:
  - {name: east, position: [20, 0], radius: 2}
  - {name: north, position: [0, -20], radius: 2}
groups:
  - {name: eastbound, type: walker, count: 12, rect: {min: [-15, -4], max: [-10, 4]}, goal: east}
  - {name: northbound, type: runner, count: 8, rect: {min: [-4, 10], max: [4, 14]}, goal: north}
agents:
  - {id: 1, type: walker, position: [-12, -10], goal: east, group: loner}
)";

struct Shot {
    sim::Scene scene;
    sim::FrameCache cache;
};

Shot record(const std::string& yaml, std::uint64_t seed = 4)
{
    Shot s;
    const sim::LoadResult loaded = sim::parseScene(yaml, "square.yaml", "");
    if (!loaded.ok())
        qFatal("%s", loaded.diagnostics[0].format().c_str());
    s.scene = loaded.scene;
    s.scene.settings.seed = seed;
    sim::World world(s.scene);
    world.startRecording(s.cache);
    std::vector<sim::AgentFrame> frame;
    for (int f = 1; f < 80; ++f) {
        world.step();
        world.snapshot(frame);
        s.cache.append(frame);
    }
    return s;
}

std::size_t indexOf(const sim::FrameCache& cache, std::uint32_t id)
{
    for (std::size_t i = 0; i < cache.agentCount(); ++i)
        if (cache.agents()[i].id == id)
            return i;
    qFatal("no agent %u", id);
}

glm::vec2 xz(const sim::AgentFrame& a) { return {a.position.x, a.position.z}; }

bool sameFrame(const sim::AgentFrame& a, const sim::AgentFrame& b)
{
    return a.position == b.position && a.headingRad == b.headingRad && a.speed == b.speed && a.phase == b.phase &&
           a.clip == b.clip && a.out == b.out && a.present == b.present && a.arrived == b.arrived;
}

sim::LayoutOp op(sim::LayoutKind kind, std::vector<std::uint32_t> ids)
{
    sim::LayoutOp o;
    o.kind = kind;
    o.agents.ids = std::move(ids);
    return o;
}

// CSV rows by agent id: frame -> the row's text.
std::map<std::uint32_t, std::map<int, std::string>> csvRows(const std::string& path)
{
    std::map<std::uint32_t, std::map<int, std::string>> rows;
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    while (std::getline(in, line)) {
        std::istringstream s(line);
        std::string frame, agent;
        std::getline(s, frame, ',');
        std::getline(s, agent, ',');
        rows[std::uint32_t(std::stoul(agent))][std::stoi(frame)] = line;
    }
    return rows;
}

}  // namespace

class TestLayoutLayer : public QObject {
    Q_OBJECT
private slots:
    // Translate group eastbound by (3, -2): every member's CSV row moves by exactly that,
    // on every frame; every other agent's rows are the recording's, byte for byte.
    void translatedAgentsMoveAndTheOthersStayByteForByte()
    {
        Shot s = record(kSquare);
        sim::LayoutOp move;
        move.kind = sim::LayoutKind::Translate;
        move.agents.groups = {"eastbound"};
        move.offset = {3.0f, -2.0f};
        s.scene.layout.ops = {move};
        std::vector<std::string> messages;
        const sim::FrameCache laid = sim::applyLayout(s.scene, s.cache, &messages);
        QVERIFY2(messages.empty(), messages.empty() ? "" : messages[0].c_str());

        QTemporaryDir dir;
        const std::string before = dir.filePath("before.csv").toStdString();
        const std::string after = dir.filePath("after.csv").toStdString();
        QVERIFY(exporting::writeTrajectoryCsv(s.cache, before).ok());
        QVERIFY(exporting::writeTrajectoryCsv(laid, after).ok());
        const auto rowsBefore = csvRows(before), rowsAfter = csvRows(after);
        const std::uint32_t first = sim::firstSpawnedId(s.scene);  // eastbound: the first 12 spawned ids
        int moved = 0, kept = 0;
        for (const auto& [id, frames] : rowsBefore) {
            const bool member = id >= first && id < first + 12;
            const std::size_t i = indexOf(s.cache, id);
            for (const auto& [f, text] : frames) {
                if (!member) {
                    QCOMPARE(rowsAfter.at(id).at(f), text);
                    ++kept;
                    continue;
                }
                const glm::vec2 d = xz(laid.at(std::size_t(f), i)) - xz(s.cache.at(std::size_t(f), i));
                QVERIFY2(std::abs(d.x - 3.0f) < 1e-4f && std::abs(d.y + 2.0f) < 1e-4f,
                         qPrintable(QString("agent %1 frame %2 moved by (%3, %4)").arg(id).arg(f).arg(d.x).arg(d.y)));
                QCOMPARE(laid.at(std::size_t(f), i).headingRad, s.cache.at(std::size_t(f), i).headingRad);
                ++moved;
            }
        }
        QCOMPARE(moved, 12 * 80);
        QCOMPARE(kept, 9 * 80);
    }

    // Rotate the runners by 90 degrees about a pivot: each keeps its distance to the pivot,
    // turns by exactly the angle about it, and faces 90 degrees further round.
    void rotationKeepsDistancesAndTurnsHeadings()
    {
        Shot s = record(kSquare);
        sim::LayoutOp turn;
        turn.kind = sim::LayoutKind::Rotate;
        turn.agents.types = {"runner"};
        turn.angleDeg = 90.0f;
        turn.pivot = glm::vec2(1.0f, 2.0f);
        s.scene.layout.ops = {turn};
        const sim::FrameCache laid = sim::applyLayout(s.scene, s.cache);
        int checked = 0;
        for (std::size_t i = 0; i < s.cache.agentCount(); ++i) {
            if (s.cache.agents()[i].typeIndex != 1)
                continue;
            for (std::size_t f = 0; f < s.cache.frameCount(); ++f) {
                const glm::vec2 before = xz(s.cache.at(f, i)) - glm::vec2(1, 2);
                const glm::vec2 after = xz(laid.at(f, i)) - glm::vec2(1, 2);
                QVERIFY(std::abs(glm::length(before) - glm::length(after)) < 1e-4f);
                // Counter-clockwise seen from above (+y up): +x turns to -z, as headings do.
                QVERIFY2(glm::length(after - glm::vec2(before.y, -before.x)) < 1e-4f, qPrintable(QString::number(f)));
                const float dh = laid.at(f, i).headingRad - s.cache.at(f, i).headingRad;
                QVERIFY(std::abs(dh - 1.5707964f) < 1e-5f);
                ++checked;
            }
        }
        QCOMPARE(checked, 8 * 80);
    }

    // Retime the loner 15 frames later: its first step comes 15 frames later, it stands in
    // its first pose until then, and its walk is the recorded one shifted.
    void aRetimedAgentStartsLaterByTheOffset()
    {
        Shot s = record(kSquare);
        s.scene.layout.ops = {op(sim::LayoutKind::TimeOffset, {1})};
        s.scene.layout.ops[0].frames = 15;
        const sim::FrameCache laid = sim::applyLayout(s.scene, s.cache);
        const std::size_t i = indexOf(s.cache, 1);
        auto firstMove = [&](const sim::FrameCache& c) {
            for (std::size_t f = 1; f < c.frameCount(); ++f)
                if (glm::length(xz(c.at(f, i)) - xz(c.at(0, i))) > 0.01f)
                    return int(f);
            return -1;
        };
        const int recorded = firstMove(s.cache), retimed = firstMove(laid);
        QVERIFY(recorded > 0);
        QCOMPARE(retimed, recorded + 15);
        for (std::size_t f = 0; f < 15; ++f) {
            QCOMPARE(xz(laid.at(f, i)), xz(s.cache.at(0, i)));
            QCOMPARE(laid.at(f, i).speed, 0.0f);
        }
        for (std::size_t f = 15; f < laid.frameCount(); ++f)
            QVERIFY(sameFrame(laid.at(f, i), s.cache.at(f - 15, i)));
        // Without hold_first it is not there at all until its new start.
        s.scene.layout.ops[0].holdFirst = false;
        const sim::FrameCache absent = sim::applyLayout(s.scene, s.cache);
        QVERIFY(!absent.at(14, i).present && absent.at(15, i).present);
        // Earlier: frame f shows frame f + 10; past the recording's end it stands still.
        s.scene.layout.ops[0].frames = -10;
        const sim::FrameCache early = sim::applyLayout(s.scene, s.cache);
        QVERIFY(sameFrame(early.at(0, i), s.cache.at(10, i)));
        QCOMPARE(xz(early.at(79, i)), xz(s.cache.at(79, i)));
        QCOMPARE(early.at(79, i).speed, 0.0f);
    }

    // Delete one walker from frame 30 on and another entirely: the CSV has no rows of the
    // first from frame 30, none of the second, and all of everyone else's.
    void deletedAgentsLeaveTheCsv()
    {
        Shot s = record(kSquare);
        const std::uint32_t first = sim::firstSpawnedId(s.scene);
        s.scene.layout.ops = {op(sim::LayoutKind::Delete, {first}), op(sim::LayoutKind::Delete, {first + 1})};
        s.scene.layout.ops[0].firstFrame = 30;
        const sim::FrameCache laid = sim::applyLayout(s.scene, s.cache);
        QTemporaryDir dir;
        const std::string path = dir.filePath("laid.csv").toStdString();
        QVERIFY(exporting::writeTrajectoryCsv(laid, path).ok());
        const auto rows = csvRows(path);
        QCOMPARE(int(rows.at(first).size()), 30);
        QCOMPARE(rows.at(first).rbegin()->first, 29);
        QVERIFY(!rows.count(first + 1));
        QCOMPARE(int(rows.size()), 20);
        // In a skinned export they are hidden from those frames: USD's visibility says so.
        exporting::UsdOptions usd;
        usd.path = dir.filePath("laid.usda").toStdString();
        usd.lod = exporting::Lod::Far;
        usd.includeSet = false;
        QVERIFY(exporting::exportUsd(s.scene, laid, usd).ok());
        QFile file(QString::fromStdString(usd.path));
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(file.readAll());
        auto visibility = [&](std::uint32_t id) {
            const qsizetype at = text.indexOf(QString("def SkelRoot \"agent_%1_walker\"").arg(id));
            const qsizetype samples = text.indexOf("token visibility.timeSamples = {", at);
            return text.mid(samples, text.indexOf('}', samples) - samples).simplified();
        };
        QCOMPARE(visibility(first), QString("token visibility.timeSamples = { 0: \"inherited\", 30: \"invisible\","));
        QCOMPARE(visibility(first + 1), QString("token visibility.timeSamples = { 0: \"invisible\","));
        // In glTF, read back as an importer would: scaled to nothing from those frames.
        exporting::GltfOptions gltf;
        gltf.path = dir.filePath("laid.glb").toStdString();
        gltf.lod = exporting::Lod::Far;
        gltf.includeSet = false;
        QVERIFY(exporting::exportGltf(s.scene, laid, gltf).ok());
        tinygltf::Model model;
        std::string error;
        QVERIFY2(test::loadGltf(gltf.path, model, error), error.c_str());
        // The scale a STEP channel holds at the frame (its last key at or before it); -1
        // without a channel.
        auto scaleAt = [&](std::uint32_t id, int frame) {
            const int node = test::nodeNamed(model, "agent_" + std::to_string(id) + "_walker");
            const tinygltf::AnimationSampler* sampler = test::samplerFor(model, node, "scale");
            if (!sampler)
                return -1.0f;
            if (sampler->interpolation != "STEP")
                qFatal("a hiding scale is keyed STEP, not %s", sampler->interpolation.c_str());
            const std::vector<float> times = test::accessorFloats(model, sampler->input);
            const std::vector<float> values = test::accessorFloats(model, sampler->output);
            float value = values[0];
            for (std::size_t k = 0; k < times.size(); ++k)
                if (times[k] <= float(frame) / 10.0f + 1e-4f)
                    value = values[3 * k];
            return value;
        };
        QVERIFY(scaleAt(first, 29) > 0.5f);
        QCOMPARE(scaleAt(first, 30), 0.0f);
        QCOMPARE(scaleAt(first, 79), 0.0f);
        QCOMPARE(scaleAt(first + 1, 0), 0.0f);
        QCOMPARE(scaleAt(first + 1, 79), 0.0f);
        QVERIFY(scaleAt(first + 2, 0) > 0.5f || scaleAt(first + 2, 0) == -1.0f);  // untouched: no channel or shown
    }

    // Mirror the eastbound group across the line x = 0: they walk west, at -x of where they
    // were, facing the other way.
    void aMirrorReflectsTheWalk()
    {
        Shot s = record(kSquare);
        sim::LayoutOp mirror;
        mirror.kind = sim::LayoutKind::Mirror;
        mirror.agents.groups = {"eastbound"};
        mirror.axis[0] = {0.0f, -5.0f};
        mirror.axis[1] = {0.0f, 5.0f};
        s.scene.layout.ops = {mirror};
        const sim::FrameCache laid = sim::applyLayout(s.scene, s.cache);
        const std::size_t i = indexOf(s.cache, sim::firstSpawnedId(s.scene));
        for (std::size_t f = 0; f < laid.frameCount(); f += 7) {
            QVERIFY(std::abs(laid.at(f, i).position.x + s.cache.at(f, i).position.x) < 1e-4f);
            QCOMPARE(laid.at(f, i).position.z, s.cache.at(f, i).position.z);
            const float h0 = s.cache.at(f, i).headingRad, h1 = laid.at(f, i).headingRad;
            QVERIFY(std::abs(std::cos(h1) + std::cos(h0)) < 1e-4f && std::abs(std::sin(h1) - std::sin(h0)) < 1e-4f);
        }
        QVERIFY(laid.at(79, i).position.x < laid.at(0, i).position.x - 5.0f);  // it walks west now
    }

    // Expand the runners by 2: on every frame each is twice as far from the group's centre.
    void expandSpreadsTheGroupAboutItsCentre()
    {
        Shot s = record(kSquare);
        sim::LayoutOp expand;
        expand.kind = sim::LayoutKind::Expand;
        expand.agents.groups = {"northbound"};
        expand.factor = 2.0f;
        s.scene.layout.ops = {expand};
        const sim::FrameCache laid = sim::applyLayout(s.scene, s.cache);
        std::vector<std::size_t> runners;
        for (std::size_t i = 0; i < s.cache.agentCount(); ++i)
            if (s.cache.agents()[i].typeIndex == 1)
                runners.push_back(i);
        QCOMPARE(runners.size(), std::size_t(8));
        for (std::size_t f = 0; f < laid.frameCount(); ++f) {
            glm::vec2 centre(0.0f);
            for (const std::size_t i : runners)
                centre += xz(s.cache.at(f, i)) / 8.0f;
            for (const std::size_t i : runners) {
                const glm::vec2 expected = centre + 2.0f * (xz(s.cache.at(f, i)) - centre);
                QVERIFY2(glm::length(xz(laid.at(f, i)) - expected) < 1e-3f, qPrintable(QString::number(f)));
            }
        }
    }

    // A lasso on frame 0 round the loner's start selects it alone; ids the recording lacks
    // and names nothing has are reported; a disabled operation changes nothing; operations
    // apply in order (translate, then rotate about the origin, is not rotate then translate).
    void selectionsMessagesAndOrder()
    {
        Shot s = record(kSquare);
        sim::LayoutOp lasso;
        lasso.kind = sim::LayoutKind::Translate;
        lasso.agents.lasso = {{-13, -11}, {-11, -11}, {-11, -9}, {-13, -9}};
        lasso.offset = {0.0f, 5.0f};
        sim::LayoutOp missing = op(sim::LayoutKind::Delete, {999, 1000});
        missing.name = "gone";
        sim::LayoutOp unknownGroup;
        unknownGroup.kind = sim::LayoutKind::Delete;
        unknownGroup.agents.groups = {"nobody"};
        s.scene.layout.ops = {lasso, missing, unknownGroup};
        const sim::LayoutSelection selection = sim::selectLayoutAgents(s.scene, s.scene.layout, s.cache);
        QCOMPARE(selection.agents[0], std::vector<std::size_t>{indexOf(s.cache, 1)});
        QVERIFY(selection.agents[1].empty() && selection.agents[2].empty());
        QString all;
        for (const std::string& m : selection.messages)
            all += QString::fromStdString(m) + "\n";
        QVERIFY2(all.contains("layout operation 2 (delete 'gone'): 2 agents are not in the recording (id 999, 1000)"),
                 qPrintable(all));
        QVERIFY2(all.contains("layout operation 3 (delete): no group named 'nobody'"), qPrintable(all));
        QVERIFY2(all.contains("layout operation 2 (delete 'gone') selects no agent"), qPrintable(all));

        s.scene.layout.ops = {lasso};
        s.scene.layout.ops[0].enabled = false;
        QCOMPARE(sim::applyLayout(s.scene, s.cache).hash(), s.cache.hash());

        sim::LayoutOp shift = op(sim::LayoutKind::Translate, {1});
        shift.offset = {10.0f, 0.0f};
        sim::LayoutOp turn = op(sim::LayoutKind::Rotate, {1});
        turn.angleDeg = 90.0f;
        turn.pivot = glm::vec2(0.0f);
        s.scene.layout.ops = {shift, turn};
        const glm::vec2 p = xz(s.cache.at(0, indexOf(s.cache, 1)));
        const glm::vec2 q = xz(sim::applyLayout(s.scene, s.cache).at(0, indexOf(s.cache, 1)));
        QVERIFY(glm::length(q - glm::vec2(p.y, -(p.x + 10.0f))) < 1e-4f);
    }

    // The scene file keeps the layer; a re-simulation with another seed applies it to the
    // same agents by id.
    void theFileKeepsTheLayerAndAReRunReappliesIt()
    {
        const std::string yaml = std::string(kSquare) + R"(layout:
  - {name: nudge, op: translate, agents: {ids: [1], groups: [northbound]}, offset: [1.5, 0], frames: [10, 40]}
  - {op: rotate, agents: {types: [runner]}, angle: 30}
  - {op: time_offset, agents: {lasso: [[-16, -5], [-9, -5], [-9, 5], [-16, 5]], lasso_frame: 0}, later: 12,
     hold_first: false}
  - {op: mirror, enabled: false, agents: {ids: [1]}, axis: [[0, 0], [1, 1]]}
  - {op: delete, agents: {ids: [1]}, frames: [60]}
  - {op: expand, agents: {groups: [eastbound]}, factor: 1.25}
)";
        const sim::LoadResult loaded = sim::parseScene(yaml, "square.yaml", "");
        QVERIFY2(loaded.ok() && loaded.diagnostics.empty(),
                 loaded.diagnostics.empty() ? "" : loaded.diagnostics[0].format().c_str());
        const sim::LayoutLayer& layer = loaded.scene.layout;
        QCOMPARE(layer.ops.size(), std::size_t(6));
        QCOMPARE(layer.ops[0].lastFrame, std::size_t(40));
        QVERIFY(!layer.ops[1].pivot);
        QCOMPARE(layer.ops[2].frames, 12);
        QVERIFY(!layer.ops[2].holdFirst && !layer.ops[3].enabled);
        QCOMPARE(layer.ops[4].firstFrame, std::size_t(60));
        QCOMPARE(layer.ops[4].lastFrame, sim::kLastFrame);
        // Written and read again: the same scene.
        const std::string written = sim::sceneToYaml(loaded.scene);
        const sim::LoadResult again = sim::parseScene(written, "square.yaml", "");
        QVERIFY2(again.ok(), again.diagnostics.empty() ? "" : again.diagnostics[0].format().c_str());
        QVERIFY(again.scene.layout == layer);
        // Another seed, another crowd: the layer selects the same agents by id.
        Shot a = record(yaml, 4), b = record(yaml, 99);
        QVERIFY(a.cache.hash() != b.cache.hash());
        const sim::LayoutSelection sa = sim::selectLayoutAgents(a.scene, layer, a.cache);
        const sim::LayoutSelection sb = sim::selectLayoutAgents(b.scene, layer, b.cache);
        for (std::size_t k = 0; k < 2; ++k) {
            QCOMPARE(sa.agents[k].size(), sb.agents[k].size());
            for (std::size_t j = 0; j < sa.agents[k].size(); ++j)
                QCOMPARE(a.cache.agents()[sa.agents[k][j]].id, b.cache.agents()[sb.agents[k][j]].id);
        }
        const sim::FrameCache laid = sim::applyLayout(b.scene, b.cache);
        QVERIFY(!laid.at(60, indexOf(b.cache, 1)).present && laid.at(59, indexOf(b.cache, 1)).present);
        // The viewport's frame-at-a-time evaluation gives every frame the exports write.
        const sim::LayoutEvaluator evaluator(b.scene, b.cache);
        std::vector<sim::AgentFrame> one;
        for (std::size_t f = 0; f < laid.frameCount(); ++f) {
            evaluator.frame(f, one);
            for (std::size_t i = 0; i < one.size(); ++i)
                QVERIFY2(sameFrame(one[i], laid.at(f, i)), qPrintable(QString("frame %1 agent %2").arg(f).arg(i)));
        }
    }

    // The check after layout edits: an agent moved onto another's path overlaps it on the
    // frames an independent recount from the frames finds; one moved across a wall steps
    // through it on the frame the recount finds; what the recording already had, and
    // agents nobody edited, are not reported.
    void theCheckFindsWhatTheEditsBroke()
    {
        const std::string yaml = std::string(kSquare) + "walls:\n  - {name: fence, points: [[0, -8], [0, -12]]}\n";
        Shot s = record(yaml);
        const std::size_t loner = indexOf(s.cache, 1);
        QCOMPARE(sim::checkLayout(s.scene, s.cache, s.cache).overlaps.size(), std::size_t(0));
        // The loner walks east along z = -10 from x = -12 and crosses x = 0 (the fence's line)
        // only if moved: put it 0.2 m beside the first eastbound walker's path instead.
        const std::size_t other = indexOf(s.cache, sim::firstSpawnedId(s.scene));
        sim::LayoutOp onto = op(sim::LayoutKind::Translate, {1});
        onto.offset = xz(s.cache.at(0, other)) - xz(s.cache.at(0, loner)) + glm::vec2(0.0f, 0.2f);
        s.scene.layout.ops = {onto};
        const sim::FrameCache laid = sim::applyLayout(s.scene, s.cache);
        const sim::LayoutCheck check = sim::checkLayout(s.scene, s.cache, laid);
        // The recount: frames where the loner's body (0.3 m) overlaps another's by > 5 cm.
        std::size_t expected = 0;
        for (std::size_t f = 0; f < laid.frameCount(); ++f)
            for (std::size_t j = 0; j < laid.agentCount(); ++j) {
                if (j == loner || !laid.at(f, j).present)
                    continue;
                const float r = s.scene.agentTypes[laid.agents()[j].typeIndex].radiusM;
                const float now = glm::length(xz(laid.at(f, loner)) - xz(laid.at(f, j)));
                const float then = glm::length(xz(s.cache.at(f, loner)) - xz(s.cache.at(f, j)));
                if (now < 0.3f + r - 0.05f && !(then < 0.3f + r - 0.05f))
                    ++expected;
            }
        QVERIFY(expected > 5);
        QCOMPARE(check.overlaps.size(), expected);
        for (const sim::LayoutClash& c : check.overlaps)
            QCOMPARE(c.agent, sim::AgentId(1));
        QVERIFY2(sim::describe(check).find("(first: frame 0, agent 1 and agent ") != std::string::npos,
                 sim::describe(check).c_str());
        // As the editor lists them: runs of consecutive frames per pair, which together
        // hold every overlap once, never touch another run of their pair, and carry the
        // deepest overlap of their frames.
        const std::vector<sim::LayoutClashSpan> spans = sim::clashSpans(check);
        std::size_t covered = 0;
        for (const sim::LayoutClashSpan& span : spans) {
            QCOMPARE(span.agent, sim::AgentId(1));
            QVERIFY(span.first <= span.last);
            covered += span.last - span.first + 1;
            float deepest = 0.0f;
            std::size_t inRun = 0;
            for (const sim::LayoutClash& c : check.overlaps)
                if (c.other == span.other && c.frame >= span.first && c.frame <= span.last) {
                    deepest = std::max(deepest, c.depthM);
                    ++inRun;
                }
            QCOMPARE(inRun, span.last - span.first + 1);  // no frame of the run lacks the overlap
            QCOMPARE(span.deepestM, deepest);
            for (const sim::LayoutClashSpan& next : spans)
                if (&next != &span && next.other == span.other)
                    QVERIFY(next.first > span.last + 1 || next.last + 1 < span.first);
        }
        QCOMPARE(covered, check.overlaps.size());
        QCOMPARE(spans.front().first, std::size_t(0));

        // An edit that moves nobody reports nothing.
        sim::LayoutOp west = op(sim::LayoutKind::Translate, {1});
        west.offset = {0.0f, 0.0f};
        s.scene.layout.ops = {west};
        QCOMPARE(sim::checkLayout(s.scene, s.cache, sim::applyLayout(s.scene, s.cache)).wallCrossings.size(),
                 std::size_t(0));  // unedited: nothing
        int recordedCrossing = -1;
        for (std::size_t f = 1; f < s.cache.frameCount() && recordedCrossing < 0; ++f)
            if (s.cache.at(f - 1, loner).position.x < 0.0f && s.cache.at(f, loner).position.x >= 0.0f)
                recordedCrossing = int(f);
        QVERIFY2(recordedCrossing < 0, "the loner reaches the fence without an edit");
        // Moved west so that it stands at x = 0 on frame 40: it walks through the fence then.
        west.offset = {-s.cache.at(40, loner).position.x, 0.0f};
        s.scene.layout.ops = {west};
        const sim::FrameCache moved = sim::applyLayout(s.scene, s.cache);
        int crossing = -1;
        for (std::size_t f = 1; f < moved.frameCount() && crossing < 0; ++f) {
            const float z = moved.at(f, loner).position.z;
            if (moved.at(f - 1, loner).position.x < 0.0f && moved.at(f, loner).position.x >= 0.0f && z < -8 &&
                z > -12)
                crossing = int(f);
        }
        QVERIFY(crossing > 0);
        const sim::LayoutCheck walls = sim::checkLayout(s.scene, s.cache, moved);
        QCOMPARE(walls.wallCrossings.size(), std::size_t(1));
        QCOMPARE(walls.wallCrossings[0].frame, std::size_t(crossing));
        QCOMPARE(walls.wallCrossings[0].wall, std::string("fence"));
        const std::vector<sim::LayoutClashSpan> wallSpans = sim::clashSpans(walls);
        QCOMPARE(wallSpans.size(), std::size_t(1));
        QCOMPARE(wallSpans[0].first, std::size_t(crossing));
        QCOMPARE(wallSpans[0].last, std::size_t(crossing));
        QCOMPARE(wallSpans[0].other, sim::AgentId(0));
        QCOMPARE(wallSpans[0].wall, std::string("fence"));
    }

    // Duplicate, swap and replace clip, as a user checks them in the exports: a copy walks
    // beside its source, 2 m north, with an id of its own that later operations select (a
    // translate moves the copy alone) and a look of its own; a swapped agent wears the look,
    // tint and type asked for in USD; a replaced clip plays on exactly its frames in the CSV.
    // The frame-at-a-time evaluation agrees on every frame; the check counts a copy left on
    // its source; the file keeps all three.
    void duplicateSwapAndReplaceClipReachTheExports()
    {
        const std::string yaml = std::string(kSquare) + R"(  - {id: 2, type: walker, position: [-12, 10], goal: east}
  - {id: 3, type: walker, position: [-12, 16], goal: east}
layout:
  - {op: swap, agents: {ids: [1]}, look: 1, tint: none}
  - {op: swap, agents: {ids: [2]}, type: runner}
  - {op: duplicate, agents: {ids: [3]}, offset: [0, 2]}
  - {op: translate, agents: {ids: [1000000000]}, offset: [1, 0]}
  - {op: replace_clip, agents: {ids: [1]}, clip: wave, frames: [10, 20]}
)";
        const std::string withLooks = [&] {
            std::string text = yaml;
            const std::string walker = "  - {name: walker, radius: 0.3}";
            text.replace(text.find(walker), walker.size(),
                         "  - {name: walker, radius: 0.3, variation: {looks: [man, woman], tints: [[0.9, 0.1, 0.1], "
                         "[0.1, 0.1, 0.9]]}}");
            return text;
        }();
        Shot s = record(withLooks);
        QVERIFY2(s.scene.layout.ops.size() == 5, "the layer is read");
        std::vector<std::string> messages;
        const sim::FrameCache laid = sim::applyLayout(s.scene, s.cache, &messages);
        QVERIFY2(messages.empty(), messages.empty() ? "" : messages[0].c_str());
        const std::size_t n = s.cache.agentCount();
        QCOMPARE(laid.agentCount(), n + 1);
        QCOMPARE(laid.frameCount(), s.cache.frameCount());
        const sim::AgentInfo copy = laid.agents()[n];
        QCOMPARE(copy.id, sim::kFirstCopyId);
        QCOMPARE(copy.typeIndex, s.cache.agents()[indexOf(s.cache, 3)].typeIndex);

        // The CSV: the copy 1 m east and 2 m north of agent 3 on every frame, agent 3 as
        // recorded; agent 1 waving on frames 10 to 20 and as recorded elsewhere.
        QTemporaryDir dir;
        const std::string before = dir.filePath("before.csv").toStdString();
        const std::string after = dir.filePath("after.csv").toStdString();
        QVERIFY(exporting::writeTrajectoryCsv(s.cache, before).ok());
        QVERIFY(exporting::writeTrajectoryCsv(laid, after).ok());
        const auto rowsBefore = csvRows(before), rowsAfter = csvRows(after);
        QCOMPARE(rowsAfter.at(3), rowsBefore.at(3));
        QCOMPARE(rowsAfter.at(sim::kFirstCopyId).size(), rowsBefore.at(3).size());
        const std::size_t three = indexOf(s.cache, 3), one = indexOf(s.cache, 1);
        for (std::size_t f = 0; f < laid.frameCount(); ++f) {
            const glm::vec2 d = xz(laid.at(f, n)) - xz(s.cache.at(f, three));
            QVERIFY2(glm::length(d - glm::vec2(1.0f, 2.0f)) < 1e-4f, qPrintable(QString("frame %1").arg(f)));
            QCOMPARE(laid.at(f, n).headingRad, s.cache.at(f, three).headingRad);
            const sim::Clip expected = f >= 10 && f <= 20 ? sim::Clip::Wave : s.cache.at(f, one).clip;
            QCOMPARE(laid.at(f, one).clip, expected);
            QCOMPARE(xz(laid.at(f, one)), xz(s.cache.at(f, one)));
        }
        QVERIFY(rowsAfter.at(1).at(15).find(",wave,") != std::string::npos);
        QVERIFY(rowsAfter.at(1).at(9).find(",wave,") == std::string::npos);

        // USD: agent 1 wears look 1 (the woman) untinted; agent 2 is a runner; the copy is an
        // agent of its own, with a look drawn for its own id.
        exporting::UsdOptions usd;
        usd.path = dir.filePath("laid.usda").toStdString();
        usd.lod = exporting::Lod::Far;
        usd.includeSet = false;
        QVERIFY(exporting::exportUsd(s.scene, laid, usd).ok());
        QFile file(QString::fromStdString(usd.path));
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(file.readAll());
        auto customData = [&](const QString& prim) {
            const qsizetype at = text.indexOf(QString("def SkelRoot \"%1\"").arg(prim));
            if (at < 0)
                return QString();
            const qsizetype data = text.indexOf("customData = {", at);
            return text.mid(data, text.indexOf('}', data) - data).simplified();
        };
        QVERIFY2(customData("agent_1_walker").contains("string character = \"woman\"") &&
                     customData("agent_1_walker").contains("int tint = -1"),
                 qPrintable(customData("agent_1_walker")));
        QVERIFY2(!customData("agent_2_runner").isEmpty(), "agent 2 is exported as a runner");
        QVERIFY(customData("agent_2_walker").isEmpty());
        QVERIFY2(!customData("agent_1000000000_walker").isEmpty(), "the copy is exported");

        // The viewport's frame-at-a-time evaluation gives every frame the exports write.
        const sim::LayoutEvaluator evaluator(s.scene, s.cache);
        QCOMPARE(evaluator.agents().size(), n + 1);
        std::vector<sim::AgentFrame> frame;
        for (std::size_t f = 0; f < laid.frameCount(); ++f) {
            evaluator.frame(f, frame);
            QCOMPARE(frame.size(), n + 1);
            for (std::size_t i = 0; i < frame.size(); ++i)
                QVERIFY2(sameFrame(frame[i], laid.at(f, i)), qPrintable(QString("frame %1 agent %2").arg(f).arg(i)));
        }

        // A copy left on its source overlaps it on every frame it is in the shot.
        s.scene.layout.ops = {op(sim::LayoutKind::Duplicate, {3})};
        const sim::FrameCache stacked = sim::applyLayout(s.scene, s.cache);
        std::size_t shown = 0;
        for (std::size_t f = 0; f < s.cache.frameCount(); ++f)
            shown += s.cache.at(f, three).present && !s.cache.at(f, three).out;
        const sim::LayoutCheck check = sim::checkLayout(s.scene, s.cache, stacked);
        QCOMPARE(check.overlaps.size(), shown);
        QCOMPARE(check.overlaps.front().agent, sim::kFirstCopyId);
        QCOMPARE(check.overlaps.front().other, sim::AgentId(3));

        // The file keeps the three kinds.
        const sim::LoadResult loaded = sim::parseScene(withLooks, "square.yaml", "");
        const sim::LoadResult again = sim::parseScene(sim::sceneToYaml(loaded.scene), "square.yaml", "");
        QVERIFY2(again.ok(), again.diagnostics.empty() ? "" : again.diagnostics[0].format().c_str());
        QVERIFY(again.scene.layout == loaded.scene.layout);
        QCOMPARE(again.scene.layout.ops[0].tint, -1);
        QCOMPARE(again.scene.layout.ops[0].look, 1);
        QCOMPARE(again.scene.layout.ops[1].type, std::string("runner"));
        QCOMPARE(again.scene.layout.ops[4].clip, sim::Clip::Wave);
    }

    // Resolve: the loner moved onto a walker's path, then resolved, overlaps nobody on any
    // frame; the walker and everyone the edit did not move keep their frames byte for byte;
    // the loner keeps to its moved path within a body's width and drifts off it smoothly. A
    // group squeezed to a tenth of its spread and resolved overlaps nobody either, and the
    // other group is untouched. The viewport's frame-at-a-time evaluation agrees.
    void resolveNudgesOnlyTheEditedAgentsApart()
    {
        const std::string yaml = std::string(kSquare) + "walls:\n  - {name: fence, points: [[0, -8], [0, -12]]}\n";
        Shot s = record(yaml);
        const std::size_t loner = indexOf(s.cache, 1);
        const std::size_t other = indexOf(s.cache, sim::firstSpawnedId(s.scene));
        sim::LayoutOp onto = op(sim::LayoutKind::Translate, {1});
        onto.offset = xz(s.cache.at(0, other)) - xz(s.cache.at(0, loner)) + glm::vec2(0.0f, 0.2f);
        s.scene.layout.ops = {onto};
        const sim::FrameCache moved = sim::applyLayout(s.scene, s.cache);
        QVERIFY(sim::checkLayout(s.scene, s.cache, moved).overlaps.size() > 5);
        sim::LayoutOp resolve;
        resolve.kind = sim::LayoutKind::Resolve;
        s.scene.layout.ops.push_back(resolve);
        std::vector<std::string> messages;
        const sim::FrameCache resolved = sim::applyLayout(s.scene, s.cache, &messages);
        QVERIFY2(messages.empty(), messages.empty() ? "" : messages[0].c_str());
        const sim::LayoutCheck check = sim::checkLayout(s.scene, s.cache, resolved);
        QVERIFY2(check.overlaps.empty(), sim::describe(check).c_str());
        float largestStep = 0.0f, largestNudge = 0.0f;
        std::size_t nudged = 0;
        for (std::size_t f = 0; f < resolved.frameCount(); ++f) {
            for (std::size_t i = 0; i < resolved.agentCount(); ++i)
                if (i != loner)
                    QVERIFY2(sameFrame(resolved.at(f, i), s.cache.at(f, i)), qPrintable(QString("frame %1 agent %2")
                                                                                            .arg(f).arg(i)));
            const glm::vec2 nudge = xz(resolved.at(f, loner)) - xz(moved.at(f, loner));
            largestNudge = std::max(largestNudge, glm::length(nudge));
            nudged += glm::length(nudge) > 0.0f;
            if (f > 0) {
                const glm::vec2 before = xz(resolved.at(f - 1, loner)) - xz(moved.at(f - 1, loner));
                largestStep = std::max(largestStep, glm::length(nudge - before));
            }
        }
        QVERIFY(nudged > 5);
        QVERIFY2(largestNudge <= 0.6f, qPrintable(QString::number(largestNudge)));
        QVERIFY2(largestStep <= 0.25f, qPrintable(QString::number(largestStep)));  // at 10 fps

        // A squeezed group: both bodies of a pair move, so it settles; the runners stay.
        sim::LayoutOp squeeze;
        squeeze.kind = sim::LayoutKind::Expand;
        squeeze.agents.groups = {"eastbound"};
        squeeze.factor = 0.1f;
        s.scene.layout.ops = {squeeze};
        const sim::FrameCache squeezed = sim::applyLayout(s.scene, s.cache);
        const std::size_t before = sim::checkLayout(s.scene, s.cache, squeezed).overlaps.size();
        QVERIFY(before > 100);
        s.scene.layout.ops.push_back(resolve);
        const sim::FrameCache settled = sim::applyLayout(s.scene, s.cache);
        const sim::LayoutCheck after = sim::checkLayout(s.scene, s.cache, settled);
        QVERIFY2(after.overlaps.empty(), qPrintable(QString("%1 overlaps before, then %2")
                                                         .arg(before).arg(QString::fromStdString(sim::describe(after)))));
        const std::uint32_t first = sim::firstSpawnedId(s.scene);
        for (std::size_t f = 0; f < settled.frameCount(); ++f)
            for (std::size_t i = 0; i < settled.agentCount(); ++i) {
                const std::uint32_t id = settled.agents()[i].id;
                if (id < first || id >= first + 12)
                    QVERIFY(sameFrame(settled.at(f, i), s.cache.at(f, i)));
            }
        const sim::LayoutEvaluator evaluator(s.scene, s.cache);
        std::vector<sim::AgentFrame> frame;
        for (std::size_t f = 0; f < settled.frameCount(); ++f) {
            evaluator.frame(f, frame);
            for (std::size_t i = 0; i < frame.size(); ++i)
                QVERIFY(sameFrame(frame[i], settled.at(f, i)));
        }
        // The file keeps a resolve without agents.
        const sim::LoadResult loaded = sim::parseScene(sim::sceneToYaml(s.scene), "square.yaml", "");
        QVERIFY2(loaded.ok(), loaded.diagnostics.empty() ? "" : loaded.diagnostics[0].format().c_str());
        QVERIFY(loaded.scene.layout == s.scene.layout);
    }

    // Bad entries fail with the file, line and what is wrong.
    void badEntriesAreErrorsWithTheirLine()
    {
        const struct {
            const char* entry;
            const char* message;
        } cases[] = {
            {"  - {op: shuffle, agents: {ids: [1]}}", "unknown layout operation 'shuffle'"},
            {"  - {op: translate, offset: [1, 0]}", "give the operation's 'agents'"},
            {"  - {op: translate, agents: {}, offset: [1, 0]}", "select some agents"},
            {"  - {op: translate, agents: {ids: [1]}}", "offset"},
            {"  - {op: expand, agents: {ids: [1]}, factor: 0}", "the factor is above 0"},
            {"  - {op: mirror, agents: {ids: [1]}, axis: [[1, 1], [1, 1]]}", "two different points"},
            {"  - {op: delete, agents: {ids: [1]}, frames: [40, 10]}", "give [first, last] frames"},
            {"  - {op: time_offset, agents: {ids: [1]}, later: 2.5}", "a whole number of frames"},
            {"  - {op: rotate, agents: {types: [flier]}, angle: 10}", "no agent type named 'flier'"},
            {"  - {op: duplicate, agents: {ids: [1]}}", "offset"},
            {"  - {op: swap, agents: {ids: [1]}}", "a swap gives a 'look', a 'tint' (or none) or a 'type'"},
            {"  - {op: swap, agents: {ids: [1]}, type: flier}", "no agent type named 'flier'"},
            {"  - {op: swap, agents: {ids: [1]}, type: runner, look: 3}",
             "look 3 is out of range: type 'runner' has 1"},
            {"  - {op: swap, agents: {ids: [1]}, look: 0, frames: [3, 9]}", "a swap shows the agents so on every frame"},
            {"  - {op: replace_clip, agents: {ids: [1]}, clip: moonwalk}", "unknown clip 'moonwalk'"},
        };
        for (const auto& c : cases) {
            const std::string yaml = std::string(kSquare) + "layout:\n" + c.entry + "\n";
            const sim::LoadResult loaded = sim::parseScene(yaml, "square.yaml", "");
            QVERIFY2(!loaded.ok(), c.entry);
            const std::string text = loaded.diagnostics[0].format();
            QVERIFY2(text.find(c.message) != std::string::npos, text.c_str());
            QVERIFY2(text.find("square.yaml:15:") == 0, text.c_str());
        }
        const sim::LoadResult twice = sim::parseScene(std::string(kSquare) + "layout:\n"
                                                      "  - {name: a, op: delete, agents: {ids: [1]}}\n"
                                                      "  - {name: a, op: delete, agents: {ids: [1]}}\n",
                                                      "square.yaml", "");
        QVERIFY(!twice.ok());
        QVERIFY2(twice.diagnostics[0].format().find("square.yaml:16:") == 0 &&
                     twice.diagnostics[0].format().find("another layout operation is already named 'a'") !=
                         std::string::npos,
                 twice.diagnostics[0].format().c_str());
    }
};

THRONG_REGISTER_TEST(TestLayoutLayer)
#include "TestLayoutLayer.moc"
