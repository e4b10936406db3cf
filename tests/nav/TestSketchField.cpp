// Sketched vector fields follow the strokes (angle error at the stroke samples), run along
// walls instead of into them, are reported when there is nothing to interpolate, and bake
// to the same bits on any thread count.
#include "TestRegistry.h"
#include "NavTestMaps.h"

#include "simcore/nav/SketchField.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/trigonometric.hpp>

#include <QTest>


#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

using namespace throng::sim;
using namespace throng::test;

namespace {

Scene corridor()
{
    Scene s;
    s.settings.boundsMin = {0.0f, 0.0f};
    s.settings.boundsMax = {30.0f, 20.0f};
    s.walls.push_back({"north", {{0, 4}, {30, 4}}});
    s.walls.push_back({"south", {{0, 16}, {30, 16}}});
    s.obstacles.push_back({"pillar", ObstacleShape::Circle, {15, 10}, 1.0f, {1, 1}, 0.0f});
    return s;
}

}  // namespace

class TestSketchField : public QObject {
    Q_OBJECT
private slots:
    void fieldFollowsTheStrokes_data()
    {
        QTest::addColumn<float>("spacingM");
        QTest::newRow("a sample a metre") << 1.0f;
        QTest::newRow("dense samples, 0.25 m") << 0.25f;
    }

    void fieldFollowsTheStrokes()
    {
        QFETCH(float, spacingM);
        Scene scene;
        scene.settings.boundsMin = {0.0f, 0.0f};
        scene.settings.boundsMax = {40.0f, 30.0f};
        FlowStroke arc;  // a quarter circle, then a straight run
        for (int k = 0; k <= 12; ++k) {
            const float a = glm::half_pi<float>() * float(k) / 12.0f;
            arc.points.push_back(glm::vec2(20.0f, 25.0f) + 12.0f * glm::vec2(-std::cos(a), -std::sin(a)));
        }
        arc.points.push_back({32.0f, 13.0f});
        scene.flowStrokes.push_back(arc);
        scene.flowStrokes.push_back({{{5.0f, 28.0f}, {35.0f, 28.0f}}, 2.0f});
        NavGrid grid;
        grid.build(scene, {0.5f, 0.3f});
        SketchParams params;
        params.sampleSpacingM = spacingM;
        SketchField field;
        QVERIFY2(field.build(scene, grid, params), field.error().c_str());
        const std::vector<VectorSample> samples = strokeSamples(scene.flowStrokes, spacingM);
        QCOMPARE(field.strokeSampleCount(), samples.size());
        float worstExact = 0.0f, worstBaked = 0.0f;
        for (const VectorSample& s : samples) {
            worstExact = std::max(worstExact, angleDeg(field.evaluate(s.position), s.direction));
            worstBaked = std::max(worstBaked, angleDeg(field.sample(s.position), s.direction));
        }
        qInfo("%zu stroke samples: worst angle error %.3f deg (RBF), %.2f deg (baked grid, bilinear)", samples.size(),
              double(worstExact), double(worstBaked));
        QVERIFY(worstExact < 3.0f);
        QVERIFY(worstBaked < 5.0f);
        // Smooth: neighbouring cells turn by little (dense samples must not make it ring).
        std::vector<float> turn;
        for (int z = 0; z < grid.rows(); ++z)
            for (int x = 0; x + 1 < grid.cols(); ++x) {
                const glm::vec2 a = field.direction({x, z}), b = field.direction({x + 1, z});
                if (glm::length(a) > 0.0f && glm::length(b) > 0.0f)
                    turn.push_back(angleDeg(a, b));
            }
        std::sort(turn.begin(), turn.end());
        const float turn99 = turn[turn.size() * 99 / 100];
        qInfo("99 %% of neighbouring cells differ by less than %.2f deg", double(turn99));
        QVERIFY(turn99 < 10.0f);
        // Between the strokes the field blends them: still heading east-ish at the arc's end.
        QVERIFY(angleDeg(field.sample({31.0f, 20.0f}), {1.0f, 0.0f}) < 60.0f);
    }

    void fieldRunsAlongWallsNeverIntoThem()
    {
        Scene scene = corridor();
        scene.flowStrokes.push_back({{{2, 10}, {12, 8}, {28, 12}}, 2.0f});  // aims past the pillar and at the walls
        scene.flowStrokes.push_back({{{4, 5.5f}, {20, 14.5f}}, 2.0f});      // straight at the south wall
        NavGrid grid;
        grid.build(scene, {0.5f, 0.3f});
        SketchField field;
        QVERIFY2(field.build(scene, grid), field.error().c_str());
        QVERIFY(field.boundarySampleCount() > 40);

        // At the wall the field has no component across it (checked between boundary samples too).
        float worstCross = 0.0f;
        for (float x = 1.0f; x < 29.0f; x += 0.37f)
            for (float z : {4.0f, 16.0f}) {
                const glm::vec2 v = field.evaluate({x, z});
                if (glm::length(v) > 1e-3f)
                    worstCross = std::max(worstCross, std::abs(v.y) / glm::length(v));
            }
        qInfo("worst share of the field across a wall, on the wall line: %.3f", double(worstCross));
        QVERIFY(worstCross < 0.15f);

        // No baked cell and no sampled point leads into a blocked cell.
        int directed = 0;
        for (int i = 0; i < grid.cellCount(); ++i) {
            const NavCell c = grid.cellAt(i);
            const glm::vec2 d = field.direction(c);
            if (glm::length(d) == 0.0f)
                continue;
            ++directed;
            QVERIFY(grid.walkable(c));
            QVERIFY(grid.clearAhead(grid.centre(c), d));
        }
        std::mt19937 gen(2);
        std::uniform_real_distribution<float> ux(0.0f, 30.0f), uz(0.0f, 20.0f);
        for (int q = 0; q < 5000; ++q) {
            const glm::vec2 p(ux(gen), uz(gen)), d = field.sample(p);
            if (glm::length(d) > 0.0f)
                QVERIFY(grid.clearAhead(p, d));
        }
        QVERIFY(directed > grid.cellCount() / 2);
        // The stroke aimed at the south wall is turned along it next to the wall.
        const glm::vec2 nearWall = field.sample({20.0f, 15.2f});
        QVERIFY(glm::length(nearWall) > 0.0f && nearWall.y < 0.35f);
    }

    void nothingToInterpolateIsReported()
    {
        SketchField field;
        const Scene scene = corridor();
        NavGrid grid;
        grid.build(scene, {0.5f, 0.3f});
        QVERIFY(!field.build(scene, grid));
        QVERIFY(field.error().find("no stroke samples") != std::string::npos);
        Scene dot = scene;
        dot.flowStrokes.push_back({{{5, 10}, {5, 10}}, 2.0f});  // a click, no length
        QVERIFY(!field.build(dot, grid));
    }

    void bakesAreBitIdenticalForOneAndTwoThreads()
    {
        Scene scene = corridor();
        scene.flowStrokes.push_back({{{2, 10}, {12, 8}, {28, 12}}, 2.0f});
        NavGrid grid;
        grid.build(scene, {0.25f, 0.3f});
        SketchField one, two;
        SketchParams oneThread, twoThreads;
        oneThread.threads = 1;
        twoThreads.threads = 2;
        QVERIFY(one.build(scene, grid, oneThread));
        QVERIFY(two.build(scene, grid, twoThreads));
        for (int i = 0; i < grid.cellCount(); ++i) {
            const glm::vec2 a = one.direction(grid.cellAt(i)), b = two.direction(grid.cellAt(i));
            QVERIFY(std::memcmp(&a, &b, sizeof a) == 0);
        }
    }
};

THRONG_REGISTER_TEST(TestSketchField)
#include "TestSketchField.moc"
