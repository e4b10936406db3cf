// State nodes over several steps (memory, timer, latch, smoothing, the action layer),
// goal choice, outputs, macros and the picked agent's live values.
#include "BrainRig.h"
#include "TestRegistry.h"

#include <QTest>

#include <cmath>

using namespace throng;
using namespace throng::test;

class TestBrainStateNodes : public QObject {
    Q_OBJECT
private slots:
    void memoryClosesALoop()
    {
        // counter = memory(counter + 1): a loop legal only through the memory node.
        GraphBuilder b;
        const auto mem = b.add("state.memory", {num("initial", 10)});
        const auto one = b.constant(1);
        const auto add = b.add("math.add");
        b.link(mem, 0, add, 0);
        b.link(one, 0, add, 1);
        b.link(add, 0, mem, 0);
        BrainRig rig(b.g, 3);
        QVERIFY2(rig.ok(), rig.errors.c_str());
        for (int s = 0; s < 4; ++s) {
            rig.step();
            QCOMPARE(rig.value(mem), 10.0f + float(s));
            QCOMPARE(rig.value(add, 0, 2), 11.0f + float(s));
        }
    }

    void timerLatchSmooth()
    {
        GraphBuilder b;
        const auto run = b.sensor("attribute", {txt("name", "run")});
        const auto reset = b.sensor("attribute", {txt("name", "reset")});
        const auto timer = b.add("state.timer");
        const auto latch = b.add("state.latch");
        const auto smooth = b.add("state.smooth", {num("tau", 1)});
        b.link(run, 0, timer, 0);
        b.link(run, 0, latch, 0);
        b.link(reset, 0, latch, 1);
        b.link(run, 0, smooth, 0);
        BrainRig rig(b.g, 1);
        QVERIFY2(rig.ok(), rig.errors.c_str());
        const auto stepWith = [&](float r, float z) {
            rig.set("attribute", {r}, "run");
            rig.set("attribute", {z}, "reset");
            rig.step(0.25f);
        };
        stepWith(0, 0);
        QCOMPARE(rig.value(timer), 0.0f);
        QCOMPARE(rig.value(latch), 0.0f);
        QCOMPARE(rig.value(smooth), 0.0f);  // starts at its input
        for (int s = 1; s <= 4; ++s) {
            stepWith(1, 0);
            QCOMPARE(rig.value(timer), 0.25f * float(s));
        }
        // After 4 × 0.25 s = one time constant, the smoothed step reached 1 - e^-1.
        QVERIFY(std::fabs(rig.value(smooth) - (1.0f - std::exp(-1.0f))) < 1e-4f);
        stepWith(0, 0);
        QCOMPARE(rig.value(timer), 0.0f);
        QCOMPARE(rig.value(latch), 1.0f);  // stays set
        stepWith(1, 1);
        QCOMPARE(rig.value(latch), 0.0f);  // reset wins
    }

    void actionLayerWaitsForTheClipToEnd()
    {
        GraphBuilder b;
        const auto walk = b.sensor("attribute", {txt("name", "walk")});
        const auto run = b.sensor("attribute", {txt("name", "run")});
        const auto act = b.add("output.action", {txt("actions", "walk run"), nums("durations", {1.0f, 0.5f})});
        b.link(walk, 0, act, 0);
        b.link(run, 0, act, 1);
        BrainRig rig(b.g, 1);
        QVERIFY2(rig.ok(), rig.errors.c_str());
        const auto step = [&](float w, float r) {
            rig.set("attribute", {w}, "walk");
            rig.set("attribute", {r}, "run");
            rig.step(0.25f);
            return rig.eval->outputs().action[0];
        };
        QCOMPARE(step(1, 0), 0.0f);  // walk: a 1 s clip
        QCOMPARE(step(0, 1), 0.0f);  // run is now more desirable, but the clip runs on
        QCOMPARE(step(0, 1), 0.0f);
        QCOMPARE(step(0, 1), 0.0f);
        QCOMPARE(step(0, 1), 1.0f);  // 1 s later the clip ends and run takes over
        QCOMPARE(rig.eval->outputs().actionNames, (std::vector<std::string>{"walk", "run"}));
    }

    void outputsAndGoal()
    {
        GraphBuilder b;
        const auto d = b.sensor("goal_distance");
        const auto speed = b.add("output", {txt("channel", "speed"), num("scale", 2)});
        const auto weight = b.add("output", {txt("channel", "weight"), txt("behaviour", "separation")});
        const auto tag = b.add("output", {txt("channel", "tag"), txt("tag", "alarm")});
        const auto goal = b.add("output.goal", {txt("goals", "north south")});
        const auto other = b.add("rule.not");
        b.link(d, 0, speed, 0);
        b.link(d, 0, weight, 0);
        b.link(d, 0, tag, 0);
        b.link(d, 0, other, 0);
        b.link(d, 0, goal, 0);
        b.link(other, 0, goal, 1);
        BrainRig rig(b.g, 2);
        QVERIFY2(rig.ok(), rig.errors.c_str());
        rig.set("goal_distance", {0.75f, 0.25f});
        rig.step();
        const sim::BrainOutputs o = rig.eval->outputs();
        QVERIFY(o.speed && !o.turn && o.goal);
        QCOMPARE(o.speed[0], 1.5f);
        QCOMPARE(o.weights.size(), std::size_t(1));
        QCOMPARE(o.weights[0].first, std::string("separation"));
        QCOMPARE(o.weights[0].second[1], 0.25f);
        QCOMPARE(o.tags[0].first, std::string("alarm"));
        QCOMPARE(o.goal[0], 0.0f);  // 0.75 > 0.25: north
        QCOMPARE(o.goal[1], 1.0f);
        QCOMPARE(o.goalNames[1], std::string("south"));
    }

    void macroExpandsInline()
    {
        // "double": macro.in 0 -> × 2 -> macro.out 0, used twice in a row.
        GraphBuilder m;
        m.g.name = "double";
        const auto in = m.add("macro.in", {num("port", 0)});
        const auto two = m.constant(2);
        const auto mul = m.add("math.multiply");
        const auto out = m.add("macro.out", {num("port", 0)});
        m.link(in, 0, mul, 0);
        m.link(two, 0, mul, 1);
        m.link(mul, 0, out, 0);
        GraphBuilder b;
        const auto x = b.sensor("speed");
        const auto m1 = b.add("macro", {txt("brain", "double")});
        const auto m2 = b.add("macro", {txt("brain", "double")});
        const auto probe = b.add("probe", {txt("name", "quadruple")});
        b.link(x, 0, m1, 0);
        b.link(m1, 0, m2, 0);
        b.link(m2, 0, probe, 0);
        BrainRig rig(b.g, 2, {m.g});
        QVERIFY2(rig.ok(), rig.errors.c_str());
        rig.set("speed", {1.5f, -1});
        rig.eval->setPickedAgent(1);
        rig.step();
        const auto probes = rig.eval->pickedProbes();
        QCOMPARE(probes.size(), std::size_t(1));
        QCOMPARE(probes[0].first, std::string("quadruple"));
        QCOMPARE(probes[0].second, -4.0f);
        // The live view holds every top-level node's value for the picked agent.
        bool sawSensor = false;
        for (const sim::BrainNodeValue& v : rig.eval->pickedValues())
            if (v.node == x)
                sawSensor = v.values == std::vector<float>{-1.0f};
        QVERIFY(sawSensor);
        QCOMPARE(rig.value(m1, 0, 0), 3.0f);  // a macro node shows its outputs
        QCOMPARE(rig.value(m2, 0, 0), 6.0f);
    }
};

THRONG_REGISTER_TEST(TestBrainStateNodes)
#include "TestBrainStateNodes.moc"
