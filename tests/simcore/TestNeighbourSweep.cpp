// The neighbour sweep (NeighbourGrid::forEachNearestSweep, WorldOptions::neighbourSweep):
// boids step in the grid's order, each search moving the last one's height windows and
// starting from last step's k nearest (walkers start from theirs too). It must change
// nothing: a k-nearest search through the sweep finds exactly what a brute-force scan
// finds, and a flock or a crowd run with and without it ends bit-identical, for 1 and 2
// threads, from a packed start, once it has gathered, and in the jam of `cross`.
#include "RunBits.h"
#include "TestRegistry.h"

#include "simcore/scenarios/BenchScenarios.h"
#include "simcore/world/NearestList.h"
#include "simcore/world/NeighbourGrid.h"
#include "simcore/world/TieOrder.h"
#include "simcore/world/World.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <vector>

using namespace throng::sim;

namespace {

constexpr std::size_t kK = 8;

// Agent i's k nearest within r (ties by index), by brute force.
std::vector<std::uint64_t> bruteNearest(const std::vector<glm::vec3>& pos, std::size_t i, float r)
{
    std::vector<std::uint64_t> keys;
    for (std::size_t j = 0; j < pos.size(); ++j) {
        const glm::vec3 d = pos[j] - pos[i];
        const float d2 = glm::dot(d, d);
        if (j != i && d2 <= r * r)
            keys.push_back(nearestKey(d2, std::uint32_t(j)));
    }
    std::sort(keys.begin(), keys.end());
    keys.resize(std::min(keys.size(), kK));
    return keys;
}

throng::test::RunBits run(const Scene& s, bool sweep, int threads, int steps, bool steerEight = true)
{
    WorldOptions o;
    o.threads = threads;
    o.neighbourSweep = sweep;
    o.steerEight = steerEight;
    return throng::test::runToEnd(s, o, steps);
}

}  // namespace

class TestNeighbourSweep : public QObject {
    Q_OBJECT
private slots:
    // The list itself: after each insert it holds the k smallest keys so far, ascending,
    // and says whether the new key is among them.
    void nearestListKeepsTheSmallest()
    {
        std::mt19937 gen(3);
        std::uniform_real_distribution<float> u(0.0f, 4.0f);
        for (int round = 0; round < 50; ++round) {
            NearestList<kK> best;
            std::vector<std::uint64_t> seen;
            for (std::uint32_t j = 0; j < 30; ++j) {
                // Coarse distances, so ties (broken by index) are common.
                const std::uint64_t key = nearestKey(std::floor(u(gen) * 4.0f) * 0.25f, j, j % 11 == 5);
                seen.push_back(key);
                std::vector<std::uint64_t> expected = seen;
                std::sort(expected.begin(), expected.end());
                expected.resize(std::min(expected.size(), kK));
                const bool kept = best.insert(key);
                QCOMPARE(kept, std::find(expected.begin(), expected.end(), key) != expected.end());
                QCOMPARE(best.count, expected.size());
                QVERIFY(std::equal(expected.begin(), expected.end(), best.keys.begin()));
            }
            QVERIFY(best.full());
        }
    }

    void aTieThatDecidesIsSeen()
    {
        // Keys at coarse distances, so ties are common. When the list says it saw no tie
        // that decides anything, breaking ties the other way round (as another storage
        // order would) must keep the same candidates in the same order; and ties must be
        // seen in some rounds and not in others.
        std::mt19937 gen(5);
        std::uniform_real_distribution<float> u(0.0f, 4.0f);
        int seen = 0, unseen = 0;
        for (int round = 0; round < 400; ++round) {
            NearestList<kK> best;
            std::vector<std::uint64_t> all;
            const int candidates = 4 + round % 24;
            for (std::uint32_t j = 0; j < std::uint32_t(candidates); ++j) {
                const std::uint64_t key = nearestKey(std::floor(u(gen) * 8.0f) * 0.5f, j);
                all.push_back(key);
                best.insertWatchingTies(key);
            }
            // The other way round: the low word reversed.
            std::vector<std::uint64_t> other = all;
            for (std::uint64_t& k : other)
                k = (k & ~std::uint64_t(0xffffffffu)) | (0xffffffffu - std::uint32_t(k));
            std::sort(other.begin(), other.end());
            other.resize(std::min(other.size(), kK));
            bool same = other.size() == best.count;
            for (std::size_t n = 0; same && n < best.count; ++n)
                same = 0xffffffffu - std::uint32_t(other[n]) == std::uint32_t(best.keys[n]);
            if (best.sawTie()) {
                ++seen;
            } else {
                ++unseen;
                QVERIFY2(same, qPrintable(QString("round %1: a tie decided the list unseen").arg(round)));
            }
        }
        QVERIFY2(seen > 50 && unseen > 50, qPrintable(QString("%1 rounds saw ties, %2 none").arg(seen).arg(unseen)));
    }

    void ranksFollowIds()
    {
        // Ids rising with the index: ranks are the indices, and nothing is kept.
        std::vector<AgentInfo> agents(5);
        for (std::size_t i = 0; i < agents.size(); ++i)
            agents[i].id = AgentId(10 + 3 * i);
        TieOrder ties;
        ties.build(agents);
        QVERIFY(ties.byIndex());
        QCOMPARE(ties.rank(3), 3u);
        QCOMPARE(ties.index(4), 4u);
        // Out of order: each agent's rank is its place by id, and back.
        const AgentId ids[] = {40, 7, 19, 3, 25};
        for (std::size_t i = 0; i < 5; ++i)
            agents[i].id = ids[i];
        ties.build(agents);
        QVERIFY(!ties.byIndex());
        const std::uint32_t ranks[] = {4, 1, 2, 0, 3};
        for (std::uint32_t i = 0; i < 5; ++i) {
            QCOMPARE(ties.rank(i), ranks[i]);
            QCOMPARE(ties.index(ranks[i]), i);
        }
    }

    void sweepFindsTheNearest_data()
    {
        QTest::addColumn<float>("cell");
        QTest::newRow("cells as large as the radius") << 3.0f;
        QTest::newRow("half the radius") << 1.5f;
        QTest::newRow("a little over a third of the radius") << 1.1f;
    }

    // Every agent's 8 nearest within 3 m, searched in the grid's order through one sweep
    // with the bound shrinking as the list fills, as the boids kernel does: the same as
    // brute force, each candidate offered at most once. The crowd has a sparse part, a
    // dense clump, agents stacked in one column and agents outside the bounds (clamped
    // into border cells).
    void sweepFindsTheNearest()
    {
        QFETCH(float, cell);
        const float r = 3.0f;
        std::mt19937 gen(7);
        std::uniform_real_distribution<float> wide(-24.0f, 24.0f), clump(-2.0f, 2.0f), height(0.0f, 40.0f);
        std::vector<glm::vec3> pos;
        for (int k = 0; k < 2500; ++k)
            pos.push_back({wide(gen), height(gen), wide(gen)});
        for (int k = 0; k < 1500; ++k)
            pos.push_back({5.0f + clump(gen), 20.0f + clump(gen), -3.0f + clump(gen)});
        for (int k = 0; k < 200; ++k)
            pos.push_back({-10.2f, 0.1f * float(k), 7.7f});
        for (int k = 0; k < 60; ++k)
            pos.push_back({27.0f + 0.05f * float(k), 10.0f, -26.0f - 0.1f * float(k)});
        NeighbourGrid grid;
        grid.configure({-25.0f, -25.0f}, {25.0f, 25.0f}, cell);
        grid.rebuild(pos, true);
        QCOMPARE(grid.order().size(), pos.size());
        NeighbourGrid::Sweep sweep;
        std::size_t full = 0;
        for (const std::uint32_t i : grid.order()) {
            NearestList<kK> best;
            float bound = r * r;
            std::set<std::uint32_t> offered;
            bool twice = false;
            auto consider = [&](std::uint32_t j, const glm::vec3& q) {
                twice = twice || !offered.insert(j).second;
                const glm::vec3 d = q - pos[i];
                const float d2 = glm::dot(d, d);
                if (j == i || d2 > bound)
                    return;
                if (best.insert(nearestKey(d2, j)) && best.full())
                    bound = best.worstDistance2();
            };
            grid.forEachNearestSweep(pos[i], r, [&] { return bound; }, consider, sweep);
            QVERIFY2(!twice, "an agent was offered twice");
            const std::vector<std::uint64_t> expected = bruteNearest(pos, i, r);
            QCOMPARE(best.count, expected.size());
            QVERIFY2(std::equal(expected.begin(), expected.end(), best.keys.begin()),
                     qPrintable(QString("agent %1: not its nearest").arg(i)));
            full += best.full();
        }
        QVERIFY(full > pos.size() / 3);  // the dense part fills its lists and shrinks the bound
    }

    // The walkers' search (forEachNearest on a grid not sorted by height) sifts each row's
    // run by the bound four at a time before offering. It must drop only agents beyond the
    // bound and keep the order: on a lattice, where many lie at exactly the bound (whole
    // metres, so the distances are exact) and some stand higher (terrain), each query
    // offers, within the bound, exactly the sequence that an unbounded query offers less
    // those beyond it; and the sift does drop some. Then the k-nearest searches with a
    // shrinking bound find what brute force finds.
    void walkersSearchSiftsOnlyBeyondTheBound()
    {
        std::vector<glm::vec3> pos;
        for (int z = -12; z <= 12; ++z)
            for (int x = -12; x <= 12; ++x)
                pos.push_back({float(x), (x + z) % 5 == 0 ? 1.0f : 0.0f, float(z)});
        NeighbourGrid grid;
        grid.configure({-12.0f, -12.0f}, {12.0f, 12.0f}, 3.0f);
        grid.rebuild(pos);
        const float r = 3.0f;
        std::size_t unbounded = 0, bounded = 0, atTheBound = 0;
        for (std::size_t i = 0; i < pos.size(); ++i) {
            auto within = [&](std::uint32_t j, float bound) {
                const glm::vec3 d = pos[j] - pos[i];
                return glm::dot(d, d) <= bound;
            };
            std::vector<std::uint32_t> all, sifted;
            grid.forEachNearest(pos[i], r, [] { return INFINITY; }, [&](std::uint32_t j, const glm::vec3&) {
                all.push_back(j);
            });
            const float bound = 4.0f;
            grid.forEachNearest(pos[i], r, [&] { return bound; }, [&](std::uint32_t j, const glm::vec3& q) {
                QCOMPARE(q, pos[j]);
                sifted.push_back(j);
            });
            std::vector<std::uint32_t> expected, kept;
            for (const std::uint32_t j : all)
                if (within(j, bound))
                    expected.push_back(j);
            for (const std::uint32_t j : sifted)
                if (within(j, bound))
                    kept.push_back(j);
            QCOMPARE(kept, expected);
            unbounded += all.size();
            bounded += sifted.size();
            for (const std::uint32_t j : expected) {
                const glm::vec3 d = pos[j] - pos[i];
                atTheBound += glm::dot(d, d) == bound;
            }
            // The nearest 8 with the bound shrinking as the list fills.
            NearestList<kK> best;
            float shrinking = r * r;
            grid.forEachNearest(pos[i], r, [&] { return shrinking; }, [&](std::uint32_t j, const glm::vec3& q) {
                const glm::vec3 d = q - pos[i];
                const float d2 = glm::dot(d, d);
                if (j == i || d2 > shrinking)
                    return;
                if (best.insert(nearestKey(d2, j)) && best.full())
                    shrinking = best.worstDistance2();
            });
            const std::vector<std::uint64_t> nearest = bruteNearest(pos, i, r);
            QCOMPARE(best.count, nearest.size());
            QVERIFY(std::equal(nearest.begin(), nearest.end(), best.keys.begin()));
        }
        QVERIFY(atTheBound > pos.size());  // most agents have neighbours at exactly the bound
        QVERIFY2(bounded < unbounded / 2, qPrintable(QString("%1 of %2 offered").arg(bounded).arg(unbounded)));
    }

    void flockIsUnchanged_data()
    {
        QTest::addColumn<float>("spacing");
        QTest::addColumn<int>("steps");
        QTest::addColumn<bool>("twoTypes");
        QTest::addColumn<float>("viewDeg");  // 0: the scenario's (300 degrees)
        QTest::newRow("packed, overlapping") << 0.38f << 30 << false << 0.0f;
        QTest::newRow("the bench flock, gathering") << 0.0f << 200 << false << 0.0f;
        QTest::newRow("two bird types mixed") << 0.0f << 100 << true << 0.0f;
        // The view cone's other cases: under 180 degrees, and all round.
        QTest::newRow("narrow view, packed") << 0.38f << 30 << false << 100.0f;
        QTest::newRow("all-round view, packed") << 0.38f << 30 << false << 360.0f;
    }

    void flockIsUnchanged()
    {
        QFETCH(float, spacing);
        QFETCH(int, steps);
        QFETCH(bool, twoTypes);
        QFETCH(float, viewDeg);
        Scene s = makeFlockScenario(1500, 3);
        if (spacing > 0.0f)
            throng::test::packOnLattice(s, spacing);
        if (viewDeg > 0.0f)
            s.agentTypes[0].viewAngleDeg = viewDeg;
        if (twoTypes) {
            // Every third bird a swift: faster, matching its neighbours' speed, neither
            // wandering nor pursuing. The grid-order path steers four or eight birds at a
            // time, so its lanes then hold both types, with behaviours on in some lanes only.
            AgentType swift = s.agentTypes[0];
            swift.name = "swift";
            swift.maxSpeed = 16.0f;
            swift.maxForce = 30.0f;
            swift.behaviours = {{"separation", 1.5f, {{"range", "", {0.8f}}}},
                                {"alignment", 1.5f, {{"match_speed", "true", {}}}},
                                {"cohesion", 0.5f, {}},
                                {"containment", 4.0f, {}}};
            s.agentTypes.push_back(swift);
            for (std::size_t k = 1; k < s.agents.size(); k += 3)
                s.agents[k].type = swift.name;
        }
        checkSame(s, steps);
    }

    // Walkers: `cross` (the agents of a circle meet in a jam at its centre).
    void crowdIsUnchanged() { checkSame(makeCrossScenario(600), 900, false); }

    // The kernel steers eight boids at once exactly where the CPU has AVX2, unless told
    // not to; flockIsUnchanged compares both widths with the plain path.
    void steersEightWhereTheCpuCan()
    {
        const Scene s = makeFlockScenario(100, 3);
#if defined(__x86_64__)
        const bool avx2 = __builtin_cpu_supports("avx2");
#else
        const bool avx2 = false;
#endif
        QCOMPARE(World::canSteerEight(), avx2);
        QCOMPARE(World(s).boidLanes(), avx2 ? 8 : 4);
        WorldOptions four;
        four.steerEight = false;
        QCOMPARE(World(s, four).boidLanes(), 4);
    }

private:
    // With the sweep (1 and 2 threads; steering eight boids at once where the CPU can, and
    // four) and without it (1 thread): the same bits, and the same overlap count.
    // (bothWidths false: walkers only, whom the width does not touch.)
    void checkSame(const Scene& s, int steps, bool bothWidths = true)
    {
        const throng::test::RunBits plain = run(s, false, 1, steps);
        for (int threads : {1, 2}) {
            for (bool eight : {true, false}) {
                if (!eight && !bothWidths)
                    continue;
                const throng::test::RunBits swept = run(s, true, threads, steps, eight);
                QVERIFY2(plain.sameStateAs(swept),
                         qPrintable(QString("%1 threads, steerEight %2: the sweep changed the result")
                                        .arg(threads)
                                        .arg(eight ? "on" : "off")));
                QCOMPARE(swept.overlaps, plain.overlaps);
            }
        }
    }
};

THRONG_REGISTER_TEST(TestNeighbourSweep)
#include "TestNeighbourSweep.moc"
