// A recording whose agent set changes at frame k (issue 6: a brush stroke resumed at the
// edit frame): frames before k keep the old agents, frames from k on the new ones, the
// hash says so, and truncating back before k brings the old set back bit for bit.
#include "TestRegistry.h"

#include "simcore/world/FrameCache.h"

#include <QTest>

using namespace throng::sim;

namespace {

std::vector<AgentFrame> frameOf(std::size_t n, float f)
{
    std::vector<AgentFrame> out(n);
    for (std::size_t i = 0; i < n; ++i)
        out[i].position = {float(i), 0.0f, f};
    return out;
}

}  // namespace

class TestFrameCacheAgentSet : public QObject {
    Q_OBJECT

private slots:
    void agentsAddedAndRemovedAtFrameK()
    {
        FrameCache cache;
        cache.reset({{1, 0}, {2, 0}, {3, 0}}, 24.0f);
        for (int f = 0; f < 5; ++f)
            cache.append(frameOf(3, float(f)));
        const std::uint64_t before = cache.hash(), firstFive = cache.hashFrames(0, 5);

        // Frame 5 on: a new agent 10 first in the World's order, agent 2 erased.
        const std::vector<AgentInfo> world{{10, 1}, {1, 0}, {3, 0}};
        const std::vector<std::int32_t> previous{-1, 0, 2};
        cache.changeAgents(world, previous);
        for (int f = 5; f < 8; ++f)
            cache.append(frameOf(3, float(f)));

        QCOMPARE(cache.frameCount(), std::size_t(8));
        QCOMPARE(cache.agentCount(), std::size_t(4));
        QCOMPARE(cache.agents()[3].id, AgentId(10));
        QCOMPARE(cache.worldAgentCount(), std::size_t(3));
        QCOMPARE(cache.cacheIndexOf(0), std::size_t(3));
        QCOMPARE(cache.worldIndexOf(1), std::ptrdiff_t(-1));  // agent 2 is gone
        QCOMPARE(cache.worldIndexOf(2), std::ptrdiff_t(2));
        // Before k: the old three, as recorded; the new one is not there.
        for (std::size_t f = 0; f < 5; ++f) {
            QVERIFY(cache.at(f, 0).present && cache.at(f, 1).present && cache.at(f, 2).present);
            QVERIFY(!cache.at(f, 3).present);
            QCOMPARE(cache.at(f, 1).position, glm::vec3(1.0f, 0.0f, float(f)));
        }
        // From k: agent 1 (World index 1), agent 3 (World index 2), agent 10 (World index 0).
        for (std::size_t f = 5; f < 8; ++f) {
            QVERIFY(!cache.at(f, 1).present);
            QVERIFY(!cache.at(f, 1).out);
            QCOMPARE(cache.at(f, 3).position, glm::vec3(0.0f, 0.0f, float(f)));
            QCOMPARE(cache.at(f, 0).position, glm::vec3(1.0f, 0.0f, float(f)));
            QCOMPARE(cache.at(f, 2).position, glm::vec3(2.0f, 0.0f, float(f)));
        }
        QCOMPARE(cache.agentsAt(2)[3].typeIndex, std::uint16_t(1));
        QCOMPARE(cache.agentSetChanges(), (std::vector<std::size_t>{0, 5}));
        QCOMPARE(cache.hashFrames(0, 5), firstFive);
        QVERIFY(cache.hash() != before);

        // Back before k: the old set and frames, bit for bit.
        cache.truncate(5);
        QCOMPARE(cache.agentCount(), std::size_t(3));
        QCOMPARE(cache.worldAgentCount(), std::size_t(3));
        QCOMPARE(cache.agentSetChanges(), (std::vector<std::size_t>{0}));
        QCOMPARE(cache.hash(), before);
        cache.append(frameOf(3, 5.0f));
        QCOMPARE(cache.at(5, 1).position, glm::vec3(1.0f, 0.0f, 5.0f));
    }

    void aTypeChangeHoldsFromItsFrameOn()
    {
        FrameCache cache;
        cache.reset({{1, 0}, {2, 0}}, 24.0f);
        cache.append(frameOf(2, 0.0f));
        cache.append(frameOf(2, 1.0f));
        const std::uint64_t before = cache.hash();
        cache.changeAgents(std::vector<AgentInfo>{{1, 0}, {2, 3}}, std::vector<std::int32_t>{0, 1});
        cache.append(frameOf(2, 2.0f));
        QCOMPARE(cache.agentCount(), std::size_t(2));
        QCOMPARE(cache.agentsAt(1)[1].typeIndex, std::uint16_t(0));
        QCOMPARE(cache.agentsAt(2)[1].typeIndex, std::uint16_t(3));
        QCOMPARE(cache.agents()[1].typeIndex, std::uint16_t(3));
        cache.truncate(2);
        QCOMPARE(cache.hash(), before);
        // The same agents with the same types: no new set.
        cache.changeAgents(std::vector<AgentInfo>{{1, 0}, {2, 0}}, std::vector<std::int32_t>{0, 1});
        QCOMPARE(cache.agentSetChanges().size(), std::size_t(1));
        QCOMPARE(cache.hash(), before);
    }
};

THRONG_REGISTER_TEST(TestFrameCacheAgentSet)
#include "TestFrameCacheAgentSet.moc"
