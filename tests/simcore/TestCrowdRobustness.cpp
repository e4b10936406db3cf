// The runtime under the abuse crowd libraries are reported to break on: agents spawned on
// top of each other (RVO2 and DetourCrowd users see them shot apart), extreme parameters
// (NaN positions in Godot and Menge), agents pressing into walls at top speed, and runs
// that differ between thread counts or ignore the seed.
#include "CrowdChecks.h"
#include "TestRegistry.h"

#include <QTest>

#include <cmath>
#include <string>

using namespace throng::sim;
using namespace throng::test::crowd;

namespace {

constexpr int kFps = 24;


// 600 placed fliers (more than two of the step's 256-agent chunks, so two threads share the
// work) with no spawn or speed variation: the seed reaches the run only through wander.
Scene flock()
{
    std::string yaml = R"(throng: 1
settings: {fps: 24, seed: 7}
agent_types:
  - name: bird
    kind: flier
    radius: 0.15
    max_speed: 6
    min_speed: 2
    max_force: 8
    perception: 3
    view_angle: 300
    variation: {speed: [1, 1], phase: [0, 0]}
    behaviours: {wander: 1, separation: 1.5, alignment: 0.5, cohesion: 0.5}
agents:
  columns: [id, type, x, y, z, heading]
  rows: |
)";
    for (int k = 0; k < 600; ++k)
        yaml += "    " + std::to_string(k + 1) + " bird " + std::to_string(0.8f * float(k % 30)) + " " +
                std::to_string(5.0f + 0.5f * float(k % 3)) + " " + std::to_string(0.8f * float(k / 30)) + " " +
                std::to_string((k * 37) % 360) + "\n";
    return parse(yaml);
}

}  // namespace

class TestCrowdRobustness : public QObject {
    Q_OBJECT
private slots:
    void overlappingSpawnSeparatesWithoutABurst()
    {
        // 20 agents within 4 cm of the origin (two exactly coincident) and one standing
        // alone 10 m away. No goals: the only motion is getting out of each other's way.
        std::string yaml = R"(throng: 1
agent_types:
  - {name: walker, radius: 0.3, max_speed: 1.4, max_force: 3, variation: {speed: [1, 1]}}
agents:
  - {id: 100, type: walker, position: [10, 0]}
  - {id: 101, type: walker, position: [0, 0]}
  - {id: 102, type: walker, position: [0, 0]}
)";
        for (int k = 1; k < 19; ++k)
            yaml += "  - {id: " + std::to_string(k) + ", type: walker, position: [" +
                    std::to_string(0.002f * float(k) * std::cos(float(k))) + ", " +
                    std::to_string(0.002f * float(k) * std::sin(float(k))) + "]}\n";
        const Scene s = parse(yaml);
        World world(s, kSerial);
        QCOMPARE(world.agentCount(), std::size_t(21));
        const glm::vec3 loner = world.positions()[0];
        float maxSpeed = 0.0f, maxStepSpeed = 0.0f, mismatch = 0.0f;
        for (int step = 0; step < kFps * 10; ++step) {
            const std::vector<glm::vec3> before = copyPositions(world);
            world.step();
            for (std::size_t i = 1; i < world.agentCount(); ++i) {
                const float reported = glm::length(world.velocities()[i]);
                const float moved = glm::distance(before[i], world.positions()[i]) / world.dt();
                maxSpeed = std::max(maxSpeed, reported);
                maxStepSpeed = std::max(maxStepSpeed, moved);
                mismatch = std::max(mismatch, std::fabs(moved - reported));
            }
            QCOMPARE(world.positions()[0], loner);
        }
        const std::size_t left = overlapsBeyond(world, 0.01f);
        qInfo("spawn burst: max reported speed %.3f m/s, max step speed %.3f m/s, largest difference %.3f m/s, "
              "overlaps left %zu",
              double(maxSpeed), double(maxStepSpeed), double(mismatch), left);
        QCOMPARE(glm::length(world.velocities()[0]), 0.0f);
        QVERIFY2(maxSpeed <= 1.4f + 0.01f, qPrintable(QString("reported speed reached %1 m/s (max 1.4)").arg(maxSpeed)));
        QVERIFY2(maxStepSpeed <= 1.4f + 0.01f,
                 qPrintable(QString("an agent moved %1 m/s in one step (max 1.4)").arg(maxStepSpeed)));
        // The exported speed (and so the walk or idle clip) is the speed the agent moves at.
        QVERIFY2(mismatch <= 0.01f, qPrintable(QString("reported speed and motion differ by %1 m/s").arg(mismatch)));
        QVERIFY2(left == 0, qPrintable(QString("%1 pairs still overlap after 10 s").arg(left)));
    }

    void flockIsDeterministicForThreadsAndSeeds()
    {
        const Scene s = flock();
        const int steps = kFps * 5;
        const std::uint64_t one = runHash(s, 1, steps);
        QCOMPARE(runHash(s, 2, steps), one);
        QCOMPARE(runHash(s, 1, steps), one);
        QCOMPARE(runHash(s, 2, steps), one);
        // Another seed changes the wander, so the frames.
        const std::uint64_t other = runHash(s, 2, steps, 8);
        QVERIFY(other != one);
        QCOMPARE(runHash(s, 1, steps, 8), other);
    }

    void extremeParametersStayFiniteForALongRun()
    {
        // Zero top speed, a force near FLT_MAX on a mass near zero, bodies on top of each
        // other, bodies exactly on a wall line or its end, leaders that are themselves
        // coincident, and a flier whose stall speed is above its top speed.
        Scene s = parse(R"(throng: 1
agent_types:
  - {name: statue, max_speed: 0}
  - {name: brute, max_speed: 50, max_force: 1.0e30, mass: 1.0e-6}
  - {name: extreme, max_speed: 1000, max_force: 3.0e38, mass: 1.0e-30}
  - name: stall
    kind: flier
    radius: 0.15
    max_speed: 2
    min_speed: 1
    variation: {speed: [1, 1]}
    behaviours: {wander: 1, separation: 1, cohesion: 1}
goals:
  - {name: across, position: [0, 8]}
  - {name: origin, position: [0, 0]}
walls:
  - {points: [[-5, 3], [5, 3]]}
  - {points: [[0, -5], [0, -1]]}
agents:
  - {id: 1, type: statue, position: [0, 0]}
  - {id: 2, type: statue, position: [0, 0]}
  - {id: 3, type: brute, position: [0, 0], goal: across}
  - {id: 4, type: brute, position: [0, 0], goal: across}
  - {id: 5, type: extreme, position: [0, 0], goal: across}
  - {id: 6, type: extreme, position: [0, 0], goal: origin}
  - {id: 7, type: brute, position: [0, 3], goal: across}
  - {id: 8, type: extreme, position: [-5, 3], goal: across}
  - {id: 9, type: statue, position: [2.5, 3]}
  - {id: 10, type: brute, position: [0, -3], goal: origin}
  - {id: 11, type: brute, position: [0, 3], leader: 3}
  - {id: 12, type: extreme, position: [5, 3], leader: 5}
  - {id: 13, type: stall, position: [0, 2, 0]}
  - {id: 14, type: stall, position: [0, 2, 0]}
  - {id: 15, type: stall, position: [20, 4, 20]}
)");
        // The reader refuses min_speed above max_speed; a scene built in code can still have it.
        s.agentTypes[3].minSpeed = 10.0f;
        const std::vector<WallSegment2> walls = wallSegments(s);
        World world(s, kSerial);
        const std::size_t lone = 14;  // the flier nobody touches
        const float startSpeed = glm::length(world.velocities()[lone]);
        float flierMax = 0.0f, flierMin = INFINITY;
        std::size_t badSteps = 0, crossingsAfterFirst = 0;
        for (int step = 0; step < 2000; ++step) {
            const std::vector<glm::vec3> before = copyPositions(world);
            world.step();
            bool bad = false;
            for (std::size_t i = 0; i < world.agentCount(); ++i)
                bad = bad || !finite(world.positions()[i]) || !finite(world.velocities()[i]) ||
                      !finite(world.forwards()[i]);
            badSteps += bad;
            // Walkers only: fliers pass over walls.
            for (std::size_t i = 0; step > 0 && i < 12; ++i)
                for (const WallSegment2& w : walls)
                    crossingsAfterFirst += crosses(xz(before[i]), xz(world.positions()[i]), w.a, w.b);
            flierMax = std::max(flierMax, glm::length(world.velocities()[lone]));
            flierMin = std::min(flierMin, glm::length(world.velocities()[lone]));
        }
        qInfo("extreme: %zu steps with non-finite state, counter %llu, walker crossings after step 1: %zu, lone flier "
              "speed %.3f m/s at the start, %.3f..%.3f m/s after",
              badSteps, static_cast<unsigned long long>(world.counters().nonFiniteValues), crossingsAfterFirst,
              double(startSpeed), double(flierMin), double(flierMax));
        QCOMPARE(badSteps, std::size_t(0));
        QCOMPARE(world.counters().nonFiniteValues, 0u);
        // Starting on a wall line is allowed; crossing one afterwards is not.
        QCOMPARE(crossingsAfterFirst, std::size_t(0));
        // Stall speed above top speed: top speed wins from the first frame on, and the
        // flier keeps flying at it.
        QVERIFY2(startSpeed <= 2.0f + 1e-3f, qPrintable(QString("the flier starts at %1 m/s (max 2)").arg(startSpeed)));
        QVERIFY2(flierMax <= 2.0f + 1e-3f, qPrintable(QString("the flier reached %1 m/s (max 2)").arg(flierMax)));
        QVERIFY2(flierMin >= 2.0f - 1e-3f, qPrintable(QString("the flier slowed to %1 m/s").arg(flierMin)));
    }

    void fliersNeverFlyBelowTheGround()
    {
        // 30 birds wander from 1 to 3 m above flat ground (y = 0) for 30 s. A bird under
        // the ground shows through it in every render.
        std::string yaml = R"(throng: 1
settings: {fps: 24, seed: 5}
agent_types:
  - name: bird
    kind: flier
    radius: 0.15
    max_speed: 3
    min_speed: 1
    variation: {speed: [1, 1]}
    behaviours: {wander: 1, separation: 1}
agents:
)";
        for (int k = 0; k < 30; ++k)
            yaml += "  - {type: bird, position: [" + std::to_string(-4.0f + 1.5f * float(k % 6)) + ", " +
                    std::to_string(1.0f + 0.5f * float(k % 5)) + ", " + std::to_string(-3.0f + 1.5f * float(k / 6)) +
                    "], heading: " + std::to_string(k * 47 % 360) + "}\n";
        World world(parse(yaml), kSerial);
        std::size_t underground = 0;
        float lowest = INFINITY;
        for (int step = 0; step < kFps * 30; ++step) {
            world.step();
            for (std::size_t i = 0; i < world.agentCount(); ++i) {
                underground += world.positions()[i].y < 0.0f;
                lowest = std::min(lowest, world.positions()[i].y);
            }
        }
        qInfo("fliers: %zu agent-steps below the ground, lowest y %.2f m", underground, double(lowest));
        QVERIFY2(underground == 0, qPrintable(QString("fliers were below the ground on %1 agent-steps, down to y = %2 m")
                                                  .arg(underground).arg(lowest)));
    }

    void walledBoxHoldsAgentsAtTopSpeed_data()
    {
        QTest::addColumn<QString>("bounds");
        QTest::addColumn<float>("sprintSpeed");
        QTest::newRow("walls, 8 m/s") << QString("{min: [-50, -50], max: [50, 50]}") << 8.0f;
        QTest::newRow("walls and containment, 8 m/s") << QString("{min: [-5, -5], max: [5, 5]}") << 8.0f;
        QTest::newRow("walls, 30 m/s (1.25 m per step)") << QString("{min: [-50, -50], max: [50, 50]}") << 30.0f;
    }

    void walledBoxHoldsAgentsAtTopSpeed()
    {
        // A 10 m box: 20 agents wander in it at 3 m/s and 20 sprint for a goal outside it,
        // pressing into the wall at full speed for the whole run.
        QFETCH(QString, bounds);
        QFETCH(float, sprintSpeed);
        const std::string yaml = "throng: 1\nsettings: {fps: 24, seed: 9, bounds: " + bounds.toStdString() + R"(}
agent_types:
  - name: roamer
    radius: 0.3
    max_speed: 3
    max_force: 6
    variation: {speed: [1, 1]}
    behaviours: {wander: 1, wall_following: 2, containment: 1, separation: 1}
  - {name: sprinter, radius: 0.3, max_speed: )" + std::to_string(sprintSpeed) + R"(, max_force: 60, variation: {speed: [1, 1]}}
goals:
  - {name: outside, position: [20, 3], radius: 1}
walls:
  - {points: [[-5, -5], [5, -5], [5, 5], [-5, 5], [-5, -5]]}
groups:
  - {name: roamers, type: roamer, count: 20, rect: {min: [-4, -4], max: [4, 4]}}
  - {name: sprinters, type: sprinter, count: 20, rect: {min: [-4, -4], max: [4, 4]}, goal: outside}
)";
        const Scene s = parse(yaml);
        const std::vector<WallSegment2> walls = wallSegments(s);
        World world(s, kSerial);
        std::size_t crossings = 0, outside = 0;
        double roamerSpeedSum = 0.0;
        std::size_t roamerSamples = 0;
        for (int step = 0; step < kFps * 15; ++step) {
            const std::vector<glm::vec3> before = copyPositions(world);
            world.step();
            crossings += wallCrossings(before, world, walls);
            for (std::size_t i = 0; i < world.agentCount(); ++i) {
                const glm::vec3 p = world.positions()[i];
                const float limit = 5.0f - world.radii()[i] + 1e-3f;
                outside += std::fabs(p.x) > limit || std::fabs(p.z) > limit;
                if (i < 20) {
                    roamerSpeedSum += glm::length(world.velocities()[i]);
                    ++roamerSamples;
                }
            }
        }
        const double roamerMean = roamerSpeedSum / double(roamerSamples);
        qInfo("box %s at %.0f m/s: %llu agent-steps, crossings %zu / %llu, bodies into the wall %zu, roamer mean "
              "speed %.2f m/s",
              qPrintable(bounds), double(sprintSpeed), static_cast<unsigned long long>(world.counters().agentSteps),
              crossings, static_cast<unsigned long long>(world.counters().wallPenetrations), outside, roamerMean);
        QVERIFY(world.counters().agentSteps >= 10000u);
        QCOMPARE(crossings, std::size_t(0));
        QCOMPARE(world.counters().wallPenetrations, 0u);
        QCOMPARE(outside, std::size_t(0));
        // The roamers really moved fast (wander keeps them near their 3 m/s).
        QVERIFY2(roamerMean > 1.5, qPrintable(QString("roamers averaged only %1 m/s").arg(roamerMean)));
    }
};

THRONG_REGISTER_TEST(TestCrowdRobustness)
#include "TestCrowdRobustness.moc"
