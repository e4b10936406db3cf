// The shortcuts that make `cross` cheaper must not change what the crowd does: a walker in
// an open field skips the wall and obstacle queries, and the combiners test a request's
// finiteness once. Checked as a user would: the same crowd with a wall far off in a corner
// (so every query runs and finds nothing) walks bit for bit the same, and a blend with
// broken requests equals the blend of the good ones alone.
#include "TestRegistry.h"

#include "simcore/scenarios/BenchScenarios.h"
#include "simcore/steering/SteeringCombination.h"
#include "simcore/steering/SteeringRequestList.h"
#include "simcore/world/World.h"

#include <QTest>

#include <cstring>
#include <limits>

using namespace throng::sim;

class TestOpenFieldShortcuts : public QObject {
    Q_OBJECT
private slots:
    void aFarWallLeavesTheCrowdBitIdentical()
    {
        const Scene open = makeCrossScenario(300);
        Scene walled = open;
        // In the corner of the bounds, beyond every ring and every goal.
        const glm::vec2 corner = open.settings.boundsMax - glm::vec2(2.0f);
        walled.walls.push_back({"far", {corner, corner - glm::vec2(3.0f, 0.0f)}});
        WorldOptions options;
        options.threads = 1;
        World a(open, options), b(walled, options);
        // 40 s: the first rings have met in the middle and the crowd is dense there.
        for (int s = 0; s < 24 * 40; ++s) {
            a.step();
            b.step();
        }
        QCOMPARE(b.counters().wallPenetrations, std::uint64_t(0));
        QVERIFY(std::memcmp(a.positions().data(), b.positions().data(), a.agentCount() * sizeof(glm::vec3)) == 0);
        QVERIFY(std::memcmp(a.velocities().data(), b.velocities().data(), a.agentCount() * sizeof(glm::vec3)) == 0);
        // And the crowd did move: nobody is where it started.
        std::size_t moved = 0;
        for (std::size_t i = 0; i < a.agentCount(); ++i)
            moved += glm::vec2(a.positions()[i].x, a.positions()[i].z) != glm::vec2(open.agents[i].position.x, open.agents[i].position.z);
        QCOMPARE(moved, a.agentCount());
    }

    void blendsIgnoreExactlyTheBrokenRequests()
    {
        constexpr float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
        SteeringRequestList good, mixed;
        good.add({1.0f, 0.0f, 0.5f}, 2.0f);
        good.add({0.0f, -0.25f, 1.0f}, 0.5f);
        mixed.add({inf, 0.0f, 0.0f}, 1.0f);      // infinite force
        mixed.add({1.0f, 0.0f, 0.5f}, 2.0f);
        mixed.add({0.0f, 1.0f, 0.0f}, nan);      // NaN weight
        mixed.add({inf, 0.0f, 0.0f}, 0.0f);      // 0 * inf
        mixed.add({0.0f, 0.0f, 0.0f}, inf);      // inf * 0
        mixed.add({1e30f, 0.0f, 0.0f}, 1e30f);   // overflows to inf
        mixed.add({0.0f, -0.25f, 1.0f}, 0.5f);
        for (float maxForce : {0.5f, 10.0f}) {
            const glm::vec3 want = blendWeighted(good, maxForce), got = blendWeighted(mixed, maxForce);
            QVERIFY(std::memcmp(&want, &got, sizeof want) == 0);
            const glm::vec3 wantP = allocateByPriority(good, maxForce), gotP = allocateByPriority(mixed, maxForce);
            QVERIFY(std::memcmp(&wantP, &gotP, sizeof wantP) == 0);
        }
        // The good part really counts: 2 * (1, 0, 0.5) + 0.5 * (0, -0.25, 1) = (2, -0.125, 1.5).
        const glm::vec3 sum = blendWeighted(mixed, 100.0f);
        QCOMPARE(sum, glm::vec3(2.0f, -0.125f, 1.5f));
    }
};

THRONG_REGISTER_TEST(TestOpenFieldShortcuts)
#include "TestOpenFieldShortcuts.moc"
