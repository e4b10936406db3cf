// Traffic inside the World, as a user of the crossroads demo checks it: over four minutes
// nobody runs a red light, no car touches a pedestrian, no walker crosses a wall or kerb
// or stands in a lane off the crosswalks, cars and pedestrians both get through on green;
// vehicles and heroes are agents of the recording; a hero is exactly on its keyframes and
// never pushed; 1 and 2 threads give the same frames.
#include "TestRegistry.h"

#include "simcore/io/SceneIO.h"
#include "simcore/world/RunStats.h"
#include "simcore/world/World.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <algorithm>
#include <cmath>
#include <string>

using namespace throng::sim;

namespace {
Scene crossroads()
{
    const LoadResult r = loadScene(std::string(THRONG_SOURCE_DIR) + "/resources/scenes/crossroads.yaml");
    if (!r.ok())
        qFatal("crossroads.yaml does not load");
    return r.scene;
}

// Open ground, a dense block of standing-room walkers, and a hero walking straight
// through it and out the other side.
Scene heroThroughCrowd()
{
    Scene scene;
    scene.settings.fps = 24.0f;
    scene.settings.seed = 3;
    scene.settings.boundsMin = glm::vec2(-30.0f);
    scene.settings.boundsMax = glm::vec2(30.0f);
    AgentType walker;
    walker.name = "walker";
    walker.radiusM = 0.3f;
    walker.maxSpeed = 1.4f;
    walker.maxForce = 6.0f;
    walker.perceptionM = 4.0f;
    scene.agentTypes.push_back(walker);
    SpawnGroup g;
    g.name = "crowd";
    g.type = "walker";
    g.count = 120;
    g.shape = AreaShape::Rect;
    g.min = {-6.0f, -4.0f};
    g.max = {6.0f, 4.0f};
    scene.groups.push_back(g);
    Hero h;
    h.id = 9000;
    h.name = "lead";
    h.type = "walker";
    h.clearanceM = 1.5f;
    h.keyframes = {{0.0f, {-15.0f, 0.0f, 0.5f}}, {4.0f, {-5.0f, 0.0f, 0.0f}}, {8.0f, {5.0f, 0.0f, -0.5f}},
                   {12.0f, {15.0f, 0.0f, 0.0f}}};
    scene.heroes.push_back(h);
    return scene;
}
}  // namespace

class TestWorldTraffic : public QObject {
    Q_OBJECT
private slots:
    void crossroadsFourMinutes()
    {
        const Scene scene = crossroads();
        World world(scene);
        const TrafficSystem* traffic = world.trafficSystem();
        QVERIFY(traffic);
        QCOMPARE(traffic->vehicleCount(), scene.vehicles.size());
        QCOMPARE(world.heroTracks().size(), std::size_t(1));
        const auto steps = std::uint64_t(std::llround(240.0 * double(scene.settings.fps)));
        std::uint64_t inLane = 0, maxWaiting = 0;
        for (std::uint64_t s = 0; s < steps; ++s) {
            world.step();
            std::uint64_t waiting = 0;
            for (std::size_t i = 0; i < world.agentCount(); ++i) {
                if (world.isDriven(i))
                    continue;
                const glm::vec2 p(world.positions()[i].x, world.positions()[i].z);
                if (traffic->lanes().forbiddenForPedestrian(p, 0.0f))
                    ++inLane;
                const PedestrianSignal& sig = world.traffic().signal[i];
                if (sig.mustStop && !sig.onCrosswalk && sig.crosswalk >= 0 && glm::length(world.velocities()[i]) < 0.1f)
                    ++waiting;
            }
            maxWaiting = std::max(maxWaiting, waiting);
        }
        const RunStats stats = RunStats::from(world, steps + 1, 1.0);
        qInfo("crossroads 240 s: vehicle crossings %llu, pedestrian crossings %llu, most walkers waiting at once %llu",
              (unsigned long long)stats.vehicleCrossings, (unsigned long long)stats.pedestrianCrossings,
              (unsigned long long)maxWaiting);
        QCOMPARE(stats.counters.redLightViolations, std::uint64_t(0));
        QCOMPARE(stats.vehicleRedLightViolations, std::uint64_t(0));
        QCOMPARE(traffic->counters().pedestrianRedLightViolations, std::uint64_t(0));
        QCOMPARE(stats.carPedestrianCollisions, std::uint64_t(0));
        QCOMPARE(stats.counters.wallPenetrations, std::uint64_t(0));
        QCOMPARE(stats.counters.obstaclePenetrations, std::uint64_t(0));
        QCOMPARE(stats.counters.nonFiniteValues, std::uint64_t(0));
        QCOMPARE(inLane, std::uint64_t(0));
        // Queues form at the crosswalks, and both cars and pedestrians flow on green.
        QVERIFY(maxWaiting >= 3);
        for (const StopLineFlow& f : stats.throughput) {
            QVERIFY2(f.greenPhases >= 4, qPrintable(QString::fromStdString(f.lane + f.crosswalk)));
            QVERIFY2(f.crossings > 0, qPrintable(QString::fromStdString(f.lane + f.crosswalk)));
        }
        QCOMPARE(stats.throughput.size(), std::size_t(8));  // 4 lane lines + 4 crosswalks
    }

    void vehiclesAndHeroesAreRecordedAgents()
    {
        const Scene scene = crossroads();
        World world(scene);
        const TrafficSystem& traffic = *world.trafficSystem();
        for (int s = 0; s < 48; ++s)
            world.step();
        std::vector<AgentFrame> frame;
        world.snapshot(frame);
        QCOMPARE(frame.size(), world.agentCount());
        std::size_t driven = 0;
        for (std::size_t i = 0; i < world.agentCount(); ++i)
            driven += world.isDriven(i) ? 1 : 0;
        QCOMPARE(driven, traffic.vehicleCount() + 1);
        // Each vehicle's recorded position is where the traffic put it.
        for (std::size_t v = 0; v < traffic.vehicleCount(); ++v) {
            std::size_t i = 0;
            while (world.id(i) != traffic.id(v))
                ++i;
            QVERIFY(world.isDriven(i));
            QCOMPARE(frame[i].position.x, traffic.position(v).x);
            QCOMPARE(frame[i].position.z, traffic.position(v).y);
        }
    }

    void heroOnKeyframesNeverPushed()
    {
        const Scene scene = heroThroughCrowd();
        World world(scene);
        QCOMPARE(world.heroTracks().size(), std::size_t(1));
        const HeroTrack& track = world.heroTracks().front();
        std::size_t hero = 0;
        while (world.id(hero) != 9000)
            ++hero;
        QVERIFY(world.isDriven(hero));
        const std::vector<glm::vec3> start(world.positions().begin(), world.positions().end());
        float worstKey = 0.0f, worstTrack = 0.0f, deepest = 0.0f;
        const int steps = 14 * 24;
        for (int s = 1; s <= steps; ++s) {
            world.step();
            const glm::vec3 p = world.positions()[hero];
            worstTrack = std::max(worstTrack, glm::distance(p, track.positionAt(world.timeS())));
            for (const Keyframe& k : track.keyframes())
                if (std::abs(double(k.timeS) - world.timeS()) < 1e-5)
                    worstKey = std::max(worstKey, glm::distance(p, k.position));
            // Room to act: no walker's body reaches into the clearance.
            for (std::size_t i = 0; i < world.agentCount(); ++i)
                if (i != hero) {
                    const float d = glm::distance(glm::vec2(p.x, p.z),
                                                  glm::vec2(world.positions()[i].x, world.positions()[i].z));
                    deepest = std::max(deepest, track.clearanceM() + world.radii()[i] - d);
                }
        }
        qInfo("hero: worst keyframe error %g m, worst track error %g m, deepest walker in clearance %g m",
              double(worstKey), double(worstTrack), double(deepest));
        // The hero went through the crowd, not round it: walkers on its line made room.
        std::size_t madeRoom = 0;
        for (std::size_t i = 0; i < world.agentCount(); ++i)
            if (i != hero && std::abs(start[i].z) < 1.0f && glm::distance(start[i], world.positions()[i]) > 0.5f)
                ++madeRoom;
        qInfo("walkers that made room: %zu", madeRoom);
        QVERIFY(madeRoom >= 10);
        QCOMPARE(worstKey, 0.0f);
        QCOMPARE(worstTrack, 0.0f);
        QVERIFY(deepest <= 1e-3f);
        QCOMPARE(world.counters().nonFiniteValues, std::uint64_t(0));
    }

    void sameFramesOnOneAndTwoThreads()
    {
        const Scene scene = crossroads();
        std::uint64_t hashes[2];
        TrafficCounters counters[2];
        for (int t = 1; t <= 2; ++t) {
            WorldOptions options;
            options.threads = t;
            World world(scene, options);
            FrameCache cache;
            world.startRecording(cache);
            std::vector<AgentFrame> frame;
            for (int s = 0; s < 40 * 24; ++s) {
                world.step();
                world.snapshot(frame);
                cache.append(frame);
            }
            hashes[t - 1] = cache.hash();
            counters[t - 1] = world.trafficSystem()->counters();
        }
        QCOMPARE(hashes[0], hashes[1]);
        QCOMPARE(counters[0].vehicleSteps, counters[1].vehicleSteps);
        QCOMPARE(counters[0].carPedestrianCollisions, counters[1].carPedestrianCollisions);
    }
};

THRONG_REGISTER_TEST(TestWorldTraffic)
#include "TestWorldTraffic.moc"
