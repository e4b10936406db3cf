// The fused walker kernel (WalkKernel.cpp) against the general steering path. The kernel
// calls the general path's functions for each behaviour and runs them in its own way (one
// pass over the neighbours, the blend's terms in the behaviour list's order, each type's
// gains worked out once), so the two must agree to the bit: on `cross` through its dense
// middle (arrival, separation, unaligned collision and reciprocal avoidance with
// keep-right), and on a crowd that also wanders, is held in by
// containment, stands still with nowhere to go, leaves by an exit and follows a path
// (which the kernel hands back to the general path), and on a two-way crowd between
// walls round pillars and a box (wall following, lateral and repulsive obstacle avoidance,
// the hard constraint). And it is bit-identical for 1 and 2 threads, and used only where
// it applies.
#include "TestRegistry.h"

#include "simcore/scenarios/BenchScenarios.h"
#include "simcore/world/World.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <cmath>
#include <cstring>
#include <string>

using namespace throng::sim;

namespace {

World makeWorld(const Scene& s, bool kernel, int threads = 1)
{
    WorldOptions o;
    o.threads = threads;
    o.walkKernel = kernel;
    return World(s, o);
}

bool sameState(const World& a, const World& b)
{
    const std::size_t bytes = a.agentCount() * sizeof(glm::vec3);
    return a.agentCount() == b.agentCount() && std::memcmp(a.positions().data(), b.positions().data(), bytes) == 0 &&
           std::memcmp(a.velocities().data(), b.velocities().data(), bytes) == 0 &&
           std::memcmp(a.forwards().data(), b.forwards().data(), bytes) == 0 &&
           std::memcmp(a.ups().data(), b.ups().data(), bytes) == 0;
}

BehaviourWeight behaviour(const char* name, float weight)
{
    BehaviourWeight b;
    b.behaviour = name;
    b.weight = weight;
    return b;
}

// 24 m x 24 m of open ground: default walkers crossing to goals (some by the bounds, one
// an exit), some with nowhere to go, some on a path; ramblers that wander, seek and are
// held in by containment.
Scene mixedCrowd()
{
    Scene s;
    s.settings.seed = 11;
    s.settings.boundsMin = glm::vec2(-12.0f);
    s.settings.boundsMax = glm::vec2(12.0f);
    AgentType walker;
    walker.name = "walker";
    s.agentTypes.push_back(walker);
    AgentType rambler;
    rambler.name = "rambler";
    rambler.viewAngleDeg = 180.0f;
    rambler.behaviours = {behaviour("containment", 3.0f), behaviour("separation", 1.0f),
                          behaviour("unaligned_collision_avoidance", 1.0f), behaviour("seek", 0.5f),
                          behaviour("wander", 1.0f), behaviour("reciprocal_avoidance", 1.0f)};
    s.agentTypes.push_back(rambler);
    for (int g = 0; g < 8; ++g) {
        Goal goal;
        goal.name = "g";  // appended: GCC 12 warns falsely on "g" + to_string (-Wrestrict)
        goal.name += std::to_string(g);
        const float a = 0.785398f * float(g);
        goal.position = glm::vec2(10.5f * std::cos(a), 10.5f * std::sin(a));
        goal.radiusM = 1.0f;
        goal.exit = g == 3;
        s.goals.push_back(goal);
    }
    Path path;
    path.name = "round";
    path.points = {{-6.0f, -6.0f}, {6.0f, -6.0f}, {6.0f, 6.0f}};
    s.paths.push_back(path);
    std::uint32_t id = 1;
    for (int row = 0; row < 18; ++row)
        for (int col = 0; col < 18; ++col, ++id) {
            Agent a;
            a.id = id;
            const bool ramble = (row + col) % 5 == 0;
            a.type = ramble ? "rambler" : "walker";
            a.position = glm::vec3(-8.5f + 1.0f * float(col) + 0.1f * std::sin(float(id)), 0.0f,
                                   -8.5f + 1.0f * float(row) + 0.1f * std::cos(float(id)));
            a.headingDeg = float(id * 37 % 360);
            if (id % 7 == 0)
                a.path = "round";
            else if (id % 6 != 0 || ramble)
                a.goal = std::string("g").append(std::to_string(id % 8));
            if (ramble && id % 3 == 0)
                a.goal.clear();  // wanders only
            s.agents.push_back(a);
        }
    return s;
}

// A 40 m corridor with a kink in its north wall, two-way flow round four pillars and a
// box in the middle: default walkers (wall following, lateral obstacle avoidance) and
// "dodgers" that push off obstacles (the repulsive answer) and have no reciprocal
// avoidance, so the walls' hard constraint has work to do.
Scene walledCrowd()
{
    Scene s;
    s.settings.seed = 5;
    s.settings.boundsMin = glm::vec2(-22.0f, -8.0f);
    s.settings.boundsMax = glm::vec2(22.0f, 8.0f);
    AgentType walker;
    walker.name = "walker";
    s.agentTypes.push_back(walker);
    AgentType dodger;
    dodger.name = "dodger";
    dodger.maxSpeed = 2.2f;
    BehaviourWeight avoid = behaviour("obstacle_avoidance", 2.0f);
    avoid.params.push_back({"response", "repulsive", {}});
    dodger.behaviours = {behaviour("arrival", 1.0f), behaviour("separation", 1.0f), avoid,
                         behaviour("wall_following", 2.0f), behaviour("unaligned_collision_avoidance", 1.0f)};
    s.agentTypes.push_back(dodger);
    Wall north;
    north.name = "north";
    north.points = {{-20.0f, -4.0f}, {-2.0f, -4.0f}, {0.0f, -3.2f}, {2.0f, -4.0f}, {20.0f, -4.0f}};
    Wall south;
    south.name = "south";
    south.points = {{-20.0f, 4.0f}, {20.0f, 4.0f}};
    s.walls = {north, south};
    for (int k = 0; k < 4; ++k) {
        Obstacle pillar;
        pillar.name = "pillar";
        pillar.center = glm::vec2(-6.0f + 4.0f * float(k), k % 2 == 0 ? 1.0f : -1.0f);
        pillar.radiusM = 0.5f;
        s.obstacles.push_back(pillar);
    }
    Obstacle box;
    box.name = "box";
    box.shape = ObstacleShape::Box;
    box.center = glm::vec2(0.0f, 3.0f);
    box.size = glm::vec2(1.0f, 1.0f);
    box.angleDeg = 30.0f;
    s.obstacles.push_back(box);
    s.goals.push_back({"east", {14.0f, 0.0f}, 3.0f});
    s.goals.push_back({"west", {-14.0f, 0.0f}, 3.0f});
    std::uint32_t id = 1;
    for (int row = 0; row < 5; ++row)
        for (int col = 0; col < 20; ++col, ++id) {
            Agent a;
            a.id = id;
            a.type = id % 4 == 0 ? "dodger" : "walker";
            const bool east = col < 10;
            a.position = glm::vec3(east ? -17.0f + 1.0f * float(col) : 17.0f - 1.0f * float(col - 10), 0.0f,
                                   -3.0f + 1.5f * float(row) + 0.05f * std::sin(float(id)));
            a.headingDeg = east ? 90.0f : 270.0f;
            a.goal = east ? "east" : "west";
            s.agents.push_back(a);
        }
    return s;
}

// Runs both paths side by side; returns the first step after which they differ, or -1.
int firstDifference(const Scene& s, int steps)
{
    World kernel = makeWorld(s, true), general = makeWorld(s, false);
    for (int k = 0; k < steps; ++k) {
        kernel.step();
        general.step();
        if (!sameState(kernel, general))
            return k;
    }
    const StepCounters& a = kernel.counters();
    const StepCounters& b = general.counters();
    if (a.overlappingPairs != b.overlappingPairs || a.agentSteps != b.agentSteps ||
        a.wallPenetrations != b.wallPenetrations || a.obstaclePenetrations != b.obstaclePenetrations)
        return steps;
    for (std::size_t i = 0; i < kernel.agentCount(); ++i)
        if (kernel.hasArrived(i) != general.hasArrived(i) || kernel.arrivalTimeS(i) != general.arrivalTimeS(i) ||
            kernel.isOut(i) != general.isOut(i))
            return steps;
    return -1;
}

}  // namespace

class TestWalkKernel : public QObject {
    Q_OBJECT
private slots:
    void kernelTakesOnlyWalkersInTheOpen()
    {
        QVERIFY(makeWorld(makeCrossScenario(50), true).usesWalkKernel(0));
        QVERIFY(!makeWorld(makeCrossScenario(50), false).usesWalkKernel(0));
        const World mixed = makeWorld(mixedCrowd(), true);
        QVERIFY(mixed.usesWalkKernel(0) && mixed.usesWalkKernel(1));
        // Walls and obstacles: the kernel too (wall following, avoidance, constraint).
        const World walled = makeWorld(walledCrowd(), true);
        QVERIFY(walled.usesWalkKernel(0) && walled.usesWalkKernel(1));
        // Alignment is not among the kernel's behaviours.
        Scene aligned = makeCrossScenario(50);
        aligned.agentTypes[0].behaviours = {behaviour("arrival", 1.0f), behaviour("alignment", 1.0f)};
        QVERIFY(!makeWorld(aligned, true).usesWalkKernel(0));
    }

    void crossIsBitIdenticalToTheGeneralPath()
    {
        // 25 s: the first rings meet in the middle after about 21 s.
        const Scene s = makeCrossScenario(600);
        World kernel = makeWorld(s, true), general = makeWorld(s, false);
        float moved = 0.0f;
        std::size_t threats = 0;
        for (int k = 0; k < 24 * 25; ++k) {
            kernel.step();
            general.step();
            QVERIFY2(sameState(kernel, general), qPrintable(QString("the paths differ after step %1").arg(k)));
            // Walkers passing side by side or meeting: someone moved off its straight line.
            for (std::size_t i = 0; i < kernel.agentCount(); ++i) {
                const glm::vec3 p = kernel.positions()[i], v = kernel.velocities()[i];
                const glm::vec2 out(p.x, p.z);
                const glm::vec2 way(v.x, v.z);
                if (glm::length(out) > 1.0f && glm::length(way) > 0.1f &&
                    std::fabs(glm::dot(glm::normalize(out), glm::normalize(way))) < 0.9f)
                    ++threats;
            }
            moved = std::max(moved, glm::length(kernel.positions()[0] - s.agents[0].position));
        }
        qInfo("cross 600, 600 steps: identical; %zu agent-steps off the straight line, %llu overlapping pairs",
              threats, static_cast<unsigned long long>(kernel.counters().overlappingPairs));
        QVERIFY(moved > 20.0f);
        QVERIFY(threats > 1000);  // avoidance did act, so the comparison covers it
        QCOMPARE(kernel.counters().overlappingPairs, general.counters().overlappingPairs);
    }

    void brainWalkersAreBitIdenticalToTheGeneralPath_data()
    {
        QTest::addColumn<float>("fps");
        QTest::newRow("24 fps: a decision every step") << 24.0f;
        QTest::newRow("60 fps: forces held between decisions") << 60.0f;
    }

    void brainWalkersAreBitIdenticalToTheGeneralPath()
    {
        // The cross's walkers with the 40-node bench brain: it sets their speed, their
        // turn and the weights of separation and arrival each step, and senses their
        // neighbours itself. The kernel takes all of that up as the general path does.
        QFETCH(float, fps);
        Scene s = makeCrossBrainScenario(600, 3);
        s.settings.fps = fps;
        World kernel = makeWorld(s, true), general = makeWorld(s, false);
        QVERIFY(kernel.usesWalkKernel(0));
        QVERIFY(!general.usesWalkKernel(0));
        QVERIFY(kernel.agentBrainEvaluator(0) != nullptr);
        Scene brainless = s;
        brainless.agentTypes[0].brain.clear();
        World plain = makeWorld(brainless, true);
        std::size_t capped = 0;
        const int steps = int(std::lround(25.0f * fps));  // 25 s
        for (int k = 0; k < steps; ++k) {
            kernel.step();
            general.step();
            plain.step();
            QVERIFY2(sameState(kernel, general), qPrintable(QString("the paths differ after step %1").arg(k)));
            // Walking well below their speed: the brain's cap (its noise alone takes 0-10 %).
            for (std::size_t i = 0; i < kernel.agentCount(); ++i)
                capped += glm::length(kernel.velocities()[i]) < 0.8f * s.agentTypes[0].maxSpeed &&
                          glm::length(plain.velocities()[i]) > 0.95f * s.agentTypes[0].maxSpeed;
        }
        qInfo("cross-brain 600 at %g fps, %d steps: identical; %zu agent-steps held well below the speed the "
              "brainless walk",
              double(fps), steps, capped);
        QVERIFY(!sameState(kernel, plain));  // the brain changed the walk
        QVERIFY(capped > 1000);
        QCOMPARE(kernel.counters().overlappingPairs, general.counters().overlappingPairs);
    }

    void mixedCrowdIsBitIdenticalToTheGeneralPath()
    {
        const Scene s = mixedCrowd();
        QCOMPARE(firstDifference(s, 24 * 20), -1);
        // The scene does what it is meant to: some arrive, some leave by the exit.
        World w = makeWorld(s, true);
        for (int k = 0; k < 24 * 20; ++k)
            w.step();
        std::size_t arrived = 0, out = 0;
        for (std::size_t i = 0; i < w.agentCount(); ++i) {
            arrived += w.hasArrived(i) ? 1 : 0;
            out += w.isOut(i) ? 1 : 0;
        }
        qInfo("mixed crowd after 20 s: %zu of %zu arrived, %zu left by the exit", arrived, w.agentCount(), out);
        QVERIFY(arrived > 50 && out > 5);
    }

    void crowdBetweenWallsIsBitIdenticalToTheGeneralPath()
    {
        const Scene s = walledCrowd();
        QCOMPARE(firstDifference(s, 24 * 30), -1);
        // Over three quarters get through the pillars and the oncoming stream to their ends
        // in 60 s (98 of 100, keeping right; 45 in 30 s), nobody goes through a wall or ends
        // a step inside a pillar; and 2 threads give the same to the bit.
        World one = makeWorld(s, true, 1), two = makeWorld(s, true, 2);
        for (int k = 0; k < 24 * 60; ++k) {
            one.step();
            two.step();
        }
        QVERIFY(sameState(one, two));
        std::size_t arrived = 0;
        for (std::size_t i = 0; i < one.agentCount(); ++i)
            arrived += one.hasArrived(i) ? 1 : 0;
        qInfo("walled crowd after 60 s: %zu of %zu arrived, %llu wall and %llu obstacle penetrations", arrived,
              one.agentCount(), static_cast<unsigned long long>(one.counters().wallPenetrations),
              static_cast<unsigned long long>(one.counters().obstaclePenetrations));
        QVERIFY(arrived > one.agentCount() * 3 / 4);
        QCOMPARE(one.counters().wallPenetrations, std::uint64_t(0));
        QCOMPARE(one.counters().obstaclePenetrations, std::uint64_t(0));
    }

    void kernelIsBitIdenticalForOneAndTwoThreads()
    {
        const Scene s = makeCrossScenario(600);
        World one = makeWorld(s, true, 1), two = makeWorld(s, true, 2);
        for (int k = 0; k < 24 * 25; ++k) {
            one.step();
            two.step();
        }
        QCOMPARE(two.threads(), 2);
        QVERIFY(sameState(one, two));
    }
};

THRONG_REGISTER_TEST(TestWalkKernel)
#include "TestWalkKernel.moc"
