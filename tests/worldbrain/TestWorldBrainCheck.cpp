// The scene check compiles every brain with the scene's brains as macros and reports
// compiler errors and sensors the World cannot fill, as file:line:col with the node id;
// a World never runs such a brain silently.
#include "TestRegistry.h"

#include "simcore/io/SceneIO.h"
#include "simcore/world/World.h"
#include "simcore/world/WorldBrain.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <algorithm>

using namespace throng::sim;

namespace {

Scene load(const std::string& yaml)
{
    const LoadResult r = parseScene(yaml, "scene.yaml", THRONG_SOURCE_DIR "/resources/brains");
    if (!r.ok())
        qFatal("%s", r.diagnostics[0].format().c_str());
    return r.scene;
}

// Line 7 holds node 2, whose input 'x' nothing feeds; line 14 holds node 1 of "vague",
// an attribute agents do not have.
const char* kBroken = R"(throng: 1
agent_types: [{name: w, brain: broken}]
brains:
  - name: broken
    nodes:
      - {id: 1, type: input, params: {sensor: goal_distance}}
      - {id: 2, type: fuzz.triangle, params: {points: [0, 1, 2]}}
      - {id: 4, type: output, params: {channel: speed}}
      - {id: 3, type: input, params: {sensor: sound_bearing, channel: bell}}
    links:
      - {from: [2, 0], to: [4, 0]}
  - name: vague
    nodes:
      - {id: 1, type: input, params: {sensor: attribute, name: wingspan}}
      - {id: 2, type: output, params: {channel: turn}}
    links:
      - {from: [1, 0], to: [2, 0]}
agents: [{type: w, position: [0, 0]}]
)";

}  // namespace

class TestWorldBrainCheck : public QObject {
    Q_OBJECT
private slots:
    void shippedBrainsAllRunInTheWorld()
    {
        const Scene s = load("throng: 1\nbrains:\n  - {name: pedestrian, file: pedestrian.brain.yaml}\n"
                             "  - {name: boid, file: boid.brain.yaml}\n  - {name: car, file: car.brain.yaml}\n");
        for (const Diagnostic& d : checkSceneBrains(s))
            QFAIL(d.format().c_str());
    }

    void compilerErrorNamesFileLineColumnAndNode()
    {
        const std::vector<Diagnostic> d = checkSceneBrains(load(kBroken));
        QVERIFY(!d.empty());
        QCOMPARE(QString::fromStdString(d[0].file), QString("scene.yaml"));
        QCOMPARE(d[0].line, 7);
        QVERIFY2(d[0].column > 0, d[0].format().c_str());
        QCOMPARE(QString::fromStdString(d[0].key), QString("brains[0]"));
        QVERIFY2(d[0].message.find("node 2 (fuzz.triangle)") != std::string::npos, d[0].format().c_str());
        QVERIFY2(d[0].format().starts_with("scene.yaml:7:"), d[0].format().c_str());
    }

    void sensorTheWorldLacksIsAnErrorAtItsNode()
    {
        const std::vector<Diagnostic> d = checkSceneBrains(load(kBroken));
        const Diagnostic* vague = nullptr;
        for (const Diagnostic& x : d)
            if (x.key == "brains[1]")
                vague = &x;
        QVERIFY(vague);
        QCOMPARE(vague->line, 14);
        QVERIFY2(vague->message.find("node 1 (input)") != std::string::npos, vague->format().c_str());
        QVERIFY2(vague->message.find("'wingspan' is not an agent attribute") != std::string::npos,
                 vague->format().c_str());
    }

    void soundHeroAndVehicleLightSensorsAreProvided()
    {
        // Every sensor of the catalogue is filled by the World now, with or without heroes,
        // sound sources or lanes in the scene.
        const char* yaml = R"(throng: 1
agent_types: [{name: w, brain: all}, {name: hero}]
heroes: [{name: h, type: hero, keyframes: [{time: 0, position: [5, 0, 0]}]}]
sound_sources: [{name: tower, channel: bell, position: [0, 9]}]
brains:
  - name: all
    nodes:
      - {id: 1, type: input, params: {sensor: sound_bearing, channel: bell}}
      - {id: 2, type: input, params: {sensor: sound_source_strength, channel: bell}}
      - {id: 3, type: filter, params: {mode: most}}
      - {id: 4, type: input, params: {sensor: hero_distance}}
      - {id: 5, type: input, params: {sensor: hero_bearing}}
      - {id: 6, type: input, params: {sensor: light_state}}
      - {id: 7, type: math.add}
      - {id: 8, type: output, params: {channel: turn}}
    links:
      - {from: [2, 0], to: [3, 0]}
      - {from: [1, 0], to: [7, 0]}
      - {from: [3, 0], to: [7, 1]}
      - {from: [4, 0], to: [7, 2]}
      - {from: [5, 0], to: [7, 3]}
      - {from: [6, 0], to: [7, 4]}
      - {from: [7, 0], to: [8, 0]}
agents: [{type: w, position: [0, 0]}]
)";
        const Scene s = load(yaml);
        for (const Diagnostic& d : checkSceneBrains(s))
            QFAIL(d.format().c_str());
        const World world(s);
        QVERIFY(world.brainErrors().empty());
        QVERIFY(world.brainEvaluator(0) != nullptr);

        // Without the bell tower nothing sounds on "bell": a warning at the first node
        // that listens to it (line 8: node 1), once per channel; the brain still runs.
        Scene quiet = s;
        quiet.soundSources.clear();
        const std::vector<Diagnostic> d = checkSceneBrains(quiet);
        QCOMPARE(d.size(), std::size_t(1));
        QCOMPARE(d[0].severity, Severity::Warning);
        QCOMPARE(d[0].line, 8);
        QVERIFY2(d[0].message.find("node 1 (input): nothing is heard on channel 'bell'") != std::string::npos,
                 d[0].format().c_str());
        QVERIFY(World(quiet).brainErrors().empty());
    }

    void worldRefusesABrainItCannotRun()
    {
        Scene s = load(kBroken);
        s.agentTypes[0].brain = "vague";
        const World world(s);
        QCOMPARE(world.brainErrors().size(), std::size_t(1));
        QVERIFY(world.brainErrors()[0].find("wingspan") != std::string::npos);
        QVERIFY(world.brainEvaluator(0) == nullptr);
    }

    void macroLibraryIsTheScenesBrains()
    {
        // "halve" is used as a macro by "walker": it compiles against the scene's brains,
        // and the walker it drives keeps to half its max speed.
        const char* yaml = R"(throng: 1
agent_types: [{name: w, max_speed: 1.6, brain: walker, variation: {speed: [1, 1]}}]
goals: [{name: g, position: [40, 0], radius: 1}]
agents: [{type: w, position: [0, 0], goal: g}]
brains:
  - name: halve
    nodes:
      - {id: 1, type: macro.in, params: {port: 0}}
      - {id: 2, type: math.multiply}
      - {id: 3, type: input.constant, params: {value: 0.5}}
      - {id: 4, type: macro.out, params: {port: 0}}
    links:
      - {from: [1, 0], to: [2, 0]}
      - {from: [3, 0], to: [2, 1]}
      - {from: [2, 0], to: [4, 0]}
  - name: walker
    nodes:
      - {id: 1, type: input, params: {sensor: attribute, name: max_speed}}
      - {id: 2, type: macro, params: {brain: halve}}
      - {id: 3, type: output, params: {channel: speed}}
    links:
      - {from: [1, 0], to: [2, 0]}
      - {from: [2, 0], to: [3, 0]}
)";
        const Scene s = load(yaml);
        for (const Diagnostic& d : checkSceneBrains(s))
            QFAIL(d.format().c_str());
        World world(s);
        QVERIFY(world.brainErrors().empty());
        float fastest = 0.0f;
        for (int k = 0; k < 24 * 8; ++k) {
            world.step();
            fastest = std::max(fastest, glm::length(world.velocities()[0]));
        }
        QVERIFY2(fastest > 0.75f && fastest <= 0.8f + 1e-4f, qPrintable(QString::number(fastest)));

        Scene missing = s;
        missing.brains[1].nodes[1].params[0].text = "nobody";
        const std::vector<Diagnostic> d = checkSceneBrains(missing);
        QVERIFY(!d.empty());
        QCOMPARE(QString::fromStdString(d[0].key), QString("brains[1]"));
        QVERIFY2(d[0].message.find("node 2 (macro)") != std::string::npos, d[0].format().c_str());
        QVERIFY2(d[0].message.find("nobody") != std::string::npos, d[0].format().c_str());
    }
};

THRONG_REGISTER_TEST(TestWorldBrainCheck)
#include "TestWorldBrainCheck.moc"
