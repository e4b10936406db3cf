// Placed agents with a brain of their own (the assign brush's per-agent brain): they run
// it instead of their type's, agents of one type with different brains each follow
// their own, the file round-trips, and runs are identical on 1 and 2 threads.
#include "TestRegistry.h"

#include "simcore/io/SceneIO.h"
#include "simcore/world/World.h"
#include "simcore/world/WorldBrain.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <cstring>
#include <string>

using namespace throng::sim;

namespace {

// "go" walks at the type's max speed; "stay" asks for speed 0; "weave" turns by noise.
const char* kBrains = R"(brains:
  - name: go
    nodes:
      - {id: 1, type: input, params: {sensor: attribute, name: max_speed}}
      - {id: 2, type: output, params: {channel: speed}}
    links: [{from: [1, 0], to: [2, 0]}]
  - name: stay
    nodes:
      - {id: 1, type: input.constant, params: {value: 0}}
      - {id: 2, type: output, params: {channel: speed}}
    links: [{from: [1, 0], to: [2, 0]}]
  - name: weave
    nodes:
      - {id: 1, type: input.noise, params: {frequency: 1, min: -90, max: 90}}
      - {id: 2, type: output, params: {channel: turn}}
    links: [{from: [1, 0], to: [2, 0]}]
)";

Scene load(const std::string& yaml)
{
    const LoadResult r = parseScene(yaml, "scene.yaml", ".");
    if (!r.ok())
        qFatal("%s", r.diagnostics[0].format().c_str());
    for (const Diagnostic& d : checkSceneBrains(r.scene))
        qFatal("%s", d.format().c_str());
    return r.scene;
}

std::string mixedScene()
{
    return std::string(R"(throng: 1
settings: {fps: 24, seed: 5, bounds: {min: [-40, -40], max: [40, 40]}}
agent_types:
  - {name: walker, max_speed: 1.4, max_force: 3, brain: go, variation: {speed: [1, 1]}}
  - {name: idler, max_speed: 1.4, max_force: 3, variation: {speed: [1, 1]}}
goals: [{name: east, position: [30, 0], radius: 1}]
agents:
  - {id: 1, type: walker, position: [0, 0, -4], goal: east}
  - {id: 2, type: walker, position: [0, 0, -2], goal: east, brain: stay, group: parked}
  - {id: 3, type: walker, position: [0, 0, 0], goal: east}
  - {id: 4, type: walker, position: [0, 0, 2], goal: east, brain: stay, group: parked}
  - {id: 5, type: idler, position: [0, 0, 4], goal: east, brain: stay}
  - {id: 6, type: idler, position: [0, 0, 6], goal: east}
)") + kBrains;
}

float travelled(const Scene& s, std::size_t agent, int steps)
{
    World world(s);
    const glm::vec3 start = world.positions()[agent];
    for (int k = 0; k < steps; ++k)
        world.step();
    return glm::distance(start, world.positions()[agent]);
}

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
    }
    return h;
}

}  // namespace

class TestWorldBrainPerAgent : public QObject {
    Q_OBJECT

private slots:
    void agentsRunTheirOwnBrainInsteadOfTheTypes()
    {
        const Scene s = load(mixedScene());
        World world(s);
        std::vector<glm::vec3> start(world.positions().begin(), world.positions().end());
        for (int k = 0; k < 24 * 4; ++k)
            world.step();
        // Walkers 1 and 3 run "go" and walk ~1.4 m/s for 4 s; 2 and 4 run "stay".
        for (std::size_t i : {0u, 2u})
            QVERIFY2(glm::distance(start[i], world.positions()[i]) > 4.0f, qPrintable(QString::number(i)));
        for (std::size_t i : {1u, 3u})
            QVERIFY2(glm::distance(start[i], world.positions()[i]) < 0.05f, qPrintable(QString::number(i)));
        // A type without a brain: agent 5 runs "stay" all the same, agent 6 steers without one.
        QVERIFY(glm::distance(start[4], world.positions()[4]) < 0.05f);
        QVERIFY(glm::distance(start[5], world.positions()[5]) > 4.0f);
        // Each (type, brain) pair runs in its own evaluator.
        QVERIFY(world.agentBrainEvaluator(0) != nullptr);
        QCOMPARE(world.agentBrainEvaluator(0), world.agentBrainEvaluator(2));
        QVERIFY(world.agentBrainEvaluator(1) != world.agentBrainEvaluator(0));
        QCOMPARE(world.agentBrainEvaluator(1), world.agentBrainEvaluator(3));
        QVERIFY(world.agentBrainEvaluator(4) != world.agentBrainEvaluator(1));
        QVERIFY(world.agentBrainEvaluator(5) == nullptr);
    }

    void clearingTheOwnBrainRestoresTheTypes()
    {
        Scene s = load(mixedScene());
        QVERIFY(travelled(s, 1, 48) < 0.05f);
        s.agents[1].brain.clear();
        QVERIFY(travelled(s, 1, 48) > 2.0f);
    }

    void brainAndGroupRoundTrip()
    {
        const Scene s = load(mixedScene());
        QCOMPARE(s.agents[1].brain, std::string("stay"));
        QCOMPARE(s.agents[1].group, std::string("parked"));
        QVERIFY(s.agents[0].brain.empty() && s.agents[0].group.empty());
        const LoadResult again = parseScene(sceneToYaml(s), "again.yaml", ".");
        QVERIFY(again.ok());
        QVERIFY(again.scene == s);
        // The table form (a painted crowd) keeps them too.
        Scene big = s;
        for (std::uint32_t k = 0; k < 600; ++k) {
            Agent a = s.agents[k % 4];
            a.id = 100 + k;
            a.position = glm::vec3(float(k % 30) - 15.0f, 0.0f, float(k / 30) + 10.0f);
            big.agents.push_back(a);
        }
        const std::string yaml = sceneToYaml(big);
        QVERIFY(yaml.find("columns:") != std::string::npos);
        const LoadResult table = parseScene(yaml, "table.yaml", ".");
        QVERIFY(table.ok());
        QVERIFY(table.scene == big);
    }

    void unknownBrainIsAnErrorAtItsPlace()
    {
        std::string yaml = mixedScene();
        yaml.replace(yaml.find("brain: stay, group"), 11, "brain: sty");
        const LoadResult r = parseScene(yaml, "scene.yaml", ".");
        QVERIFY(!r.ok());
        const std::string first = r.diagnostics[0].format();
        QVERIFY2(first.find("scene.yaml:9:") != std::string::npos, first.c_str());
        QVERIFY2(first.find("sty") != std::string::npos, first.c_str());
    }

    void identicalOnOneAndTwoThreads()
    {
        std::string yaml = R"(throng: 1
settings: {fps: 24, seed: 9, bounds: {min: [-40, -40], max: [40, 40]}}
agent_types: [{name: walker, max_speed: 1.4, max_force: 3, brain: go}]
goals: [{name: east, position: [30, 0], radius: 3}]
agents:
)";
        const char* brains[] = {"", "stay", "weave"};
        for (int k = 0; k < 3000; ++k) {
            yaml += "  - {type: walker, position: [" + std::to_string(-30 + (k % 60)) + ", 0, " +
                    std::to_string(-25 + k / 60) + "], goal: east";
            if (*brains[k % 3])
                yaml += std::string(", brain: ") + brains[k % 3];
            yaml += "}\n";
        }
        const Scene s = load(yaml + kBrains);
        QCOMPARE(hashRun(s, 2, 48), hashRun(s, 1, 48));
    }
};

THRONG_REGISTER_TEST(TestWorldBrainPerAgent)
#include "TestWorldBrainPerAgent.moc"
