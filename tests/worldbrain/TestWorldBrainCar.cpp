// Cars driven by the shipped car brain on a lane: the first waits before its stop line
// while the light is red and goes on green, the others queue behind it without touching.
// (That the car-following model bounds a brain that cannot see: TestWorldBrainCarSafety.)
#include "TestRegistry.h"

#include "simcore/io/SceneIO.h"
#include "simcore/traffic/LightPhase.h"
#include "simcore/traffic/TrafficSystem.h"
#include "simcore/world/World.h"
#include "simcore/world/WorldBrain.h"

#include <QTest>

#include <algorithm>

using namespace throng::sim;

namespace {

// A 400 m lane east along z = 0 from x = -100; its stop line 100 m along (x = 0). The
// light is red until t = 12 s, then green for 20 s. Three cars start 0..30 m along at 8 m/s.
const char* kQueue = R"(throng: 1
settings: {fps: 24, seed: 9, bounds: {min: [-120, -60], max: [320, 60]}}
brains: [{name: car, file: car.brain.yaml}]
agent_types:
  - {name: car, kind: vehicle, radius: 1.1, max_speed: 12, perception: 45, view_angle: 90, brain: car}
lanes:
  - {name: east, points: [[-100, 0], [300, 0]], width: 3.5, speed_limit: 13.9, loop: false}
traffic_lights:
  - {name: signal, green: 20, yellow: 3, red: 15, offset: 26, position: [2, 3], stop_lines: [{lane: east, at: 100}]}
vehicles:
  - {id: 1, type: car, lane: east, at: 30, speed: 8}
  - {id: 2, type: car, lane: east, at: 15, speed: 8}
  - {id: 3, type: car, lane: east, at: 0, speed: 8}
)";

Scene load(const char* yaml)
{
    const LoadResult r = parseScene(yaml, "scene.yaml", THRONG_SOURCE_DIR "/resources/brains");
    if (!r.ok())
        qFatal("%s", r.diagnostics[0].format().c_str());
    for (const Diagnostic& d : checkSceneBrains(r.scene))
        qFatal("%s", d.format().c_str());
    return r.scene;
}

struct QueueRun {
    float leadFrontAtRedEnd = 0.0f, leadSpeedAtRedEnd = -1.0f, leadFrontMaxOnRed = -1e9f;
    float crossedAt = -1.0f, smallestGap = 1e9f, topSpeed = 0.0f;
    std::uint64_t redViolations = 0, collisions = 0;
};

QueueRun drive(const Scene& s)
{
    QueueRun out;
    World world(s, {0, false, 1});
    if (!world.brainErrors().empty())
        qFatal("%s", world.brainErrors()[0].c_str());
    const TrafficSystem& ts = *world.trafficSystem();
    const float line = 100.0f;
    while (world.timeS() < 30.0) {
        world.step();
        const double t = world.timeS();
        const float front = ts.s(0) + ts.radius(0);
        if (t < 12.0)
            out.leadFrontMaxOnRed = std::max(out.leadFrontMaxOnRed, front);
        if (std::abs(t - 11.5) < 0.5 * world.dt()) {
            out.leadFrontAtRedEnd = front;
            out.leadSpeedAtRedEnd = ts.speed(0);
        }
        if (out.crossedAt < 0.0f && front > line)
            out.crossedAt = float(t);
        for (std::size_t v = 0; v < ts.vehicleCount(); ++v)
            out.topSpeed = std::max(out.topSpeed, ts.speed(v));
        for (std::size_t v = 1; v < ts.vehicleCount(); ++v)  // bumper to bumper, each behind the one before
            out.smallestGap = std::min(out.smallestGap, ts.s(v - 1) - ts.s(v) - ts.radius(v - 1) - ts.radius(v));
    }
    out.redViolations = ts.counters().vehicleRedLightViolations;
    out.collisions = ts.counters().vehicleCollisions;
    return out;
}

}  // namespace

class TestWorldBrainCar : public QObject {
    Q_OBJECT
private slots:
    void carBrainStopsOnRedGoesOnGreenKeepsItsGap()
    {
        const Scene s = load(kQueue);
        QCOMPARE(lightPhaseAt(s.trafficLights[0], 11.9), LightPhase::Red);
        QCOMPARE(lightPhaseAt(s.trafficLights[0], 12.1), LightPhase::Green);
        const QueueRun r = drive(s);
        // Waited before the line: front within 5 m of it, standing, never over it on red.
        QVERIFY2(r.leadFrontMaxOnRed < 100.0f, qPrintable(QString::number(r.leadFrontMaxOnRed)));
        QVERIFY2(r.leadFrontAtRedEnd > 95.0f, qPrintable(QString::number(r.leadFrontAtRedEnd)));
        QVERIFY2(r.leadSpeedAtRedEnd >= 0.0f && r.leadSpeedAtRedEnd < 0.1f, qPrintable(QString::number(r.leadSpeedAtRedEnd)));
        // Went on green: over the line within 4 s of the change, and up to speed later.
        QVERIFY2(r.crossedAt > 12.0f && r.crossedAt < 16.0f, qPrintable(QString::number(r.crossedAt)));
        QVERIFY2(r.topSpeed > 10.0f && r.topSpeed <= 12.0f + 1e-3f, qPrintable(QString::number(r.topSpeed)));
        // The queue behind it kept a gap: never closer than 1 m bumper to bumper.
        QVERIFY2(r.smallestGap > 1.0f, qPrintable(QString::number(r.smallestGap)));
        QCOMPARE(r.redViolations, std::uint64_t(0));
        QCOMPARE(r.collisions, std::uint64_t(0));
    }

    void crossroadsCarsDrivenByTheBrainObeyTheLightsAndTouchNobody()
    {
        // The crossroads demo (16 cars on four lanes, two signal groups, 200 walkers on the
        // crosswalks, a hero), whose cars the shipped car brain drives, for 60 s.
        LoadResult r = loadScene(THRONG_SOURCE_DIR "/resources/scenes/crossroads.yaml");
        QVERIFY(r.ok());
        const Scene& s = r.scene;
        int cars = 0;
        for (const AgentType& t : s.agentTypes)
            if (t.kind == AgentKind::Vehicle) {
                QCOMPARE(QString::fromStdString(t.brain), QString("car"));
                ++cars;
            }
        QCOMPARE(cars, 1);
        World world(s, {0, false, 1});
        QVERIFY(world.brainErrors().empty());
        while (world.timeS() < 60.0)
            world.step();
        const TrafficSystem& ts = *world.trafficSystem();
        QCOMPARE(ts.counters().vehicleRedLightViolations, std::uint64_t(0));
        QCOMPARE(ts.counters().vehicleCollisions, std::uint64_t(0));
        QCOMPARE(ts.counters().carPedestrianCollisions, std::uint64_t(0));
        std::uint64_t carCrossings = 0;
        for (const StopLineThroughput& line : ts.throughput())
            if (line.lane >= 0)
                carCrossings += line.crossings;
        // Traffic flows: the cars cross stop lines all through the minute.
        qInfo("crossroads, cars driven by the car brain: %llu stop-line crossings in 60 s",
              static_cast<unsigned long long>(carCrossings));
        QVERIFY2(carCrossings >= 30, qPrintable(QString::number(carCrossings)));
    }

    void identicalOnOneAndTwoThreads()
    {
        const Scene s = load(kQueue);
        std::vector<float> trace[2];
        for (int threads = 1; threads <= 2; ++threads) {
            World world(s, {0, false, threads});
            for (int k = 0; k < 24 * 20; ++k) {
                world.step();
                for (std::size_t v = 0; v < world.trafficSystem()->vehicleCount(); ++v)
                    trace[threads - 1].push_back(world.trafficSystem()->s(v));
            }
        }
        QVERIFY(trace[0] == trace[1]);
    }
};

THRONG_REGISTER_TEST(TestWorldBrainCar)
#include "TestWorldBrainCar.moc"
