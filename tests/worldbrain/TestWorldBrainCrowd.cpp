// A crowd of brain walkers never freezes itself: 40 walkers with the shipped pedestrian
// brain, 20 each way along a 3 m sidewalk, get past 16 others who wait at a red crosswalk
// that opens off it, within 60 s. Before the fix none got past in 60 s: each crowded
// walker widened its personal space, so all pushed against all, and the waiters the brain
// stopped could not even be pushed aside (with only the brain fixed, 32 of 40 got past;
// with only the World's yielding, 1 of 40).
#include "TestRegistry.h"

#include "simcore/io/SceneIO.h"
#include "simcore/world/World.h"
#include "simcore/world/WorldBrain.h"

#include <QTest>

#include <algorithm>

using namespace throng::sim;

namespace {

// The sidewalk runs along x between a building (z = -3) and the kerb (z = 0), which opens
// onto the crosswalk for |x| < 1.5. The light stays red for the whole run, and without
// lanes there is no traffic signal: only the brain holds the waiters at the line.
const char* kCorner = R"(throng: 1
settings: {fps: 24, seed: 5, bounds: {min: [-40, -20], max: [40, 20]}}
brains: [{name: pedestrian, file: pedestrian.brain.yaml}]
agent_types:
  - {name: walker, radius: 0.3, max_speed: 1.4, max_force: 6, perception: 4, view_angle: 270, brain: pedestrian,
     behaviours: {arrival: 1, separation: 1.5}}
walls:
  - {points: [[-40, -3], [40, -3]]}
  - {points: [[-40, 0], [-1.5, 0]]}
  - {points: [[1.5, 0], [40, 0]]}
goals:
  - {name: across, position: [0, 10], radius: 1.5}
  - {name: east, position: [24, -1.5], radius: 1.5}
  - {name: west, position: [-24, -1.5], radius: 1.5}
crosswalks: [{name: zebra, from: [0, 0], to: [0, 8], width: 3}]
traffic_lights:
  - {name: signal, green: 5, yellow: 3, red: 200, offset: 8, stop_lines: [{crosswalk: zebra}]}
groups:
  - {name: waiting, type: walker, count: 16, rect: {min: [-1.5, -2.7], max: [1.5, -0.3]}, goal: across}
  - {name: eastward, type: walker, count: 20, rect: {min: [-20, -2.7], max: [-6, -0.3]}, goal: east}
  - {name: westward, type: walker, count: 20, rect: {min: [6, -2.7], max: [20, -0.3]}, goal: west}
)";

}  // namespace

class TestWorldBrainCrowd : public QObject {
    Q_OBJECT
private slots:
    void walkersPassAGroupWaitingAtACorner()
    {
        const LoadResult r = parseScene(kCorner, "scene.yaml", THRONG_SOURCE_DIR "/resources/brains");
        QVERIFY2(r.ok(), r.ok() ? "" : r.diagnostics[0].format().c_str());
        QVERIFY(checkSceneBrains(r.scene).empty());
        World world(r.scene, {0, false, 1});
        QVERIFY(world.brainErrors().empty());
        QCOMPARE(world.agentCount(), std::size_t(56));
        // Agents come in group order: 16 waiting, 20 eastward, 20 westward.
        auto passed = [&] {
            int n = 0;
            for (std::size_t i = 16; i < 56; ++i)
                n += (i < 36 ? world.positions()[i].x > 4.0f : world.positions()[i].x < -4.0f) ? 1 : 0;
            return n;
        };
        double allPastAt = -1.0;
        float waiterFurthest = -10.0f;
        while (world.timeS() < 60.0 && allPastAt < 0.0) {
            world.step();
            for (std::size_t i = 0; i < 16; ++i)
                waiterFurthest = std::max(waiterFurthest, world.positions()[i].z);
            if (passed() == 40)
                allPastAt = world.timeS();
        }
        qInfo("%d of 40 past the waiting group; all past after %.1f s; the waiters stayed behind z = %.2f",
              passed(), allPastAt, double(waiterFurthest));
        QCOMPARE(passed(), 40);
        QVERIFY(allPastAt > 0.0 && allPastAt <= 60.0);
        // The waiters gave way but were not pushed across: none walked out onto the red
        // crosswalk (its strip starts at z = 0; a body may touch the line).
        QVERIFY2(waiterFurthest < 0.3f, qPrintable(QString::number(waiterFurthest)));
        QCOMPARE(world.lightState(0), 2);
    }
};

THRONG_REGISTER_TEST(TestWorldBrainCrowd)
#include "TestWorldBrainCrowd.moc"
