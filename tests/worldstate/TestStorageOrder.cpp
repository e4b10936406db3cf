// The order a World stores its agents in changes no agent's result: the same birds
// numbered row by row or up each column (the grid's own order), and the cross's walkers,
// with and without their 40-node brains, placed in a shuffled order, end every checked
// frame bit for bit where they did, agent by agent (matched by id), with the same
// counters; so do birds and walkers on exact lattices, stored in reverse, where
// neighbours at equal distances must be chosen among by id (TieOrder.h). The grid's
// order in memory is worth a quarter of the flock's step at a million birds
// (throng-bench-flock --by-column); this is what lets a World store its agents in any
// order it likes.
#include "TestRegistry.h"

#include "simcore/scenarios/BenchScenarios.h"
#include "simcore/world/GridOrder.h"
#include "simcore/world/World.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <random>
#include <tuple>
#include <vector>

using namespace throng;
using namespace throng::sim;

namespace {

// Each agent's frame by id.
std::map<AgentId, AgentFrame> byId(const World& world)
{
    std::vector<AgentFrame> frames;
    world.snapshot(frames);
    std::map<AgentId, AgentFrame> out;
    for (std::size_t i = 0; i < frames.size(); ++i)
        out[world.id(i)] = frames[i];
    return out;
}

bool sameBits(const AgentFrame& a, const AgentFrame& b)
{
    return std::memcmp(&a.position, &b.position, sizeof a.position) == 0 &&
           std::memcmp(&a.headingRad, &b.headingRad, sizeof a.headingRad) == 0 &&
           std::memcmp(&a.speed, &b.speed, sizeof a.speed) == 0 && a.clip == b.clip && a.arrived == b.arrived &&
           a.out == b.out;
}

// Steps both Worlds to each of `frames` and compares every agent there; how many agents
// moved more than 1 cm between the first and the last check (so the test is not
// comparing a crowd that stands still).
int compareRuns(const Scene& a, const Scene& b, std::vector<int> frames)
{
    World one(a), two(b);
    const std::map<AgentId, AgentFrame> start = byId(one);
    int done = 0;
    for (const int frame : frames) {
        for (; done < frame; ++done) {
            one.step();
            two.step();
        }
        const std::map<AgentId, AgentFrame> x = byId(one), y = byId(two);
        if (x.size() != y.size())
            qFatal("frame %d: %zu agents against %zu", frame, x.size(), y.size());
        for (const auto& [id, f] : x) {
            const auto it = y.find(id);
            if (it == y.end() || !sameBits(f, it->second))
                qFatal("frame %d: agent %u differs", frame, unsigned(id));
        }
    }
    const StepCounters &ca = one.counters(), &cb = two.counters();
    if (ca.overlappingPairs != cb.overlappingPairs || ca.wallPenetrations != cb.wallPenetrations ||
        ca.obstaclePenetrations != cb.obstaclePenetrations || ca.agentSteps != cb.agentSteps ||
        ca.peakDensity != cb.peakDensity || ca.peakDensityTimeS != cb.peakDensityTimeS)
        qFatal("the counters differ: %llu against %llu overlapping pairs, peak density %g against %g",
               (unsigned long long)ca.overlappingPairs, (unsigned long long)cb.overlappingPairs, double(ca.peakDensity),
               double(cb.peakDensity));
    int moved = 0;
    for (const auto& [id, f] : byId(one))
        moved += glm::length(f.position - start.at(id).position) > 0.01f;
    return moved;
}

Scene shuffled(Scene scene, unsigned seed)
{
    std::mt19937 rng(seed);
    std::shuffle(scene.agents.begin(), scene.agents.end(), rng);
    return scene;
}

}  // namespace

class TestStorageOrder : public QObject {
    Q_OBJECT

private slots:
    void birdsNumberedByColumnFlyAsByRow()
    {
        constexpr std::uint32_t kBirds = 8000;  // a cube: the same lattice either way
        const Scene rows = makeFlockScenario(kBirds, 3);
        const Scene columns = makeFlockScenario(kBirds, 3, FlockNumbering::ByColumn);
        // The same birds: each id at the same place, with the same heading and leader, in
        // another order.
        QCOMPARE(rows.agents.size(), columns.agents.size());
        std::map<AgentId, const Agent*> placed;
        for (const Agent& a : rows.agents)
            placed[a.id] = &a;
        std::size_t moved = 0;
        for (std::size_t k = 0; k < columns.agents.size(); ++k) {
            const Agent& a = columns.agents[k];
            QVERIFY(placed.count(a.id));
            QCOMPARE(a.position, placed[a.id]->position);
            QCOMPARE(a.headingDeg, placed[a.id]->headingDeg);
            QCOMPARE(a.leader, placed[a.id]->leader);
            moved += rows.agents[k].id != a.id;
        }
        QVERIFY2(moved > kBirds * 9 / 10, "the two orders should differ for almost every bird");
        QVERIFY(World(rows).usesBoidKernel(0));
        QVERIFY(compareRuns(rows, columns, {1, 24, 120, 240}) > int(kBirds) * 9 / 10);
    }

    void fliersPutInTheGridsOrderFlyAsPlaced()
    {
        // What throng-cli run and bench do to a scene of 65,536 placed agents or more
        // with fliers, here from 1,000 on.
        const Scene flock = makeFlockScenario(8000, 3);
        Scene ordered = flock;
        QVERIFY(orderPlacedForGrid(ordered, 1000));
        QCOMPARE(ordered.agents.size(), flock.agents.size());
        // Every agent is still there, with all it had, and now in the grid's order: rows
        // of 3 m cells (the birds' perception) along z, cells along x, then up.
        std::map<AgentId, const Agent*> placed;
        for (const Agent& a : flock.agents)
            placed[a.id] = &a;
        const glm::vec2 min = flock.settings.boundsMin;
        auto key = [&](const Agent& a) {
            return std::tuple(std::floor((a.position.z - min.y) / 3.0f), std::floor((a.position.x - min.x) / 3.0f),
                              a.position.y);
        };
        std::size_t moved = 0, outOfOrderBefore = 0;
        for (std::size_t k = 0; k < ordered.agents.size(); ++k) {
            const Agent& a = ordered.agents[k];
            QVERIFY(placed.count(a.id));
            const Agent& was = *placed[a.id];
            QVERIFY(a.position == was.position && a.headingDeg == was.headingDeg && a.leader == was.leader &&
                    a.type == was.type);
            placed.erase(a.id);
            moved += flock.agents[k].id != a.id;
            if (k > 0) {
                QVERIFY2(!(key(a) < key(ordered.agents[k - 1])), qPrintable(QString("agent %1 out of order").arg(k)));
                outOfOrderBefore += key(flock.agents[k]) < key(flock.agents[k - 1]);
            }
        }
        QVERIFY(placed.empty());
        QVERIFY2(moved > 7000 && outOfOrderBefore > 1000,
                 qPrintable(QString("%1 moved, %2 out of order before").arg(moved).arg(outOfOrderBefore)));
        QVERIFY(compareRuns(flock, ordered, {1, 24, 120}) > 7000);

        // Below the threshold, and without fliers, a scene keeps its order.
        Scene small = flock;
        QVERIFY(!orderPlacedForGrid(small));
        QVERIFY(small.agents == flock.agents);
        const Scene cross = makeCrossScenario(2000, 7);
        Scene walkers = cross;
        QVERIFY(!orderPlacedForGrid(walkers, 1000));
        QVERIFY(walkers.agents == cross.agents);
    }

    void birdsOnAnExactLatticeChooseAmongEqualNeighboursById()
    {
        // 4,096 birds on an exact lattice 1.5 m apart, all heading the same way: each has 6
        // neighbours 1.5 m off and 12 at 2.12 m in its 3 m perception, so which of the 12
        // (those in its view cone) complete its 8 nearest is a choice among equal
        // distances. Stored in reverse,
        // the birds must choose as they do stored in order: by id, not by where they lie
        // in memory (TieOrder.h).
        Scene lattice = makeFlockScenario(4096, 3);
        std::size_t k = 0;
        for (Agent& a : lattice.agents) {
            const int x = int(k % 16), y = int(k / 16 % 16), z = int(k / 256);
            a.position = glm::vec3(-12.0f + 1.5f * float(x), 20.0f + 1.5f * float(y), -12.0f + 1.5f * float(z));
            a.headingDeg = 0.0f;
            ++k;
        }
        Scene reversed = lattice;
        std::reverse(reversed.agents.begin(), reversed.agents.end());
        QVERIFY(World(lattice).usesBoidKernel(0));
        QVERIFY(compareRuns(lattice, reversed, {1, 2, 24, 120}) > 4000);
    }

    void walkersOnAnExactLatticeChooseAmongEqualNeighboursById()
    {
        // 400 walkers on a square lattice 1.5 m apart, each bound for its own goal across
        // the middle: neighbours at equal distances on every side. Stored in reverse, they
        // walk as stored in order, through the walker kernel's search and, with brains,
        // through the brain's (gatherNeighbours).
        for (const bool brains : {false, true}) {
            Scene lattice = brains ? makeCrossBrainScenario(400, 5) : makeCrossScenario(400, 5);
            std::size_t k = 0;
            for (Agent& a : lattice.agents) {
                a.position = glm::vec3(-14.25f + 1.5f * float(k % 20), 0.0f, -14.25f + 1.5f * float(k / 20));
                a.headingDeg = 90.0f * float(k % 4);
                ++k;
            }
            Scene reversed = lattice;
            std::reverse(reversed.agents.begin(), reversed.agents.end());
            QVERIFY(World(lattice).usesWalkKernel(0));
            QVERIFY(compareRuns(lattice, reversed, {1, 2, 24, 120}) > 350);
        }
    }

    void shuffledWalkersWalkAsPlaced()
    {
        // The cross: 2,000 walkers on rings, each walking through the middle to the far side.
        const Scene cross = makeCrossScenario(2000, 7);
        QCOMPARE(cross.agents.size(), std::size_t(2000));
        QVERIFY(World(cross).usesWalkKernel(0));
        QVERIFY(compareRuns(cross, shuffled(cross, 11), {1, 60, 300, 600}) > 1900);
    }

    void shuffledWalkersWithBrainsWalkAsPlaced()
    {
        const Scene cross = makeCrossBrainScenario(600, 7);
        QVERIFY(World(cross).agentBrainEvaluator(0) != nullptr);
        QVERIFY(compareRuns(cross, shuffled(cross, 13), {1, 48, 240}) > 550);
    }
};

THRONG_REGISTER_TEST(TestStorageOrder)
#include "TestStorageOrder.moc"
