// The compiler rejects each kind of bad graph with a message naming the node (and, for a
// graph read from a file, its line and column), and accepts the good ones.
#include "BrainRig.h"
#include "TestRegistry.h"

#include "simcore/io/SceneIO.h"

#include <QTest>

using namespace throng;
using namespace throng::test;

namespace {

// A graph of one node of `type` fed by speed sensors, for parameter checks.
sim::BrainGraph single(const std::string& type, std::vector<sim::BrainParam> params, int inputs = 1)
{
    GraphBuilder b;
    const auto n = b.add(type, std::move(params));
    for (int p = 0; p < inputs; ++p)
        b.link(b.sensor("speed"), 0, n, std::uint32_t(p));
    return b.g;
}

QString expectError(const sim::BrainGraph& g, sim::NodeId node, const std::string& text,
                    const std::vector<sim::BrainGraph>& library = {})
{
    const sim::BrainCompileResult r = sim::compileBrain(g, library);
    if (r.ok())
        return "compiled, but should fail with: " + QString::fromStdString(text);
    std::string all;
    for (const sim::BrainError& e : r.errors) {
        if (e.node == node && e.message.find(text) != std::string::npos)
            return {};
        all += "\n  [node " + std::to_string(e.node) + "] " + e.format();
    }
    return QString::fromStdString("no error on node " + std::to_string(node) + " containing '" + text + "'; got:" + all);
}

#define EXPECT_ERROR(...)                                   \
    do {                                                    \
        const QString why = expectError(__VA_ARGS__);       \
        QVERIFY2(why.isEmpty(), qPrintable(why));           \
    } while (false)

}  // namespace

class TestBrainCompiler : public QObject {
    Q_OBJECT
private slots:
    void unknownTypesSensorsAndParameters()
    {
        EXPECT_ERROR(single("fuzz.bogus", {}), 1, "node 1 (fuzz.bogus): unknown node type 'fuzz.bogus'");
        GraphBuilder b;
        const auto smell = b.sensor("smell");
        const auto fz = b.add("fuzz.sigmoid");
        b.link(smell, 0, fz, 0);
        EXPECT_ERROR(b.g, 1, "unknown sensor 'smell'");
        QCOMPARE(sim::compileBrain(b.g).errors.size(), std::size_t(1));  // no follow-on error on node 2
        GraphBuilder s;
        s.sensor("sound_strength");
        EXPECT_ERROR(s.g, 1, "sensor 'sound_strength' needs parameter 'channel'");
        EXPECT_ERROR(single("fuzz.triangle", {nums("points", {0, 1})}), 1, "parameter 'points' needs 3 numbers, not 2");
        EXPECT_ERROR(single("fuzz.triangle", {nums("points", {0, 3, 1})}), 1, "'points' must be in ascending order");
        EXPECT_ERROR(single("fuzz.triangle", {}), 1, "missing parameter 'points'");
        EXPECT_ERROR(single("fuzz.gaussian", {num("width", 0)}), 1, "parameter 'width' must be in [1e-06");
        EXPECT_ERROR(single("rule.not", {num("colour", 3)}), 1, "unknown parameter 'colour'");
        EXPECT_ERROR(single("rule.and", {txt("mode", "xor")}, 2), 1, "parameter 'mode' must be one of min product, not 'xor'");
        EXPECT_ERROR(single("input.constant", {txt("value", "ten")}, 0), 1, "parameter 'value' must be a number");
        EXPECT_ERROR(single("output", {txt("channel", "weight"), txt("behaviour", "dance")}), 1,
                     "unknown steering behaviour 'dance'");
        EXPECT_ERROR(single("defuzz.average", {nums("values", {1, 2, 3})}, 2), 1,
                     "parameter 'values' has 3 values for 2 connected inputs");
    }

    void badLinksAndMissingInputs()
    {
        EXPECT_ERROR(single("math.subtract", {}, 1), 1, "input 1 'b' is not connected");
        EXPECT_ERROR(single("rule.and", {}, 1), 1, "needs at least 2 connected inputs, has 1");
        GraphBuilder b;
        const auto x = b.sensor("speed");
        const auto n = b.add("rule.not");
        b.link(x, 3, n, 0);
        EXPECT_ERROR(b.g, n, "link 0: node 1 (input) has no output port 3");
        GraphBuilder t;
        const auto y = t.sensor("speed");
        const auto m = t.add("rule.not");
        t.link(y, 0, m, 0);
        t.link(y, 0, m, 0);
        EXPECT_ERROR(t.g, m, "input 0 of node 2 is connected twice");
        GraphBuilder u;
        const auto z = u.sensor("speed");
        const auto w = u.add("math.abs");
        u.link(z, 0, w, 2);
        EXPECT_ERROR(u.g, w, "node 2 (math.abs) has no input port 2");
    }

    void perNeighbourIntoScalarNeedsAFilter()
    {
        GraphBuilder b;
        const auto d = b.sensor("neighbour_distance");
        const auto fz = b.add("fuzz.sigmoid");
        const auto out = b.add("output", {txt("channel", "speed")});
        b.link(d, 0, fz, 0);
        b.link(fz, 0, out, 0);
        EXPECT_ERROR(b.g, out, "type mismatch: input 0 'x' takes one value per agent but node 2 gives one per neighbour");
        GraphBuilder f;
        const auto s = f.sensor("speed");
        const auto filter = f.add("filter");
        f.link(s, 0, filter, 0);
        EXPECT_ERROR(f.g, filter, "type mismatch: input 0 'x' takes per-neighbour values but node 1 gives one value per agent");
    }

    void cyclesOnlyThroughMemory()
    {
        GraphBuilder b;
        const auto x = b.sensor("speed");
        const auto add = b.add("math.add");
        const auto abs = b.add("math.abs");
        b.link(x, 0, add, 0);
        b.link(abs, 0, add, 1);
        b.link(add, 0, abs, 0);
        EXPECT_ERROR(b.g, add, "illegal cycle 2 -> 3 -> 2 (a loop must pass through a state.memory node)");
        // The same loop through a memory node compiles.
        const auto mem = b.add("state.memory");
        b.g.links.back() = {add, 0, mem, 0};
        b.link(mem, 0, abs, 0);
        const sim::BrainCompileResult r = sim::compileBrain(b.g);
        QVERIFY2(r.ok(), r.errors.empty() ? "" : r.errors[0].format().c_str());
    }

    void duplicateOutputsAndMacros()
    {
        GraphBuilder b;
        const auto x = b.sensor("speed");
        const auto o1 = b.add("output", {txt("channel", "speed")});
        const auto o2 = b.add("output", {txt("channel", "speed")});
        b.link(x, 0, o1, 0);
        b.link(x, 0, o2, 0);
        EXPECT_ERROR(b.g, o2, "duplicate output channel 'speed': node 2 already drives it");
        EXPECT_ERROR(single("macro", {txt("brain", "nowhere")}, 0), 1, "no brain named 'nowhere' for this macro");
        GraphBuilder self;
        self.g.name = "loop";
        self.add("macro", {txt("brain", "loop")});
        EXPECT_ERROR(self.g, 1, "macro 'loop' uses itself", {self.g});
        // An error inside a macro names the macro node, then the inner node.
        GraphBuilder inner;
        inner.g.name = "broken";
        inner.add("fuzz.triangle");
        GraphBuilder outer;
        outer.add("note", {txt("text", "uses broken")});
        outer.add("macro", {txt("brain", "broken")});
        EXPECT_ERROR(outer.g, 2, "node 2 (macro): in macro 'broken': node 1 (fuzz.triangle): missing parameter 'points'",
                     {inner.g});
    }

    void errorsInAFileCarryLineAndColumn()
    {
        const std::string text = "throng: 1\n"
                                 "brains:\n"
                                 "  - name: b\n"
                                 "    nodes:\n"
                                 "      - {id: 1, type: input, params: {sensor: speed}}\n"
                                 "      - {id: 7, type: math.subtract}\n"
                                 "    links:\n"
                                 "      - {from: [1, 0], to: [7, 0]}\n"
                                 "      - {from: [1, 2], to: [7, 1]}\n";
        const sim::LoadResult loaded = sim::parseScene(text, "scene.yaml", ".");
        QVERIFY(loaded.ok());
        const sim::BrainCompileResult r = sim::compileBrain(loaded.scene.brains[0]);
        QVERIFY(!r.ok());
        QStringList all;
        for (const sim::BrainError& e : r.errors)
            all << QString::fromStdString(e.format());
        QVERIFY2(all.contains("scene.yaml:9:9: error: link 1: node 1 (input) has no output port 2"), qPrintable(all.join("\n")));
        QVERIFY2(all.contains("scene.yaml:6:9: error: node 7 (math.subtract): input 1 'b' is not connected"),
                 qPrintable(all.join("\n")));
    }
};

THRONG_REGISTER_TEST(TestBrainCompiler)
#include "TestBrainCompiler.moc"
