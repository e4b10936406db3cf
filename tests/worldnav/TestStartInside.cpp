// Agents that start where no body fits, and goals no body can reach (issue 23, finding 8):
// a user painted walkers over a crate and a pillar; those in the box obstacle stayed
// trapped inside it for the whole shot, and one in a circle popped 2.3 m out in one frame.
// A* walkers sent to a goal in a closed room shuffled against its walls forever. Now an
// agent inside is walked out along the shortest way at its own pace, and a walker with no
// way at all waits.
#include "NavRig.h"
#include "TestRegistry.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <QTest>

#include <cmath>

using namespace throng::sim;
using throng::test::parse;

namespace {

// A 3 m x 2 m crate turned 20 degrees at (0, 0), a pillar of radius 2.5 m at (10, 0), a goal
// to the north-east. Agents 1-3 start inside the crate (one at its centre, one near a
// face, one in a corner), 4 deep inside the pillar, 5 just inside the crate's face.
const char* kYard = R"(throng: 1
settings: {fps: 30, seed: 4, bounds: {min: [-20, -20], max: [30, 20]}}
agent_types:
  - {name: walker, radius: 0.3, max_speed: 1.2}
obstacles:
  - {name: crate, shape: box, center: [0, 0], size: [3, 2], angle: 20}
  - {name: pillar, shape: circle, center: [10, 0], radius: 2.5}
goals:
  - {name: gate, position: [20, -12], radius: 1.5}
agents:
  - {id: 1, type: walker, position: [0, 0, 0], goal: gate}
  - {id: 2, type: walker, position: [0.2, 0, 0.7], goal: gate}
  - {id: 3, type: walker, position: [-1.2, 0, -0.3], goal: gate}
  - {id: 4, type: walker, position: [10.2, 0, 0.1], goal: gate}
  - {id: 5, type: walker, position: [1.35, 0, -0.2], goal: gate}
)";

// How deep a body at p (radius r) lies in the crate or the pillar; <= 0 when clear.
float depthInside(glm::vec2 p, float r)
{
    const float a = glm::radians(20.0f);
    const glm::vec2 ax(std::cos(a), -std::sin(a)), az(std::sin(a), std::cos(a));
    const float px = 1.5f + r - std::fabs(glm::dot(p, ax)), pz = 1.0f + r - std::fabs(glm::dot(p, az));
    const float box = std::min(px, pz);
    const float circle = 2.5f + r - glm::distance(p, glm::vec2(10.0f, 0.0f));
    return std::max(box > 0.0f ? box : 0.0f, circle);
}

}  // namespace

class TestStartInside : public QObject {
    Q_OBJECT
private slots:
    void walkedOutSmoothlyThenOnToTheGoal()
    {
        World world(parse(kYard));
        QCOMPARE(world.agentCount(), std::size_t(5));
        for (std::size_t i = 0; i < 5; ++i) {
            const glm::vec2 p(world.positions()[i].x, world.positions()[i].z);
            QVERIFY2(depthInside(p, 0.3f) > 0.05f, "every agent starts inside");
            QVERIFY(world.isEscaping(i));
            QVERIFY(depthInside(world.escapeTo(i), 0.3f) <= 0.0f);
        }
        // The shortest way out of the pillar's centre region is about 2.3 m; at 1.2 m/s or
        // so that is 2 s. Nobody may move more than its top speed allows in a frame.
        std::vector<glm::vec3> last(world.positions().begin(), world.positions().end());
        std::vector<double> clearAt(5, -1.0);
        float biggestStep = 0.0f;
        while (world.timeS() < 60.0) {
            world.step();
            for (std::size_t i = 0; i < 5; ++i) {
                const glm::vec3 p = world.positions()[i];
                biggestStep = std::max(biggestStep, glm::distance(p, last[i]));
                last[i] = p;
                const float depth = depthInside({p.x, p.z}, 0.3f);
                if (clearAt[i] < 0.0 && depth <= 0.005f)
                    clearAt[i] = world.timeS();
                if (clearAt[i] >= 0.0)
                    QVERIFY2(depth <= 0.005f, qPrintable(QString("agent %1 back inside at %2 s").arg(i + 1).arg(world.timeS())));
            }
        }
        // 1.2 m/s with a speed factor up to 1.2: 0.048 m a frame at 30 fps.
        QVERIFY2(biggestStep <= 1.2f * 1.2f / 30.0f + 1e-4f, qPrintable(QString("a frame's move of %1 m").arg(biggestStep)));
        for (std::size_t i = 0; i < 5; ++i) {
            QVERIFY2(clearAt[i] >= 0.0 && clearAt[i] < 4.0, qPrintable(QString("agent %1 out at %2 s").arg(i + 1).arg(clearAt[i])));
            QVERIFY(!world.isEscaping(i));
            QVERIFY2(world.hasArrived(i), qPrintable(QString("agent %1 never reached the gate").arg(i + 1)));
        }
        // Walking out of the crate crossed its sides; that is no wall penetration.
        QCOMPARE(world.counters().wallPenetrations, std::uint64_t(0));
    }

    void groupsSpawnClearOfTheSet()
    {
        // 60 walkers spawned in a square that a pillar and a crate half fill: each member
        // drawn inside one is drawn again, so none starts inside; those drawn overlapping
        // an edge are pushed clear in the first step, by less than their radius.
        World world(parse(R"(throng: 1
settings: {fps: 24, seed: 9, bounds: {min: [-20, -20], max: [20, 20]}}
agent_types:
  - {name: walker, radius: 0.25, max_speed: 1.3}
obstacles:
  - {shape: circle, center: [0, 0], radius: 2}
  - {shape: box, center: [-3, 3], size: [2, 2]}
walls: [{points: [[-4, -1], [4, -1.5]]}]
goals:
  - {name: gate, position: [15, 0], radius: 2}
groups:
  - {name: painted, type: walker, count: 60, rect: {min: [-4, -4], max: [4, 4]}, goal: gate}
)"));
        QCOMPARE(world.agentCount(), std::size_t(60));
        std::vector<glm::vec3> start(world.positions().begin(), world.positions().end());
        for (std::size_t i = 0; i < world.agentCount(); ++i) {
            const glm::vec2 p(world.positions()[i].x, world.positions()[i].z);
            QVERIFY(!world.isEscaping(i));
            QVERIFY(glm::length(p) >= 2.0f);
            QVERIFY(!(std::fabs(p.x + 3.0f) < 1.0f && std::fabs(p.y - 3.0f) < 1.0f));
            QVERIFY(std::fabs(p.x) <= 4.0f && std::fabs(p.y) <= 4.0f);
        }
        world.step();
        for (std::size_t i = 0; i < world.agentCount(); ++i) {
            const glm::vec2 p(world.positions()[i].x, world.positions()[i].z);
            QVERIFY(glm::length(p) >= 2.0f + 0.25f - 0.01f);
            QVERIFY(!(std::fabs(p.x + 3.0f) < 1.24f && std::fabs(p.y - 3.0f) < 1.24f));
            QVERIFY(glm::distance(world.positions()[i], start[i]) <= 0.25f + 0.02f);
        }
    }

    void groupInsideABoxWalksOut()
    {
        // A group painted wholly inside a 6 m x 5 m block: no draw fits, so every member
        // walks out through the nearest face, up to 3 m, none faster than its own pace.
        World world(parse(R"(throng: 1
settings: {fps: 24, seed: 9, bounds: {min: [-20, -20], max: [20, 20]}}
agent_types:
  - {name: walker, radius: 0.25, max_speed: 1.3}
obstacles:
  - {shape: box, center: [0, 0], size: [6, 5], angle: 10}
goals:
  - {name: gate, position: [15, 0], radius: 2}
groups:
  - {name: buried, type: walker, count: 30, rect: {min: [-2, -1.5], max: [2, 1.5]}, goal: gate}
)"));
        for (std::size_t i = 0; i < world.agentCount(); ++i)
            QVERIFY(world.isEscaping(i));
        std::vector<glm::vec3> last(world.positions().begin(), world.positions().end());
        float biggestStep = 0.0f;
        while (world.timeS() < 6.0) {
            world.step();
            for (std::size_t i = 0; i < world.agentCount(); ++i) {
                biggestStep = std::max(biggestStep, glm::distance(world.positions()[i], last[i]));
                last[i] = world.positions()[i];
            }
        }
        QVERIFY2(biggestStep <= 1.3f * 1.2f / 24.0f + 1e-4f, qPrintable(QString::number(biggestStep)));
        const float a = glm::radians(10.0f);
        const glm::vec2 ax(std::cos(a), -std::sin(a)), az(std::sin(a), std::cos(a));
        for (std::size_t i = 0; i < world.agentCount(); ++i) {
            const glm::vec2 p(world.positions()[i].x, world.positions()[i].z);
            QVERIFY2(!world.isEscaping(i), qPrintable(QString("agent %1 still inside after 6 s").arg(i)));
            QVERIFY(std::fabs(glm::dot(p, ax)) >= 3.24f || std::fabs(glm::dot(p, az)) >= 2.74f);
        }
        throng::test::runUntil(world, 120.0, [](const World& w) { return throng::test::arrivedCount(w) == w.agentCount(); });
        QCOMPARE(throng::test::arrivedCount(world), world.agentCount());
    }

    void sameForOneAndTwoThreads()
    {
        // Walking out, hairpin progress and waiting keep a run bit-identical for any thread
        // count: the yard's escapers, followers of a path that turns back, A* walkers with
        // no way, and a crowd through a 1 m exit.
        const std::string yaml = std::string(kYard) + R"(  - {id: 6, type: walker, position: [-10, 0, 10], path: hairpin}
  - {id: 7, type: walker, position: [-10, 0, 11], path: hairpin}
  - {id: 8, type: planner, position: [-15, 0, -15], goal: vault}
paths:
  - {name: hairpin, radius: 1, points: [[-12, 10], [4, 10], [-12, 12]]}
walls:
  - {points: [[20, 2], [28, 2], [28, 8], [20, 8], [20, 2]]}
  - {points: [[-18, -3], [-18, -18], [-3, -18], [-3, -10.5]]}
  - {points: [[-3, -9.5], [-3, -3], [-18, -3]]}
groups:
  - {name: crowd, type: walker, count: 40, rect: {min: [-16, -16], max: [-6, -6]}, goal: door}
)";
        std::string scene = yaml;
        scene.replace(scene.find("goals:\n"), 7, "goals:\n  - {name: vault, position: [24, 5], radius: 1}\n"
                                                 "  - {name: door, position: [-3, -10], radius: 0.5, exit: true}\n");
        scene.replace(scene.find("agent_types:\n"), 13, "agent_types:\n  - {name: planner, radius: 0.3, navigation: astar}\n");
        WorldOptions one, two;
        one.threads = 1;
        two.threads = 2;
        World a(parse(scene), one), b(parse(scene), two);
        for (int k = 0; k < 30 * 40; ++k) {
            a.step();
            b.step();
        }
        std::size_t out = 0;
        for (std::size_t i = 0; i < a.agentCount(); ++i) {
            QCOMPARE(a.positions()[i], b.positions()[i]);
            out += a.isOut(i) ? 1 : 0;
        }
        QVERIFY2(out >= 30, qPrintable(QString::number(out)));
    }

    void astarWalkersWithNoWayWait()
    {
        // The goal lies in a closed room; A* walkers outside it have no way in. They stop
        // and wait where they stand; one already in the room walks to it.
        World world(parse(R"(throng: 1
settings: {fps: 24, seed: 2, bounds: {min: [-20, -20], max: [20, 20]}}
agent_types:
  - {name: planner, radius: 0.3, navigation: astar}
walls:
  - {points: [[4, -4], [12, -4], [12, 4], [4, 4], [4, -4]]}
goals:
  - {name: vault, position: [8, 0], radius: 1}
agents:
  - {id: 1, type: planner, position: [-10, 0, 0], goal: vault}
  - {id: 2, type: planner, position: [0, 0, 6], goal: vault}
  - {id: 3, type: planner, position: [-5, 0, -8], goal: vault}
  - {id: 4, type: planner, position: [6, 0, 2], goal: vault}
)"));
        std::vector<float> walked(4, 0.0f);
        std::vector<glm::vec3> last(world.positions().begin(), world.positions().end());
        while (world.timeS() < 60.0) {
            world.step();
            for (std::size_t i = 0; i < 4; ++i) {
                walked[i] += glm::distance(world.positions()[i], last[i]);
                last[i] = world.positions()[i];
            }
        }
        for (std::size_t i = 0; i < 3; ++i) {
            QVERIFY2(walked[i] < 0.5f, qPrintable(QString("walker %1 shuffled %2 m").arg(i + 1).arg(walked[i])));
            QVERIFY(!world.hasArrived(i));
        }
        QVERIFY(world.hasArrived(3));
        QCOMPARE(world.navigation().counters.sideSteps, std::uint64_t(0));
    }
};

THRONG_REGISTER_TEST(TestStartInside)
#include "TestStartInside.moc"
