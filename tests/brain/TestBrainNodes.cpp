// Each stateless node's truth table or curve at key points, one agent per input row.
#include "BrainRig.h"
#include "TestRegistry.h"

#include <QTest>

#include <cmath>

using namespace throng;
using namespace throng::test;

namespace {

// Feeds inputs[p][agent] into port p of a node of `type`; returns output `port` per agent.
std::vector<float> apply(const std::string& type, std::vector<sim::BrainParam> params,
                         const std::vector<std::vector<float>>& inputs, std::uint32_t port = 0)
{
    GraphBuilder b;
    const sim::NodeId node = b.add(type, std::move(params));
    for (std::size_t p = 0; p < inputs.size(); ++p)
        b.link(b.sensor("attribute", {txt("name", "in" + std::to_string(p))}), 0, node, std::uint32_t(p));
    const std::size_t agents = inputs.empty() ? 1 : inputs[0].size();
    BrainRig rig(b.g, agents);
    if (!rig.ok()) {
        qWarning("%s", rig.errors.c_str());
        return {};
    }
    for (std::size_t p = 0; p < inputs.size(); ++p)
        rig.set("attribute", inputs[p], "in" + std::to_string(p));
    rig.step();
    std::vector<float> out;
    for (std::size_t a = 0; a < agents; ++a)
        out.push_back(rig.value(node, port, a));
    return out;
}

void near(const std::vector<float>& got, const std::vector<float>& want)
{
    QCOMPARE(got.size(), want.size());
    for (std::size_t i = 0; i < got.size(); ++i)
        if (std::fabs(got[i] - want[i]) > 1e-5f)
            QFAIL(qPrintable(QString("row %1: got %2, want %3").arg(i).arg(got[i]).arg(want[i])));
}

}  // namespace

class TestBrainNodes : public QObject {
    Q_OBJECT
private slots:
    void fuzzSets()
    {
        near(apply("fuzz.triangle", {nums("points", {0, 2, 4})}, {{-1, 0, 1, 2, 3, 4, 5}}), {0, 0, 0.5f, 1, 0.5f, 0, 0});
        near(apply("fuzz.trapezoid", {nums("points", {0, 1, 3, 5})}, {{-1, 0.5f, 1, 2, 3, 4, 5, 6}}),
             {0, 0.5f, 1, 1, 1, 0.5f, 0, 0});
        // A right shoulder, as walker.brain.yaml writes it: 1 from 6 m on.
        near(apply("fuzz.trapezoid", {nums("points", {2, 6, 1000, 1000})}, {{1, 4, 6, 50, 1000}}), {0, 0.5f, 1, 1, 1});
        // A left shoulder: vertical rise at a == b.
        near(apply("fuzz.trapezoid", {nums("points", {0, 0, 1, 2})}, {{-0.1f, 0, 1.5f}}), {0, 1, 0.5f});
        near(apply("fuzz.gaussian", {num("centre", 1), num("width", 2)}, {{1, 3, -1, 5}}),
             {1, std::exp(-0.5f), std::exp(-0.5f), std::exp(-2.0f)});
        near(apply("fuzz.sigmoid", {num("centre", 2), num("slope", 3)}, {{2, 2 + std::log(3.0f) / 3, -100}}), {0.5f, 0.75f, 0});
        near(apply("fuzz.sigmoid", {num("centre", 0), num("slope", -1)}, {{-100, 100}}), {1, 0});
    }

    void rules()
    {
        const std::vector<std::vector<float>> ab{{0.3f, 1, 0}, {0.8f, 1, 0}};
        near(apply("rule.and", {}, ab), {0.3f, 1, 0});
        near(apply("rule.and", {txt("mode", "product")}, ab), {0.24f, 1, 0});
        near(apply("rule.or", {}, ab), {0.8f, 1, 0});
        near(apply("rule.or", {txt("mode", "probsum")}, ab), {0.86f, 1, 0});
        near(apply("rule.and", {}, {{0.9f}, {0.7f}, {0.4f}}), {0.4f});  // three inputs
        near(apply("rule.not", {}, {{0.3f, 0, 1}}), {0.7f, 1, 0});
        near(apply("rule.weight", {num("weight", 0.5f)}, {{0.3f, 1}}), {0.15f, 0.5f});
        near(apply("rule.hedge", {txt("mode", "strong")}, {{0.3f, 1}}), {0.09f, 1});
        near(apply("rule.hedge", {txt("mode", "weak")}, {{0.25f, 0}}), {0.5f, 0});
        // Priority: earlier inputs claim their share of 1 first.
        const std::vector<std::vector<float>> pr{{0.7f, 0.2f}, {0.6f, 0.3f}, {0.5f, 0.9f}};
        near(apply("rule.priority", {}, pr, 0), {0.7f, 0.2f});
        near(apply("rule.priority", {}, pr, 1), {0.3f, 0.3f});
        near(apply("rule.priority", {}, pr, 2), {0.0f, 0.5f});
    }

    void defuzz()
    {
        const std::vector<std::vector<float>> t{{1, 0.5f, 0, 0.25f}, {0, 0.5f, 0, 0.75f}};
        near(apply("defuzz.average", {nums("values", {2, 8}), num("default", -1)}, t), {2, 5, -1, 6.5f});
        const std::vector<std::vector<float>> w{{0.2f, 0.5f}, {0.9f, 0.5f}, {0.9f, 0.1f}};
        near(apply("defuzz.winner", {}, w, 0), {1, 0});  // ties go to the first
        near(apply("defuzz.winner", {}, w, 1), {0.9f, 0.5f});
        near(apply("defuzz.winner", {nums("values", {10, 20, 30})}, w, 0), {20, 10});
    }

    void math()
    {
        const std::vector<std::vector<float>> ab{{6, -2, 3}, {3, 4, 0}};
        near(apply("math.add", {}, ab), {9, 2, 3});
        near(apply("math.subtract", {}, ab), {3, -6, 3});
        near(apply("math.multiply", {}, ab), {18, -8, 0});
        near(apply("math.divide", {num("fallback", 99)}, ab), {2, -0.5f, 99});
        near(apply("math.min", {}, ab), {3, -2, 0});
        near(apply("math.max", {}, ab), {6, 4, 3});
        near(apply("math.abs", {}, {{-2, 0, 3}}), {2, 0, 3});
        near(apply("math.clamp", {num("min", -1), num("max", 2)}, {{-5, 0.5f, 7}}), {-1, 0.5f, 2});
        near(apply("math.clamp", {}, {{5, 5}, {0, 6}, {3, 8}}), {3, 6});  // limits from inputs
        near(apply("math.lerp", {}, {{0, 10}, {10, 20}, {0.25f, 1}}), {2.5f, 20});
        near(apply("math.remap", {nums("from", {0, 10}), nums("to", {1, 0})}, {{0, 5, 20}}), {1, 0.5f, 0});
        near(apply("math.remap", {nums("from", {0, 10}), nums("to", {1, 0}), txt("clamp", "no")}, {{20}}), {-1});
        const std::vector<std::vector<float>> cmp{{1, 2, 3}, {2, 2, 2}};
        near(apply("math.compare", {txt("mode", "lt")}, cmp), {1, 0, 0});
        near(apply("math.compare", {txt("mode", "le")}, cmp), {1, 1, 0});
        near(apply("math.compare", {txt("mode", "gt")}, cmp), {0, 0, 1});
        near(apply("math.compare", {txt("mode", "ge")}, cmp), {0, 1, 1});
        near(apply("math.compare", {txt("mode", "eq")}, cmp), {0, 1, 0});
        near(apply("math.compare", {txt("mode", "ne")}, cmp), {1, 0, 1});
        near(apply("math.compare", {txt("mode", "gt"), num("value", 1.5f)}, {{1, 2}}), {0, 1});  // b from a parameter
    }

    void inputsAndConstants()
    {
        GraphBuilder b;
        const auto c = b.constant(2.5f);
        const auto r = b.add("input.random", {num("min", 10), num("max", 20)});
        const auto n = b.add("input.noise", {num("frequency", 1), num("min", -1), num("max", 1)});
        const auto t = b.sensor("time");
        const auto sum = b.add("math.add");
        b.link(c, 0, sum, 0);
        b.link(c, 0, sum, 1);
        BrainRig rig(b.g, 50);
        QVERIFY2(rig.ok(), rig.errors.c_str());
        rig.step(0.01f);
        QCOMPARE(rig.value(sum), 5.0f);  // folded at compile time
        QCOMPARE(rig.value(c), 2.5f);
        std::vector<float> first, noise;
        float spread = 0.0f;
        for (std::size_t a = 0; a < 50; ++a) {
            const float v = rig.value(r, 0, a);
            QVERIFY(v >= 10 && v < 20);
            first.push_back(v);
            spread = std::max(spread, std::fabs(v - first[0]));
            noise.push_back(rig.value(n, 0, a));
            QVERIFY(noise.back() >= -1 && noise.back() <= 1);
        }
        QVERIFY2(spread > 3.0f, "agents draw different random values");
        rig.step(0.01f);
        QCOMPARE(rig.value(t), 0.01f);
        for (std::size_t a = 0; a < 50; ++a) {
            QCOMPARE(rig.value(r, 0, a), first[a]);                        // fixed for the agent's life
            QVERIFY(std::fabs(rig.value(n, 0, a) - noise[a]) < 0.1f);     // smooth over 10 ms at 1 Hz
        }
    }
};

THRONG_REGISTER_TEST(TestBrainNodes)
#include "TestBrainNodes.moc"
