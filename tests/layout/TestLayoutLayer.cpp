// The layout layer (issue 29) on a real recording (LayoutShot.h: two groups crossing a
// square). Each operation measured where a user would look: the trajectories CSV. Moved
// agents are where the layer puts them and the others byte for byte where they were; a
// retimed agent's first step comes later by the offset; deleted agents leave the CSV and
// are invisible in USD and scaled away in glTF; a turn keeps distances to its pivot; a
// mirror reflects the walk; Expand spreads the group about its centre. Selections by id,
// group, type and lasso; operations that select nobody are named; the file round trip
// keeps the layer; bad entries fail with file:line messages; a re-simulation with another
// seed keeps the layer by agent id. (Copies, swaps, clips, the check and resolve:
// TestLayoutCopiesAndChecks.)
#include "LayoutShot.h"
#include "TestRegistry.h"

#include "GltfReadBack.h"
#include "export/GltfExporter.h"

#include <QTemporaryDir>
#include <QTest>

#include <glm/geometric.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

using namespace throng;
using namespace throng::test::layout;

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
        const auto rowsBefore = csvRows(s.cache, dir.filePath("before.csv").toStdString());
        const auto rowsAfter = csvRows(laid, dir.filePath("after.csv").toStdString());
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
        const auto rows = csvRows(laid, path);
        QCOMPARE(int(rows.at(first).size()), 30);
        QCOMPARE(rows.at(first).rbegin()->first, 29);
        QVERIFY(!rows.count(first + 1));
        QCOMPARE(int(rows.size()), 20);
        // In a skinned export they are hidden from those frames: USD's visibility says so.
        const QString text = usdText(s.scene, laid, dir.filePath("laid.usda"));
        QVERIFY2(!text.isEmpty(), "no USD written");
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
        const sim::LayoutOp expand = expandGroup("northbound", 2.0f);
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
