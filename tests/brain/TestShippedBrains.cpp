// The brains in resources/brains compile, and the pedestrian brain, closing the loop over
// a tiny 1-D walker, stops before the stop line on red and walks on when it turns green.
#include "BrainRig.h"
#include "TestRegistry.h"

#include "simcore/io/SceneIO.h"

#include <QTest>

#include <algorithm>
#include <cmath>

using namespace throng;
using namespace throng::test;

namespace {

sim::BrainGraph loadShipped(const std::string& name)
{
    const std::string scene = "throng: 1\nbrains:\n  - {name: " + name + ", file: " + name + ".brain.yaml}\n";
    const sim::LoadResult r = sim::parseScene(scene, "shipped.yaml", THRONG_SOURCE_DIR "/resources/brains");
    for (const sim::Diagnostic& d : r.diagnostics)
        qWarning("%s", d.format().c_str());
    return r.ok() ? r.scene.brains[0] : sim::BrainGraph{};
}

// One pedestrian on a line: the stop line at x = 10 m, the goal at x = 30 m.
struct Walker {
    float x = 0.0f, speed = 0.0f, maxSpeed = 1.4f;
    float maxAccel = 3.0f;  // m/s², what the steering step would allow
};

}  // namespace

class TestShippedBrains : public QObject {
    Q_OBJECT
private slots:
    void everyShippedBrainCompiles_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<int>("minNodes");
        for (const char* n : {"pedestrian", "boid", "rider", "car"})
            QTest::newRow(n) << QString(n) << 20;
    }
    void everyShippedBrainCompiles()
    {
        QFETCH(QString, name);
        QFETCH(int, minNodes);
        const sim::BrainGraph g = loadShipped(name.toStdString());
        QVERIFY(int(g.nodes.size()) >= minNodes);
        const sim::BrainCompileResult r = sim::compileBrain(g);
        QString all;
        for (const sim::BrainError& e : r.errors)
            all += QString::fromStdString(e.format()) + "\n";
        QVERIFY2(r.ok(), qPrintable(all));
        QVERIFY(!r.program->outputs.empty());
    }

    void pedestrianStopsAtRedAndGoesOnGreen()
    {
        const sim::BrainGraph g = loadShipped("pedestrian");
        BrainRig rig(g, 1);
        QVERIFY2(rig.ok(), rig.errors.c_str());
        Walker w;
        const float dt = 0.1f, lineX = 10.0f, goalX = 30.0f, greenAt = 30.0f;
        float closestBeforeGreen = 1e9f, speedAtGreen = -1.0f;
        float t = 0.0f;
        for (int step = 0; step < 600; ++step, t += dt) {
            const bool red = t < greenAt;
            const bool beforeLine = w.x < lineX;
            rig.set("goal_distance", {goalX - w.x});
            rig.set("light_state", {beforeLine && red ? 1.0f : 0.0f});
            rig.set("stop_line_distance", {beforeLine ? lineX - w.x : 1e6f});
            rig.set("hero_distance", {1e6f});
            rig.set("hero_bearing", {0.0f});
            rig.set("nearest_distance", {4.0f});
            rig.set("attribute", {w.maxSpeed}, "max_speed");
            rig.step(dt);
            const float want = rig.eval->outputs().speed[0];
            w.speed += std::clamp(want - w.speed, -w.maxAccel * dt, w.maxAccel * dt);
            w.x += w.speed * dt;
            if (red) {
                QVERIFY2(w.x < lineX, qPrintable(QString("crossed the line on red at t = %1 s, x = %2").arg(t).arg(w.x)));
                closestBeforeGreen = lineX - w.x;
                speedAtGreen = w.speed;
            }
        }
        // It walked up to the line (not stopping far back) and stood still on red ...
        QVERIFY2(closestBeforeGreen < 3.0f, qPrintable(QString("stopped %1 m before the line").arg(closestBeforeGreen)));
        QVERIFY2(speedAtGreen < 0.02f, qPrintable(QString("still moving at %1 m/s on red").arg(speedAtGreen)));
        // ... then crossed on green and reached its goal, where it stands.
        QVERIFY2(std::fabs(w.x - goalX) < 1.5f, qPrintable(QString("ended at x = %1").arg(w.x)));
        QVERIFY(w.speed < 0.1f);
        QCOMPARE(rig.eval->outputs().actionNames[size_t(rig.eval->outputs().action[0])], std::string("idle"));
    }

    void pedestrianGivesWayToTheHero()
    {
        BrainRig rig(loadShipped("pedestrian"), 2);
        QVERIFY2(rig.ok(), rig.errors.c_str());
        rig.set("goal_distance", {20, 20});
        rig.set("light_state", {0, 0});
        rig.set("stop_line_distance", {1e6f, 1e6f});
        rig.set("hero_distance", {1.0f, 1.0f});
        rig.set("hero_bearing", {0.0f, 180.0f});  // agent 0: hero straight ahead; agent 1: behind
        rig.set("nearest_distance", {4, 4});
        rig.set("attribute", {1.4f, 1.4f}, "max_speed");
        for (int s = 0; s < 30; ++s)
            rig.step(0.1f);
        QVERIFY(rig.eval->outputs().speed[0] < 0.05f);
        QVERIFY(rig.eval->outputs().speed[1] > 1.3f);
    }
};

THRONG_REGISTER_TEST(TestShippedBrains)
#include "TestShippedBrains.moc"
