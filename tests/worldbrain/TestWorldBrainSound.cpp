// Brains that listen: an agent hears beacons and emitting agents on its channel with the
// bearing, distance and strength geometry gives, walks to the loudest beacon, and a run
// with sound sensors is identical on 1 and 2 threads.
#include "TestRegistry.h"

#include "simcore/brain/BrainEvaluator.h"
#include "simcore/io/SceneIO.h"
#include "simcore/world/World.h"
#include "simcore/world/WorldBrain.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <algorithm>
#include <cstring>

using namespace throng::sim;

namespace {

Scene load(const std::string& yaml)
{
    const LoadResult r = parseScene(yaml, "scene.yaml", THRONG_SOURCE_DIR "/resources/brains");
    if (!r.ok())
        qFatal("%s", r.diagnostics[0].format().c_str());
    for (const Diagnostic& d : checkSceneBrains(r.scene))
        qFatal("%s", d.format().c_str());
    return r.scene;
}

std::vector<float> picked(const World& world, std::size_t type, NodeId node)
{
    for (const BrainNodeValue& v : world.brainEvaluator(type)->pickedValues())
        if (v.node == node && v.port == 0)
            return v.values;
    return {};
}

// The listener (id 1) stands at the origin facing +x (left = -z). It emits on "bell"
// itself (and must not hear itself); two ringers emit on "bell" with strength 0.8 over
// 10 m; a mute agent and a "horn" beacon make no sound on "bell"; a bell beacon of
// strength 1 over 50 m stands 40 m to its right.
const char* kHearing = R"(throng: 1
settings: {fps: 24, seed: 5, bounds: {min: [-60, -60], max: [60, 60]}}
agent_types:
  - {name: listener, max_speed: 1, brain: ears, emits: {channel: bell, strength: 1, radius: 30}}
  - {name: ringer, max_speed: 1, emits: {channel: bell, strength: 0.8, radius: 10}}
  - {name: mute, max_speed: 1}
sound_sources:
  - {name: church, channel: bell, position: [0, 40], strength: 1, radius: 50}
  - {name: ship, channel: horn, position: [2, 0], strength: 1, radius: 50}
agents:
  - {id: 1, type: listener, position: [0, 0, 0], heading: 0}
  - {id: 2, type: ringer, position: [3, 0, 4]}
  - {id: 3, type: ringer, position: [0, 0, -6]}
  - {id: 4, type: mute, position: [1, 0, 1]}
brains:
  - name: ears
    nodes:
      - {id: 1, type: input, params: {sensor: sound_source_distance, channel: bell}}
      - {id: 2, type: input, params: {sensor: sound_source_bearing, channel: bell}}
      - {id: 3, type: input, params: {sensor: sound_source_strength, channel: bell}}
      - {id: 4, type: input, params: {sensor: sound_bearing, channel: bell}}
      - {id: 5, type: input, params: {sensor: sound_strength, channel: horn}}
      - {id: 6, type: filter, params: {mode: count, threshold: 0}}
      - {id: 7, type: probe, params: {name: count}}
      - {id: 8, type: probe, params: {name: loudest}}
      - {id: 9, type: probe, params: {name: horn}}
      - {id: 10, type: filter, params: {mode: most}}
      - {id: 11, type: filter, params: {mode: least}}
      - {id: 12, type: math.add}
      - {id: 13, type: probe, params: {name: sum}}
    links:
      - {from: [3, 0], to: [6, 0]}
      - {from: [6, 0], to: [7, 0]}
      - {from: [4, 0], to: [8, 0]}
      - {from: [5, 0], to: [9, 0]}
      - {from: [1, 0], to: [10, 0]}
      - {from: [2, 0], to: [11, 0]}
      - {from: [10, 0], to: [12, 0]}
      - {from: [11, 0], to: [12, 1]}
      - {from: [12, 0], to: [13, 0]}
)";

// A walker that turns toward the loudest sound on "bell" and slows to a stop within a
// metre of it; it wanders forward and has no goal. The far church bell (strength 1) is
// louder than the near handbell (0.3) where it starts.
const char* kBeacon = R"(throng: 1
settings: {fps: 24, seed: 8, bounds: {min: [-40, -40], max: [40, 40]}}
agent_types:
  - name: walker
    max_speed: 1.4
    max_force: 4
    variation: {speed: [1, 1]}
    behaviours: {wander: {weight: 1, strength: 0.2}}
    brain: homing
sound_sources:
  - {name: church, channel: bell, position: [20, 5], strength: 1, radius: 40}
  - {name: handbell, channel: bell, position: [-6, -4], strength: 0.3, radius: 40}
  - {name: foghorn, channel: horn, position: [0, -20], strength: 1, radius: 60}
agents:
  - {id: 1, type: walker, position: [0, 0, 0], heading: 180}
brains:
  - name: homing
    nodes:
      - {id: 1, type: input, params: {sensor: sound_source_bearing, channel: bell}}
      - {id: 2, type: filter, params: {mode: nearest}}
      - {id: 3, type: output, params: {channel: turn, scale: 3}}
      - {id: 4, type: input, params: {sensor: sound_distance, channel: bell}}
      - {id: 5, type: math.remap, params: {from: [0.6, 2.5], to: [0, 1.4]}}
      - {id: 6, type: output, params: {channel: speed}}
    links:
      - {from: [1, 0], to: [2, 0]}
      - {from: [2, 0], to: [3, 0]}
      - {from: [4, 0], to: [5, 0]}
      - {from: [5, 0], to: [6, 0]}
)";

// 300 wanderers that each emit on "chat" and turn toward the loudest other one.
const char* kChatter = R"(throng: 1
settings: {fps: 24, seed: 21, bounds: {min: [-30, -30], max: [30, 30]}}
agent_types:
  - name: talker
    max_speed: 1.3
    emits: {channel: chat, strength: 0.9, radius: 6}
    behaviours: {wander: 1, separation: 1, containment: 2}
    brain: gather
groups:
  - {name: crowd, type: talker, count: 300, rect: {min: [-20, -20], max: [20, 20]}}
brains:
  - name: gather
    nodes:
      - {id: 1, type: input, params: {sensor: sound_source_bearing, channel: chat}}
      - {id: 2, type: filter, params: {mode: nearest}}
      - {id: 3, type: output, params: {channel: turn, scale: 1}}
      - {id: 4, type: input, params: {sensor: sound_source_strength, channel: chat}}
      - {id: 5, type: filter, params: {mode: count, threshold: 0.5}}
      - {id: 6, type: math.remap, params: {from: [0, 4], to: [1.3, 0.2]}}
      - {id: 7, type: output, params: {channel: speed}}
    links:
      - {from: [1, 0], to: [2, 0]}
      - {from: [2, 0], to: [3, 0]}
      - {from: [4, 0], to: [5, 0]}
      - {from: [5, 0], to: [6, 0]}
      - {from: [6, 0], to: [7, 0]}
)";

// Five riders with the shipped rider brain pursue a leader (id 1) that rides east at 7 m/s
// and emits on "leader": the brain rides fast (up to 12 m/s) while it hears the leader
// far ahead, and at 5 m/s when it hears nothing.
const char* kRide = R"(throng: 1
settings: {fps: 24, seed: 12, bounds: {min: [-20, -40], max: [260, 40]}}
brains: [{name: rider, file: rider.brain.yaml}]
agent_types:
  - {name: lead, max_speed: 7, max_force: 20, variation: {speed: [1, 1]}, emits: {channel: leader, strength: 1, radius: 40}}
  - name: rider
    max_speed: 12
    max_force: 30
    perception: 6
    variation: {speed: [1, 1]}
    behaviours: {pursuit: 1, leader_following: 1, obstacle_avoidance: 1, separation: 1}
    brain: rider
goals: [{name: far, position: [250, 0], radius: 2}]
agents:
  - {id: 1, type: lead, position: [0, 0, 0], heading: 0, goal: far}
  - {id: 2, type: rider, position: [-6, 0, 3], heading: 0, leader: 1}
  - {id: 3, type: rider, position: [-6, 0, -3], heading: 0, leader: 1}
  - {id: 4, type: rider, position: [-10, 0, 0], heading: 0, leader: 1}
  - {id: 5, type: rider, position: [-12, 0, 4], heading: 0, leader: 1}
  - {id: 6, type: rider, position: [-12, 0, -4], heading: 0, leader: 1}
)";

// The largest distance of a rider from the leader after `seconds`.
float farthestRider(const Scene& s, float seconds)
{
    World world(s, {0, false, 1});
    if (!world.brainErrors().empty())
        qFatal("%s", world.brainErrors()[0].c_str());
    while (world.timeS() < seconds)
        world.step();
    float farthest = 0.0f;
    for (std::size_t i = 1; i < world.agentCount(); ++i)
        farthest = std::max(farthest, glm::distance(world.positions()[i], world.positions()[0]));
    return farthest;
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

class TestWorldBrainSound : public QObject {
    Q_OBJECT
private slots:
    void hearsEmittersAndBeaconsAsGeometryGives()
    {
        const Scene s = load(kHearing);
        World world(s, {0, false, 1});
        QVERIFY(world.brainErrors().empty());
        world.pickBrainAgent(0);
        world.step();
        // Loudest first: ringer 2 at 5 m (0.8 x (1 - 5/10) = 0.4), ringer 3 at 6 m (0.32),
        // the church 40 m away (1 x (1 - 40/50) = 0.2). Not itself, not the mute agent,
        // not the horn.
        const std::vector<float> dist = picked(world, 0, 1), bearing = picked(world, 0, 2),
                                 strength = picked(world, 0, 3);
        QCOMPARE(dist.size(), std::size_t(3));
        QCOMPARE(bearing.size(), std::size_t(3));
        QCOMPARE(strength.size(), std::size_t(3));
        const float expectDist[3] = {5.0f, 6.0f, 40.0f};
        // + = left; facing +x, left is -z: ringer 2 (z = +4) is 53.13 degrees right,
        // ringer 3 (z = -6) straight left, the church (z = +40) straight right.
        const float expectBearing[3] = {-53.130102f, 90.0f, -90.0f};
        const float expectStrength[3] = {0.4f, 0.32f, 0.2f};
        for (std::size_t k = 0; k < 3; ++k) {
            QVERIFY2(std::abs(dist[k] - expectDist[k]) < 1e-4f, qPrintable(QString::number(dist[k])));
            QVERIFY2(std::abs(bearing[k] - expectBearing[k]) < 1e-3f, qPrintable(QString::number(bearing[k])));
            QVERIFY2(std::abs(strength[k] - expectStrength[k]) < 1e-5f, qPrintable(QString::number(strength[k])));
        }
        const auto probes = world.brainEvaluator(0)->pickedProbes();
        auto probe = [&](const char* name) {
            for (const auto& [n, v] : probes)
                if (n == name)
                    return v;
            return -1.0f;
        };
        QCOMPARE(probe("count"), 3.0f);
        QVERIFY(std::abs(probe("loudest") - expectBearing[0]) < 1e-3f);  // the scalar sensor: the loudest
        // The ship's horn, 2 m away, is heard on its own channel only: 1 x (1 - 2/50).
        QVERIFY2(std::abs(probe("horn") - 0.96f) < 1e-5f, qPrintable(QString::number(probe("horn"))));
    }

    void walksToTheLoudestBeacon()
    {
        const Scene s = load(kBeacon);
        World world(s, {0, false, 1});
        QVERIFY(world.brainErrors().empty());
        float nearestHandbell = 1e9f;
        while (world.timeS() < 40.0) {
            world.step();
            const glm::vec2 p(world.positions()[0].x, world.positions()[0].z);
            nearestHandbell = std::min(nearestHandbell, glm::distance(p, glm::vec2(-6, -4)));
        }
        const glm::vec2 p(world.positions()[0].x, world.positions()[0].z);
        // Turned round (it started facing away), walked to the church bell and stopped
        // within a metre of it; it never went to the nearer, quieter handbell.
        QVERIFY2(glm::distance(p, glm::vec2(20, 5)) < 1.0f, qPrintable(QString("%1 %2").arg(p.x).arg(p.y)));
        QVERIFY(glm::length(world.velocities()[0]) < 0.05f);
        QVERIFY2(nearestHandbell > 4.0f, qPrintable(QString::number(nearestHandbell)));
    }

    void ridersKeepUpWithTheLeaderTheyHear()
    {
        const Scene s = load(kRide);
        // Hearing the leader, the riders keep up with it over 20 s (140 m).
        const float heard = farthestRider(s, 20.0f);
        QVERIFY2(heard < 15.0f, qPrintable(QString::number(heard)));
        // A silent leader: the same brain rides at its 5 m/s and falls behind.
        Scene silent = s;
        silent.agentTypes[0].emits = {};
        const float lost = farthestRider(silent, 20.0f);
        QVERIFY2(lost > 30.0f, qPrintable(QString::number(lost)));
    }

    void identicalOnOneAndTwoThreads()
    {
        for (const char* yaml : {kHearing, kBeacon, kChatter}) {
            const Scene s = load(yaml);
            QCOMPARE(hashRun(s, 2, 240), hashRun(s, 1, 240));
        }
    }
};

THRONG_REGISTER_TEST(TestWorldBrainSound)
#include "TestWorldBrainSound.moc"
