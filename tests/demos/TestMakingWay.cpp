// Collision layers and priorities, as a user checks them: a crowd parts for an
// ambulance, which keeps its line and speed; equal priorities change nothing; agents on
// layers that do not collide walk through each other.
#include "DemoRuns.h"
#include "TestRegistry.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <string>

using namespace throng::sim;
using namespace throng::test::demos;

namespace {

// An ambulance (id 1) walks 35 m east along a path on z = 0 through 120 walkers standing in a
// 16 x 10 m block, and 40 more crossing its line from south to north.
std::string crowdScene(float ambulancePriority, float walkerPriority, bool crowd = true)
{
    return R"(throng: 1
settings: {fps: 24, seed: 5, bounds: {min: [-30, -30], max: [30, 30]}}
agent_types:
  - {name: walker, max_speed: 1.4, priority: )" + std::to_string(walkerPriority) + R"(}
  - {name: ambulance, radius: 0.4, max_speed: 1.4, variation: {speed: [1, 1]}, priority: )" +
           std::to_string(ambulancePriority) + R"(}
goals:
  - {name: north, position: [0, -25], radius: 4}
paths:
  - {name: road, radius: 0.5, points: [[-15, 0], [20, 0]]}
agents:
  - {id: 1, type: ambulance, position: [-15, 0], heading: 0, path: road}
)" + (crowd ? R"(groups:
  - {name: standing, type: walker, count: 120, rect: {min: [-8, -5], max: [8, 5]}}
  - {name: crossing, type: walker, count: 40, rect: {min: [8, 4], max: [14, 14]}, goal: north}
)"
                : "");
}

struct AmbulanceRun {
    float maxLateralM = 0.0f;     // largest |z| of the ambulance on its way
    float arrivalS = -1.0f;       // when it reached its goal
    std::uint64_t ambulanceOverlapSteps = 0;  // steps in which a walker overlaps the ambulance
    std::uint64_t overlappingPairs = 0;       // all pairs, summed over steps
};

AmbulanceRun runAmbulance(const std::string& yaml)
{
    const Scene scene = parse(yaml);
    World world(scene, threads(1));
    AmbulanceRun r;
    while (!world.hasArrived(0) && world.timeS() < 60.0) {
        world.step();
        const auto p = world.positions();
        r.maxLateralM = std::max(r.maxLateralM, std::fabs(p[0].z));
        bool overlap = false;
        for (std::size_t i = 1; i < world.agentCount(); ++i)
            overlap = overlap || glm::distance(ground(p[0]), ground(p[i])) < world.radii()[0] + world.radii()[i] - 0.01f;
        r.ambulanceOverlapSteps += overlap;
    }
    r.arrivalS = world.arrivalTimeS(0);
    r.overlappingPairs = world.counters().overlappingPairs;
    return r;
}

std::string twoLayerScene(bool separateLayers)
{
    // Ten walkers on layer 1 walk east and ten on layer 2 walk west along the same ten
    // lines; with separate layers each group collides only with its own.
    const std::string east = separateLayers ? ", layer: 1, collides_with: [1]" : "";
    const std::string west = separateLayers ? ", layer: 2, collides_with: [2]" : "";
    std::string yaml = R"(throng: 1
settings: {fps: 24, seed: 2, bounds: {min: [-30, -30], max: [30, 30]}}
agent_types:
  - {name: eastward, max_speed: 1.4, variation: {speed: [1, 1]})" + east + R"(}
  - {name: westward, max_speed: 1.4, variation: {speed: [1, 1]})" + west + R"(}
agents:
)";
    for (int k = 0; k < 10; ++k) {
        const std::string z = std::to_string(-4.5 + k);
        yaml += "  - {type: eastward, position: [-10, " + z + "], heading: 0, path: e" + std::to_string(k) + "}\n";
        yaml += "  - {type: westward, position: [10, " + z + "], heading: 180, path: w" + std::to_string(k) + "}\n";
    }
    yaml += "paths:\n";
    for (int k = 0; k < 10; ++k) {
        const std::string z = std::to_string(-4.5 + k);
        yaml += "  - {name: e" + std::to_string(k) + ", radius: 0.5, points: [[-10, " + z + "], [12, " + z + "]]}\n";
        yaml += "  - {name: w" + std::to_string(k) + ", radius: 0.5, points: [[10, " + z + "], [-12, " + z + "]]}\n";
    }
    return yaml;
}

}  // namespace

class TestMakingWay : public QObject {
    Q_OBJECT
private slots:
    void crowdPartsForAHigherPriority()
    {
        const AmbulanceRun free = runAmbulance(crowdScene(10, 0, false));
        const AmbulanceRun run = runAmbulance(crowdScene(10, 0));
        QVERIFY2(free.arrivalS > 0.0f && run.arrivalS > 0.0f, qPrintable(QString::number(run.arrivalS)));
        // It keeps its line and its speed...
        const float speedLoss = 1.0f - free.arrivalS / run.arrivalS;
        qInfo("priority 10 through the crowd: lateral %.3f m, arrival %.2f s (free %.2f s), speed loss %.4f, "
              "overlap steps %llu", double(run.maxLateralM), double(run.arrivalS), double(free.arrivalS),
              double(speedLoss), static_cast<unsigned long long>(run.ambulanceOverlapSteps));
        QVERIFY2(run.maxLateralM < 0.1f, qPrintable(QString("lateral %1 m").arg(run.maxLateralM)));
        QVERIFY2(speedLoss < 0.03f, qPrintable(QString("speed loss %1").arg(speedLoss)));
        // ...while the crowd parts without touching it.
        QCOMPARE(run.ambulanceOverlapSteps, std::uint64_t(0));
    }

    void equalPrioritiesShareTheAvoidance()
    {
        // The same crowd with the ambulance at the walkers' priority: it is pushed about
        // like anyone (the check above can fail)...
        const AmbulanceRun equal = runAmbulance(crowdScene(0, 0));
        qInfo("equal priorities: lateral %.3f m, arrival %.2f s, overlap steps %llu", double(equal.maxLateralM),
              double(equal.arrivalS), static_cast<unsigned long long>(equal.ambulanceOverlapSteps));
        QVERIFY2(equal.maxLateralM > 0.3f || equal.arrivalS < 0.0f || equal.arrivalS > 27.0f,
                 qPrintable(QString("lateral %1 m, arrival %2 s").arg(equal.maxLateralM).arg(equal.arrivalS)));
        // ...and only the difference of priorities counts: everyone at 3 moves exactly as
        // everyone at 0 (the scenes from before priorities existed).
        QCOMPARE(runHash(parse(crowdScene(3, 3)), 1, 240), runHash(parse(crowdScene(0, 0)), 1, 240));
    }

    void layersThatDoNotCollidePassThrough()
    {
        for (bool separate : {true, false}) {
            const Scene scene = parse(twoLayerScene(separate));
            World world(scene, threads(1));
            float maxLateral = 0.0f;
            std::vector<float> startZ;
            for (glm::vec3 p : world.positions())
                startZ.push_back(p.z);
            for (int s = 0; s < 24 * 20; ++s) {
                world.step();
                for (std::size_t i = 0; i < world.agentCount(); ++i)
                    maxLateral = std::max(maxLateral, std::fabs(world.positions()[i].z - startZ[i]));
            }
            if (separate) {
                // Each walks straight through the other group, and both groups get across.
                QVERIFY2(maxLateral < 0.01f, qPrintable(QString::number(maxLateral)));
                for (std::size_t i = 0; i < world.agentCount(); ++i)
                    QVERIFY(world.hasArrived(i));
                QCOMPARE(world.counters().overlappingPairs, std::uint64_t(0));  // overlaps across layers are allowed
            } else {
                QVERIFY2(maxLateral > 0.2f, qPrintable(QString::number(maxLateral)));
            }
        }
    }

    void keysRoundTripAndBadValuesAreLocated()
    {
        const char* yaml = R"(throng: 1
agent_types:
  - {name: horse, priority: 2.5, layer: 3, collides_with: [0, 3, 31]}
  - {name: bird, kind: flier}
groups:
  - {name: birds, type: bird, count: 5, circle: {center: [0, 0], radius: 2}, altitude: [10, 20]}
)";
        const Scene s = parse(yaml);
        QCOMPARE(s.agentTypes[0].priority, 2.5f);
        QCOMPARE(s.agentTypes[0].layer, 3u);
        QCOMPARE(s.agentTypes[0].collidesWith, (1u << 0) | (1u << 3) | (1u << 31));
        QCOMPARE(s.agentTypes[1].collidesWith, 0xffffffffu);  // default: every layer
        QCOMPARE(s.groups[0].altitudeM, glm::vec2(10.0f, 20.0f));
        QVERIFY(parse(sceneToYaml(s)) == s);
        World world(s, threads(1));
        for (std::size_t i = 0; i < world.agentCount(); ++i)
            QVERIFY(world.positions()[i].y >= 10.0f && world.positions()[i].y <= 20.0f);

        const std::pair<const char*, const char*> bad[] = {
            {"  - {name: horse, layer: 32}\n", "error: agent_types[0].layer"},
            {"  - {name: horse, collides_with: [1.5]}\n", "error: agent_types[0].collides_with"},
            {"  - {name: horse, priority: high}\n", "error: agent_types[0].priority"},
        };
        for (const auto& [type, expected] : bad) {
            const LoadResult r = parseScene(std::string("throng: 1\nagent_types:\n") + type, "scene.yaml", ".");
            QVERIFY(!r.ok());
            // file:line:col, then the key.
            const std::string message = r.diagnostics[0].format();
            QVERIFY2(message.rfind("scene.yaml:3:", 0) == 0 && message.find(expected) != std::string::npos,
                     message.c_str());
        }
        const LoadResult walkers = parseScene(
            "throng: 1\nagent_types: [{name: w}]\ngroups: [{name: g, type: w, count: 1, rect: {min: [0, 0], max: [1, 1]}, "
            "altitude: [1, 2]}]\n", "scene.yaml", ".");
        QVERIFY(walkers.ok());
        QCOMPARE(walkers.diagnostics.size(), std::size_t(1));  // a warning: ground agents ignore it
        QVERIFY(walkers.diagnostics[0].format().find("only affects fliers") != std::string::npos);
    }

    void identicalOnOneAndTwoThreads()
    {
        const Scene s = parse(crowdScene(10, 0));
        QCOMPARE(runHash(s, 2, 240), runHash(s, 1, 240));
        const Scene layers = parse(twoLayerScene(true));
        QCOMPARE(runHash(layers, 2, 240), runHash(layers, 1, 240));
    }
};

THRONG_REGISTER_TEST(TestMakingWay)
#include "TestMakingWay.moc"
