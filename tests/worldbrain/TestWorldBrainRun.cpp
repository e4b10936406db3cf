// Brain-driven agents in the World, as a user watches them: a pedestrian waits at a red
// crosswalk and crosses on green, a boid flock holds together, a walker that slows by its
// goal distance arrives and stops, and every run is identical on 1 and 2 threads.
#include "TestRegistry.h"

#include "simcore/brain/BrainEvaluator.h"
#include "simcore/io/SceneIO.h"
#include "simcore/traffic/LightPhase.h"
#include "simcore/world/RunStats.h"
#include "simcore/world/World.h"
#include "simcore/world/WorldBrain.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <algorithm>
#include <cstring>

using namespace throng::sim;

namespace {

const WorldOptions kSerial{0, false, 1};

Scene load(const std::string& yaml)
{
    const LoadResult r = parseScene(yaml, "scene.yaml", THRONG_SOURCE_DIR "/resources/brains");
    if (!r.ok())
        qFatal("%s", r.diagnostics[0].format().c_str());
    for (const Diagnostic& d : checkSceneBrains(r.scene))
        qFatal("%s", d.format().c_str());
    return r.scene;
}

// A crossing from z = -6 to z = 6; the light is red for t < 10 s, then green 10 s.
const char* kCrossing = R"(throng: 1
settings: {fps: 24, seed: 3, bounds: {min: [-30, -30], max: [30, 30]}}
brains: [{name: pedestrian, file: pedestrian.brain.yaml}]
agent_types: [{name: walker, max_speed: 1.4, max_force: 3, brain: pedestrian}]
goals: [{name: across, position: [0, 12], radius: 1}]
crosswalks: [{name: zebra, from: [0, -6], to: [0, 6], width: 4}]
traffic_lights:
  - {name: signal, green: 10, yellow: 2, red: 10, offset: 12, stop_lines: [{crosswalk: zebra}]}
agents:
  - {id: 1, type: walker, position: [0, 0, -14], heading: 270, goal: across}
  - {id: 2, type: walker, position: [1, 0, -16], heading: 270, goal: across}
)";

const char* kFlock = R"(throng: 1
settings: {fps: 24, seed: 11, bounds: {min: [-60, -60], max: [60, 60]}}
brains: [{name: boid, file: boid.brain.yaml}]
agent_types:
  - {name: bird, kind: flier, radius: 0.2, max_speed: 4, max_force: 6, perception: 6, min_speed: 1, brain: boid}
groups:
  - {name: flock, type: bird, count: 40, rect: {min: [-5, -5], max: [5, 5]}}
)";

// Speed = max speed x "far from the goal" (1 beyond 3 m, falling to 0 at the goal).
const char* kArrive = R"(throng: 1
settings: {fps: 24, seed: 2, bounds: {min: [-30, -30], max: [30, 30]}}
agent_types: [{name: walker, max_speed: 1.5, max_force: 4, brain: eager, variation: {speed: [1, 1]}}]
goals: [{name: g, position: [15, 0], radius: 0.6}]
agents: [{id: 1, type: walker, position: [0, 0, 0], goal: g}]
brains:
  - name: eager
    nodes:
      - {id: 1, type: input, params: {sensor: goal_distance}}
      - {id: 2, type: fuzz.trapezoid, params: {points: [0, 3, 1e6, 1e6]}}
      - {id: 3, type: input, params: {sensor: attribute, name: max_speed}}
      - {id: 4, type: math.multiply}
      - {id: 5, type: output, params: {channel: speed}}
      - {id: 6, type: output.action, params: {actions: "walk idle", durations: [0, 0]}}
      - {id: 7, type: rule.not}
    links:
      - {from: [1, 0], to: [2, 0]}
      - {from: [2, 0], to: [4, 0]}
      - {from: [3, 0], to: [4, 1]}
      - {from: [4, 0], to: [5, 0]}
      - {from: [2, 0], to: [6, 0]}
      - {from: [2, 0], to: [7, 0]}
      - {from: [7, 0], to: [6, 1]}
)";

glm::vec2 xz(glm::vec3 v) { return {v.x, v.z}; }

std::uint64_t hashRun(const Scene& s, int threads, int steps)
{
    World world(s, {0, false, threads});
    std::uint64_t h = 1469598103934665603ull;
    for (int k = 0; k < steps; ++k) {
        world.step();
        for (glm::vec3 p : world.positions()) {
            std::uint32_t bits[3];
            std::memcpy(bits, &p, sizeof bits);
            for (std::uint32_t b : bits)
                h = (h ^ b) * 1099511628211ull;
        }
        for (std::size_t i = 0; i < world.agentCount(); ++i)
            h = (h ^ std::uint64_t(world.brainAction(i) + 1)) * 1099511628211ull;
    }
    return h;
}

}  // namespace

class TestWorldBrainRun : public QObject {
    Q_OBJECT
private slots:
    void pedestrianWaitsForGreenThenCrosses()
    {
        const Scene s = load(kCrossing);
        QCOMPARE(lightPhaseAt(s.trafficLights[0], 5.0), LightPhase::Red);
        QCOMPARE(lightPhaseAt(s.trafficLights[0], 10.5), LightPhase::Green);
        World world(s, kSerial);
        QVERIFY(world.brainErrors().empty());
        float nearestToZebra = -100.0f, speedAt9 = 1.0f;
        float enteredAt = -1.0f;
        while (world.timeS() < 30.0) {
            world.step();
            const double t = world.timeS();
            const float z = world.positions()[0].z;
            if (t < 10.0)
                nearestToZebra = std::max(nearestToZebra, z);
            if (std::abs(t - 9.5) < 0.5 * world.dt())
                speedAt9 = glm::length(world.velocities()[0]);
            if (enteredAt < 0.0f && z > -6.0f)
                enteredAt = float(t);
        }
        // Waited before the line on red: the body never reached the crosswalk, and stood.
        QVERIFY2(nearestToZebra < -6.0f - 0.3f, qPrintable(QString::number(nearestToZebra)));
        QVERIFY2(nearestToZebra > -6.0f - 3.5f, qPrintable(QString::number(nearestToZebra)));
        QVERIFY2(speedAt9 < 0.05f, qPrintable(QString::number(speedAt9)));
        // Set off on green: on the crosswalk within 3 s of the light changing, then across.
        QVERIFY2(enteredAt > 10.0f && enteredAt < 13.0f, qPrintable(QString::number(enteredAt)));
        QVERIFY(world.hasArrived(0));
        QVERIFY(world.hasArrived(1));
        QCOMPARE(world.counters().redLightViolations, std::uint64_t(0));
    }

    void pedestrianWithoutBrainWouldWalkOnRed()
    {
        // The same scene without the brain: the crossing test above depends on the brain.
        Scene s = load(kCrossing);
        s.agentTypes[0].brain.clear();
        World world(s, kSerial);
        while (world.timeS() < 10.0)
            world.step();
        QVERIFY(world.counters().redLightViolations > 0);
    }

    void boidFlockStaysTogether()
    {
        const Scene s = load(kFlock);
        World world(s, kSerial);
        QVERIFY(world.brainErrors().empty());
        while (world.timeS() < 30.0)
            world.step();
        // Flock-mates: within the perception radius (6 m) of each other. After 30 s the
        // birds linked that way are still one flock, and nobody is left alone.
        const auto p = world.positions();
        const std::size_t n = p.size();
        std::vector<std::size_t> group(n);
        for (std::size_t i = 0; i < n; ++i)
            group[i] = i;
        auto root = [&](std::size_t i) {
            while (group[i] != i)
                i = group[i] = group[group[i]];
            return i;
        };
        std::size_t alone = 0;
        for (std::size_t i = 0; i < n; ++i) {
            bool mate = false;
            for (std::size_t j = 0; j < n; ++j)
                if (j != i && glm::distance(p[i], p[j]) < 6.0f) {
                    mate = true;
                    group[root(i)] = root(j);
                }
            alone += !mate;
        }
        std::vector<std::size_t> size(n, 0);
        std::size_t largest = 0;
        for (std::size_t i = 0; i < n; ++i)
            largest = std::max(largest, ++size[root(i)]);
        QCOMPARE(alone, std::size_t(0));
        QCOMPARE(largest, n);
        // Tighter than the 10 m square they started in (mean 3.6 m from the centre).
        glm::vec3 centre(0.0f);
        for (glm::vec3 q : p)
            centre += q;
        centre /= float(n);
        float spread = 0.0f;
        for (glm::vec3 q : p)
            spread += glm::distance(q, centre) / float(n);
        QVERIFY2(spread < 3.0f, qPrintable(QString::number(spread)));
        QCOMPARE(world.counters().nonFiniteValues, std::uint64_t(0));
    }

    void slowsNearGoalArrivesAndStops()
    {
        const Scene s = load(kArrive);
        World world(s, kSerial);
        float speedAt1m = -1.0f, cruise = 0.0f;
        while (world.timeS() < 25.0) {
            world.step();
            const float d = glm::distance(xz(world.positions()[0]), glm::vec2(15, 0));
            const float v = glm::length(world.velocities()[0]);
            if (d > 5.0f)
                cruise = std::max(cruise, v);
            if (speedAt1m < 0.0f && d < 1.0f)
                speedAt1m = v;
        }
        QVERIFY2(cruise > 1.4f, qPrintable(QString::number(cruise)));
        // By the brain, 1 m from the goal's centre (up to 1.48 m from the agent's own spot
        // in it) it walks at half its cruising speed or less.
        QVERIFY2(speedAt1m >= 0.0f && speedAt1m < 0.5f * cruise, qPrintable(QString::number(speedAt1m)));
        QVERIFY(world.hasArrived(0));
        QCOMPARE(glm::length(world.velocities()[0]), 0.0f);
        QVERIFY(glm::distance(xz(world.positions()[0]), glm::vec2(15, 0)) < 0.6f);
        // The action it chose near the goal reaches the recorded clip.
        QCOMPARE(QString::fromStdString(world.brainActionName(0)), QString("idle"));
        std::vector<AgentFrame> frame;
        world.snapshot(frame);
        QCOMPARE(frame[0].clip, Clip::Idle);
    }

    void actionIsRecordedAsTheClipWhileWalking()
    {
        const Scene s = load(kArrive);
        World world(s, kSerial);
        for (int k = 0; k < 48; ++k)
            world.step();
        QCOMPARE(QString::fromStdString(world.brainActionName(0)), QString("walk"));
        std::vector<AgentFrame> frame;
        world.snapshot(frame);
        QCOMPARE(frame[0].clip, Clip::Walk);
    }

    // Every clip reads back from its name; actions loop in time, each agent at its own
    // offset, the same on every call.
    void actionClipsAreNamedAndTimed()
    {
        for (int c = 0; c < kClipCount; ++c) {
            const std::optional<Clip> back = clipFromName(toString(Clip(c)));
            QVERIFY(back && *back == Clip(c));
            QCOMPARE(isAction(Clip(c)), c >= int(Clip::Wait));
            QCOMPARE(clipCycleS(Clip(c)) > 0.0f, isAction(Clip(c)));
        }
        QVERIFY(!clipFromName("dance"));
        QCOMPARE(QString(toString(Clip::LookAround)), QString("look_around"));
        // A wave is 1 s a cycle: a quarter second on, a quarter cycle on (mod 1).
        for (const std::uint32_t id : {1u, 2u, 77u}) {
            const float a = actionPhase(Clip::Wave, 3.0, id), b = actionPhase(Clip::Wave, 3.25, id);
            QVERIFY(a >= 0.0f && a < 1.0f);
            const float step = b - a + (b < a ? 1.0f : 0.0f);
            QVERIFY2(std::abs(step - 0.25f) < 1e-4f, qPrintable(QString::number(step)));
            QCOMPARE(actionPhase(Clip::Wave, 3.0, id), a);
        }
        // Offsets differ between agents: ten agents at one moment are not in step.
        std::vector<float> phases;
        for (std::uint32_t id = 1; id <= 10; ++id)
            phases.push_back(actionPhase(Clip::Cheer, 5.0, id));
        std::sort(phases.begin(), phases.end());
        QVERIFY(phases.back() - phases.front() > 0.5f);
        QCOMPARE(actionPhase(Clip::Walk, 5.0, 3), 0.0f);
    }

    // A brain's action named as a clip is the recorded clip; another name keeps the speed's.
    void actionNamedAsAClipIsRecorded()
    {
        const char* scene = R"(throng: 1
settings: {fps: 24, seed: 2, bounds: {min: [-30, -30], max: [30, 30]}}
agent_types: [{name: walker, max_speed: 1.5, brain: b}]
goals: [{name: east, position: [20, 0], radius: 1}]
agents: [{id: 1, type: walker, position: [0, 0, 0], goal: east}, {id: 2, type: walker, position: [0, 0, 5]}]
brains:
  - name: b
    nodes:
      - {id: 1, type: input, params: {sensor: goal_distance}}
      - {id: 2, type: math.compare, params: {mode: lt, value: 1000}}
      - {id: 3, type: rule.not}
      - {id: 4, type: output.action, params: {actions: "dance phone"}}
    links:
      - {from: [1, 0], to: [2, 0]}
      - {from: [2, 0], to: [3, 0]}
      - {from: [3, 0], to: [4, 0]}
      - {from: [2, 0], to: [4, 1]}
)";
        const Scene s = load(scene);
        World world(s, kSerial);
        QVERIFY(world.brainErrors().empty());
        for (int k = 0; k < 24; ++k)
            world.step();
        std::vector<AgentFrame> frame;
        world.snapshot(frame);
        // Agent 1 has a goal: "phone" while it walks there.
        QCOMPARE(QString::fromStdString(world.brainActionName(0)), QString("phone"));
        QCOMPARE(frame[0].clip, Clip::Phone);
        QVERIFY(frame[0].speed > 0.5f);
        // Agent 2 has none (the distance sensor says 1e6 m): "dance" is no clip, so its
        // speed's clip stands.
        QCOMPARE(QString::fromStdString(world.brainActionName(1)), QString("dance"));
        QCOMPARE(frame[1].clip, Clip::Idle);
    }

    void goalChoiceSendsTheAgentToTheChosenGoal()
    {
        const Scene s = load(R"(throng: 1
settings: {fps: 24, seed: 2, bounds: {min: [-30, -30], max: [30, 30]}}
agent_types: [{name: walker, max_speed: 1.5, brain: chooser}]
goals: [{name: east, position: [10, 0], radius: 1}, {name: west, position: [-10, 0], radius: 1}]
agents: [{id: 1, type: walker, position: [0, 0, 0], goal: east}]
brains:
  - name: chooser
    nodes:
      - {id: 1, type: input.constant, params: {value: 0.2}}
      - {id: 2, type: input.constant, params: {value: 0.8}}
      - {id: 3, type: output.goal, params: {goals: "east west"}}
    links:
      - {from: [1, 0], to: [3, 0]}
      - {from: [2, 0], to: [3, 1]}
)");
        World world(s, kSerial);
        while (world.timeS() < 15.0)
            world.step();
        QVERIFY(world.hasArrived(0));
        QVERIFY2(world.positions()[0].x < -8.0f, qPrintable(QString::number(world.positions()[0].x)));
    }

    void walkerStopsWhenItSeesATaggedNeighbour()
    {
        // A standing "guard" publishes the tag "halt" = 1; a walker whose brain stops for
        // any neighbour with that tag walks toward the guard and stops once it perceives
        // it (4 m), far short of its goal beyond.
        const char* yaml = R"(throng: 1
settings: {fps: 24, seed: 4, bounds: {min: [-30, -30], max: [30, 30]}}
agent_types:
  - {name: guard, max_speed: 1, brain: guard}
  - {name: walker, max_speed: 1.4, perception: 4, view_angle: 360, brain: obey}
goals: [{name: far, position: [20, 0], radius: 1}]
agents:
  - {id: 1, type: guard, position: [10, 0, 1.5]}
  - {id: 2, type: walker, position: [0, 0, 0], goal: far}
brains:
  - name: guard
    nodes:
      - {id: 1, type: input.constant, params: {value: 1}}
      - {id: 2, type: output, params: {channel: tag, tag: halt}}
    links:
      - {from: [1, 0], to: [2, 0]}
  - name: obey
    nodes:
      - {id: 1, type: input, params: {sensor: neighbour_tag, tag: halt}}
      - {id: 2, type: filter, params: {mode: most}}
      - {id: 3, type: rule.not}
      - {id: 4, type: output, params: {channel: speed, scale: 1.4}}
    links:
      - {from: [1, 0], to: [2, 0]}
      - {from: [2, 0], to: [3, 0]}
      - {from: [3, 0], to: [4, 0]}
)";
        const Scene s = load(yaml);
        World world(s, kSerial);
        QVERIFY(world.brainErrors().empty());
        while (world.timeS() < 20.0)
            world.step();
        const glm::vec2 walker = xz(world.positions()[1]);
        const float toGuard = glm::distance(walker, glm::vec2(10, 1.5));
        QVERIFY2(toGuard < 4.2f && toGuard > 3.0f, qPrintable(QString::number(toGuard)));
        QVERIFY(!world.hasArrived(1));
        QVERIFY(glm::length(world.velocities()[1]) < 0.05f);
        // The live view of the walker's brain shows why: the tag it sees, and "go" = 0.
        world.pickBrainAgent(1);
        world.step();
        const BrainEvaluator* live = world.brainEvaluator(1);
        QVERIFY(live);
        bool sawTag = false, sawStop = false;
        for (const BrainNodeValue& v : live->pickedValues()) {
            if (v.node == 2)
                sawTag = v.values.size() == 1 && v.values[0] == 1.0f;
            if (v.node == 3)
                sawStop = v.values.size() == 1 && v.values[0] == 0.0f;
        }
        QVERIFY(sawTag);
        QVERIFY(sawStop);
    }

    void identicalOnOneAndTwoThreads()
    {
        for (const char* yaml : {kCrossing, kFlock, kArrive}) {
            const Scene s = load(yaml);
            QCOMPARE(hashRun(s, 2, 240), hashRun(s, 1, 240));
        }
    }
};

THRONG_REGISTER_TEST(TestWorldBrainRun)
#include "TestWorldBrainRun.moc"
