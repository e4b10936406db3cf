// Per-agent variation is a pure function of (seed, agent id): the same on every run, spread
// over the type's ranges and palette, different between neighbours, and in step with the
// simulation's own speed factor and phase offset.
#include "TestRegistry.h"

#include "export/character/AgentVariation.h"
#include "simcore/world/FrameCache.h"
#include "simcore/world/World.h"

#include <QTest>

#include <set>

using namespace throng;
using namespace throng::exporting;

namespace {

sim::Variation crowdVariation()
{
    sim::Variation v;
    v.looks = {"man", "woman", "tall_man", "child"};
    v.tints = {{0.8f, 0.2f, 0.2f}, {0.2f, 0.4f, 0.8f}, {0.9f, 0.8f, 0.3f}};
    v.heightScale = {0.9f, 1.1f};
    v.speedFactor = {0.8f, 1.2f};
    v.phaseOffset = {0.0f, 1.0f};
    return v;
}

}  // namespace

class TestAgentVariation : public QObject {
    Q_OBJECT

private slots:
    void reproducibleForASeed()
    {
        const sim::Variation v = crowdVariation();
        bool anyDiffers = false;
        for (std::uint32_t id = 1; id <= 200; ++id) {
            const AgentVariation a = drawVariation(v, 42, id, 4), b = drawVariation(v, 42, id, 4);
            QCOMPARE(a.look, b.look);
            QCOMPARE(a.tint, b.tint);
            QCOMPARE(a.heightScale, b.heightScale);
            QCOMPARE(a.speedFactor, b.speedFactor);
            QCOMPARE(a.phaseOffset, b.phaseOffset);
            const AgentVariation other = drawVariation(v, 43, id, 4);
            anyDiffers = anyDiffers || other.heightScale != a.heightScale || other.look != a.look;
        }
        QVERIFY(anyDiffers);  // another seed, another crowd
    }

    // 200 agents use every look and tint, fill the ranges, and no two share a height.
    void differentBetweenAgents()
    {
        const sim::Variation v = crowdVariation();
        std::set<std::size_t> looks;
        std::set<int> tints;
        std::set<float> heights, phases;
        float lo = 10.0f, hi = 0.0f;
        for (std::uint32_t id = 1; id <= 200; ++id) {
            const AgentVariation a = drawVariation(v, 7, id, 4);
            looks.insert(a.look);
            tints.insert(a.tint);
            heights.insert(a.heightScale);
            phases.insert(a.phaseOffset);
            QVERIFY(a.heightScale >= 0.9f && a.heightScale <= 1.1f);
            QVERIFY(a.speedFactor >= 0.8f && a.speedFactor <= 1.2f);
            QVERIFY(a.phaseOffset >= 0.0f && a.phaseOffset <= 1.0f);
            lo = std::min(lo, a.heightScale);
            hi = std::max(hi, a.heightScale);
        }
        QCOMPARE(looks.size(), std::size_t(4));
        QCOMPARE(tints.size(), std::size_t(3));
        QCOMPARE(heights.size(), std::size_t(200));
        QCOMPARE(phases.size(), std::size_t(200));
        QVERIFY(lo < 0.92f && hi > 1.08f);
        const AgentVariation plain = drawVariation(sim::Variation{}, 7, 1, 1);
        QCOMPARE(plain.look, std::size_t(0));
        QCOMPARE(plain.tint, -1);
        QCOMPARE(plain.heightScale, 1.0f);
    }

    // The gait starts where the simulation says the agent's phase starts.
    void agreesWithTheSimulation()
    {
        sim::Scene scene;
        sim::AgentType walker;
        walker.name = "walker";
        walker.variation = crowdVariation();
        scene.agentTypes = {walker};
        scene.settings.seed = 99;
        for (std::uint32_t id = 1; id <= 20; ++id) {
            sim::Agent a;
            a.id = id * 3;
            a.type = "walker";
            a.position = {static_cast<float>(id), 0.0f, 0.0f};
            scene.agents.push_back(a);
        }
        sim::World world(scene, sim::WorldOptions{});
        sim::FrameCache cache;
        world.startRecording(cache);
        for (std::size_t i = 0; i < cache.agentCount(); ++i) {
            const AgentVariation v = drawVariation(walker.variation, 99, cache.agents()[i].id, 4);
            QCOMPARE(v.phaseOffset, cache.at(0, i).phase);
        }
    }
};

THRONG_REGISTER_TEST(TestAgentVariation)
#include "TestAgentVariation.moc"
