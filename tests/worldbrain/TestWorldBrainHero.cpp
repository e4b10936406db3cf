// The hero sensors in a World with a keyframed hero: a walker whose brain stops while the
// hero is nearer than 5 m stops as the hero comes by and walks on once it has passed.
#include "TestRegistry.h"

#include "simcore/brain/BrainEvaluator.h"
#include "simcore/io/SceneIO.h"
#include "simcore/world/World.h"
#include "simcore/world/WorldBrain.h"

#include <glm/geometric.hpp>

#include <QTest>

using namespace throng::sim;

namespace {

// The walker heads east from x = 0 to x = 30 at 1.2 m/s; the hero walks west along
// z = 3 from x = 30 (t = 0) to x = -10 (t = 20 s), passing 3 m beside it.
const char* kHeroPasses = R"(throng: 1
settings: {fps: 24, seed: 6, bounds: {min: [-40, -40], max: [40, 40]}}
agent_types:
  - {name: walker, max_speed: 1.2, variation: {speed: [1, 1]}, brain: wary}
  - {name: hero, max_speed: 3}
goals: [{name: east, position: [30, 0], radius: 0.5}]
agents: [{id: 1, type: walker, position: [0, 0, 0], heading: 0, goal: east}]
heroes:
  - name: star
    id: 50
    type: hero
    clearance: 1
    keyframes:
      - {time: 0, position: [30, 0, 3]}
      - {time: 20, position: [-10, 0, 3]}
brains:
  - name: wary
    nodes:
      - {id: 1, type: input, params: {sensor: hero_distance}}
      - {id: 2, type: math.compare, params: {mode: lt, value: 5}}
      - {id: 3, type: rule.not}
      - {id: 4, type: output, params: {channel: speed, scale: 1.2}}
      - {id: 5, type: input, params: {sensor: hero_bearing}}
      - {id: 6, type: probe, params: {name: bearing}}
    links:
      - {from: [1, 0], to: [2, 0]}
      - {from: [2, 0], to: [3, 0]}
      - {from: [3, 0], to: [4, 0]}
      - {from: [5, 0], to: [6, 0]}
)";

glm::vec2 xz(glm::vec3 v) { return {v.x, v.z}; }

}  // namespace

class TestWorldBrainHero : public QObject {
    Q_OBJECT
private slots:
    void stopsWhileTheHeroIsNearThenWalksOn()
    {
        const LoadResult r = parseScene(kHeroPasses, "scene.yaml", "");
        QVERIFY2(r.ok(), r.ok() ? "" : r.diagnostics[0].format().c_str());
        QVERIFY(checkSceneBrains(r.scene).empty());
        World world(r.scene, {0, false, 1});
        QVERIFY(world.brainErrors().empty());
        QCOMPARE(world.heroTracks().size(), std::size_t(1));
        world.pickBrainAgent(0);
        float stoppedAt = -1.0f, walkedOnAt = -1.0f, speedWhileNear = 0.0f, closest = 1e9f;
        float bearingAt2s = 0.0f;
        while (world.timeS() < 40.0) {
            const glm::vec2 heroBefore = xz(world.positions()[1]);
            const float before = glm::distance(xz(world.positions()[0]), heroBefore);
            world.step();
            const double t = world.timeS();
            const float v = glm::length(world.velocities()[0]);
            closest = std::min(closest, before);
            if (std::abs(t - 2.0) < 0.5 * world.dt())
                for (const auto& [name, value] : world.brainEvaluator(0)->pickedProbes())
                    if (name == "bearing")
                        bearingAt2s = value;
            if (stoppedAt < 0.0f && t > 1.0 && v < 0.01f)
                stoppedAt = float(t);
            // The brain saw the hero within 5 m at the step's start: it must not move.
            if (before < 4.9f)
                speedWhileNear = std::max(speedWhileNear, v);
            if (stoppedAt > 0.0f && walkedOnAt < 0.0f && v > 0.5f)
                walkedOnAt = float(t);
        }
        // The hero comes within 5 m at t = 8.1 s (x gap 30 - 3.2 t = 4 m); the walker
        // stops then, stands while the hero passes, and walks on once it is 5 m behind
        // (hero at x = 9.7 - 4 at t = 12.1 s).
        QVERIFY2(stoppedAt > 7.5f && stoppedAt < 8.6f, qPrintable(QString::number(stoppedAt)));
        QVERIFY2(speedWhileNear < 0.01f, qPrintable(QString::number(speedWhileNear)));
        QVERIFY2(walkedOnAt > 11.5f && walkedOnAt < 13.0f, qPrintable(QString::number(walkedOnAt)));
        QVERIFY2(closest > 3.0f - 1e-3f && closest < 3.2f, qPrintable(QString::number(closest)));
        QVERIFY(world.hasArrived(0));
        // At 2 s the hero is ahead and 3 m to the right (+z): a small negative bearing,
        // -atan(3 / (30 - 2 x 2 - 2.4)) = -7.2 degrees.
        QVERIFY2(bearingAt2s < -6.5f && bearingAt2s > -8.0f, qPrintable(QString::number(bearingAt2s)));
    }

    void withoutHeroesTheSensorSaysNobodyIsNear()
    {
        LoadResult r = parseScene(kHeroPasses, "scene.yaml", "");
        r.scene.heroes.clear();
        World world(r.scene, {0, false, 1});
        QVERIFY(world.brainErrors().empty());
        float slowest = 1e9f;
        while (world.timeS() < 20.0) {
            world.step();
            if (world.timeS() > 2.0 && !world.hasArrived(0))
                slowest = std::min(slowest, glm::length(world.velocities()[0]));
        }
        QVERIFY2(slowest > 1.0f, qPrintable(QString::number(slowest)));
    }
};

THRONG_REGISTER_TEST(TestWorldBrainHero)
#include "TestWorldBrainHero.moc"
