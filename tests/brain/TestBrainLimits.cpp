// Brains as deep and as wide as users build them: what a user saw before was a chain of
// 18 macros (each a small valid brain using the one before) reported as "macro uses
// itself", and a rule.and fed by 300 conditions refused at its 257th input with "has no
// input port 256", a limit no page mentioned. Chains now nest to kMaxMacroDepth; a macro
// that uses itself, a chain past the depth and an expansion past kMaxExpandedNodes are
// errors that say which; repeating inputs take up to kMaxVariadicInputs.
#include "BrainRig.h"
#include "TestRegistry.h"

#include <QTest>

using namespace throng;
using namespace throng::test;

namespace {

// "level<k>": macro.in -> level<k-1> (or nothing at 0) -> + 1 -> macro.out.
std::vector<sim::BrainGraph> addOneChain(int depth, int usesPerLevel = 1)
{
    std::vector<sim::BrainGraph> library;
    for (int k = 0; k < depth; ++k) {
        GraphBuilder m;
        m.g.name = "level" + std::to_string(k);
        sim::NodeId last = m.add("macro.in", {num("port", 0)});
        for (int u = 0; k > 0 && u < usesPerLevel; ++u) {
            const sim::NodeId inner = m.add("macro", {txt("brain", "level" + std::to_string(k - 1))});
            m.link(last, 0, inner, 0);
            last = inner;
        }
        const sim::NodeId one = m.constant(1);
        const sim::NodeId add = m.add("math.add");
        const sim::NodeId out = m.add("macro.out", {num("port", 0)});
        m.link(last, 0, add, 0);
        m.link(one, 0, add, 1);
        m.link(add, 0, out, 0);
        library.push_back(m.g);
    }
    return library;
}

// speed -> macro(top of the chain) -> probe "out".
GraphBuilder useTop(int depth)
{
    GraphBuilder b;
    const auto x = b.sensor("speed");
    const auto m = b.add("macro", {txt("brain", "level" + std::to_string(depth - 1))});
    const auto probe = b.add("probe", {txt("name", "out")});
    b.link(x, 0, m, 0);
    b.link(m, 0, probe, 0);
    return b;
}

float probed(BrainRig& rig, float speed)
{
    rig.set("speed", {speed});
    rig.eval->setPickedAgent(0);
    rig.step();
    const auto probes = rig.eval->pickedProbes();
    return probes.empty() ? -12345.0f : probes[0].second;
}

std::string allErrors(const sim::BrainCompileResult& r)
{
    std::string s;
    for (const sim::BrainError& e : r.errors)
        s += e.message + "\n";
    return s;
}

}  // namespace

class TestBrainLimits : public QObject {
    Q_OBJECT
private slots:
    void aChainOfThirtyMacrosCompilesAndRuns()
    {
        const auto library = addOneChain(30);
        BrainRig rig(useTop(30).g, 1, library);
        QVERIFY2(rig.ok(), rig.errors.c_str());
        QCOMPARE(probed(rig, 0.5f), 30.5f);
    }

    void aChainAtTheDepthLimitRunsAndOneMoreIsNamed()
    {
        const int depth = int(sim::kMaxMacroDepth);
        BrainRig rig(useTop(depth).g, 1, addOneChain(depth));
        QVERIFY2(rig.ok(), rig.errors.c_str());
        QCOMPARE(probed(rig, 0.0f), float(depth));
        const sim::BrainCompileResult deeper = sim::compileBrain(useTop(depth + 1).g, addOneChain(depth + 1));
        QVERIFY(!deeper.ok());
        const std::string e = allErrors(deeper);
        QVERIFY2(e.find("nests macros more than " + std::to_string(depth) + " deep") != std::string::npos, e.c_str());
        QVERIFY2(e.find("uses itself") == std::string::npos, e.c_str());
    }

    void aMacroThatUsesItselfIsStillAnError()
    {
        // a -> b -> a
        GraphBuilder a, b;
        a.g.name = "a";
        b.g.name = "b";
        a.add("macro", {txt("brain", "b")});
        b.add("macro", {txt("brain", "a")});
        const sim::BrainCompileResult r = sim::compileBrain(a.g, {a.g, b.g});
        QVERIFY(!r.ok());
        QVERIFY2(allErrors(r).find("macro 'b' uses itself") != std::string::npos, allErrors(r).c_str());
    }

    void aMacroThatDoublesAtEveryLevelIsStoppedByItsSize()
    {
        // Each level uses the one below twice: 2^24 nodes at the top, stopped at the limit
        // with a message instead of exhausting memory.
        const sim::BrainCompileResult r = sim::compileBrain(useTop(24).g, addOneChain(24, 2));
        QVERIFY(!r.ok());
        const std::string e = allErrors(r);
        QVERIFY2(e.find("expands the brain past " + std::to_string(sim::kMaxExpandedNodes) + " nodes") != std::string::npos,
                 e.substr(0, 400).c_str());
    }

    void aRuleAndTakesThreeHundredInputs()
    {
        for (const float last : {0.3f, 0.97f}) {
            GraphBuilder b;
            const auto x = b.sensor("speed");
            const auto c = b.constant(last);
            const auto andNode = b.add("rule.and");
            const auto probe = b.add("probe", {txt("name", "out")});
            for (std::uint32_t k = 0; k < 299; ++k)
                b.link(x, 0, andNode, k);
            b.link(c, 0, andNode, 299);  // past the old silent limit of 256
            b.link(andNode, 0, probe, 0);
            BrainRig rig(b.g, 1);
            QVERIFY2(rig.ok(), rig.errors.c_str());
            QCOMPARE(probed(rig, 0.95f), std::min(last, 0.95f));
        }
    }

    void anInputPastTheLimitSaysTheLimit()
    {
        GraphBuilder b;
        const auto x = b.sensor("speed");
        const auto andNode = b.add("rule.and");
        b.link(x, 0, andNode, 0);
        b.link(x, 0, andNode, sim::kMaxVariadicInputs);
        const sim::BrainCompileResult r = sim::compileBrain(b.g);
        QVERIFY(!r.ok());
        const std::string e = allErrors(r);
        QVERIFY2(e.find("takes at most " + std::to_string(sim::kMaxVariadicInputs) + " inputs") != std::string::npos, e.c_str());
    }
};

THRONG_REGISTER_TEST(TestBrainLimits)
#include "TestBrainLimits.moc"
