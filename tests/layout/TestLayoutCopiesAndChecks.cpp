// The layout layer's copies, swaps, clips, check and resolve on a real recording
// (LayoutShot.h): a duplicate walks beside its source with an id and a look of its own; a
// swap and a replaced clip reach the exports; the check after the edits finds the
// overlaps and wall crossings they make, as an independent recount does; resolve nudges
// only the edited agents apart.
#include "LayoutShot.h"
#include "TestRegistry.h"

#include "simcore/layout/LayoutCheck.h"

#include <QTemporaryDir>
#include <QTest>

#include <glm/geometric.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

using namespace throng;
using namespace throng::test::layout;

class TestLayoutCopiesAndChecks : public QObject {
    Q_OBJECT
private slots:
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
        const auto rowsBefore = csvRows(s.cache, dir.filePath("before.csv").toStdString());
        const auto rowsAfter = csvRows(laid, dir.filePath("after.csv").toStdString());
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
        const QString text = usdText(s.scene, laid, dir.filePath("laid.usda"));
        QVERIFY2(!text.isEmpty(), "no USD written");
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
        const sim::LayoutOp squeeze = expandGroup("eastbound", 0.1f);
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
};

THRONG_REGISTER_TEST(TestLayoutCopiesAndChecks)
#include "TestLayoutCopiesAndChecks.moc"
