// Sketched fields of many long strokes: the field still follows every stroke, and the
// solve grows with the strokes instead of with their square. What a user saw before: the
// RBF system was one dense matrix over every sample, so 50 strokes took 17 s and 1 GB to
// load and 300 strokes of 100 m (a busy painted plaza) aborted with std::bad_alloc; the
// 20 strokes of 280 m here (5,600 samples) asked for a 1 GB matrix and minutes of
// factorising. Timings are in bench/SketchBench.cpp, not here.
#include "TestRegistry.h"
#include "NavTestMaps.h"

#include "simcore/nav/SketchField.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <QTest>


#include <algorithm>
#include <cmath>
#include <cstring>

using namespace throng::sim;
using namespace throng::test;

namespace {

// A 300 x 130 m concourse with 20 wavy lanes 6 m apart, 280 m long, walked in turn east
// and west (the hardest layout for a smooth field: opposite flows side by side), and a
// wall along each long side.
Scene concourse()
{
    Scene s;
    s.settings.boundsMin = {-150.0f, -10.0f};
    s.settings.boundsMax = {150.0f, 120.0f};
    s.walls.push_back({"north", {{-150, -6}, {150, -6}}});
    s.walls.push_back({"south", {{-150, 118}, {150, 118}}});
    for (int lane = 0; lane < 20; ++lane) {
        FlowStroke f;
        const float z = 2.0f + 6.0f * float(lane);
        for (int k = 0; k <= 56; ++k) {
            const float x = -140.0f + 5.0f * float(k);
            f.points.push_back({x, z + 1.5f * std::sin(x * 6.2831853f / 40.0f + float(lane))});
        }
        if (lane % 2)
            std::reverse(f.points.begin(), f.points.end());
        s.flowStrokes.push_back(f);
    }
    return s;
}

}  // namespace

class TestSketchFieldScale : public QObject {
    Q_OBJECT
private slots:
    void manyLongStrokesAreFollowed()
    {
        const Scene scene = concourse();
        NavGrid grid;
        grid.build(scene, {0.5f, 0.3f});
        SketchField field;
        QVERIFY2(field.build(scene, grid), field.error().c_str());
        QVERIFY(field.strokeSampleCount() > 5000);
        QVERIFY(field.patchCount() > 1);  // solved in local patches, not one dense system
        const std::vector<VectorSample> samples = strokeSamples(scene.flowStrokes, 1.0f);
        float worstExact = 0.0f, worstBaked = 0.0f, worstBetween = 0.0f;
        for (std::size_t k = 0; k < samples.size(); ++k) {
            const VectorSample& s = samples[k];
            worstExact = std::max(worstExact, angleDeg(field.evaluate(s.position), s.direction));
            worstBaked = std::max(worstBaked, angleDeg(field.sample(s.position), s.direction));
            // Half-way to the next sample of the same stroke, off the sample points.
            if (k + 1 < samples.size() && glm::distance(samples[k + 1].position, s.position) < 1.5f)
                worstBetween = std::max(worstBetween, angleDeg(field.evaluate(0.5f * (s.position + samples[k + 1].position)),
                                                              s.direction + samples[k + 1].direction));
        }
        qInfo("%zu stroke samples in %zu patches: worst angle %.2f deg at the samples, %.2f between them, %.2f baked",
              samples.size(), field.patchCount(), double(worstExact), double(worstBetween), double(worstBaked));
        QVERIFY(worstExact < 3.0f);
        QVERIFY(worstBetween < 5.0f);
        QVERIFY(worstBaked < 10.0f);
    }

    void patchesBakeBitIdenticallyOnAnyThreadCount()
    {
        const Scene scene = concourse();
        NavGrid grid;
        grid.build(scene, {1.0f, 0.3f});
        SketchField one, two;
        SketchParams oneThread, twoThreads;
        oneThread.threads = 1;
        twoThreads.threads = 2;
        QVERIFY(one.build(scene, grid, oneThread));
        QVERIFY(two.build(scene, grid, twoThreads));
        QVERIFY(one.patchCount() > 1);
        for (int i = 0; i < grid.cellCount(); ++i) {
            const glm::vec2 a = one.direction(grid.cellAt(i)), b = two.direction(grid.cellAt(i));
            QVERIFY(std::memcmp(&a, &b, sizeof a) == 0);
        }
    }
};

THRONG_REGISTER_TEST(TestSketchFieldScale)
#include "TestSketchFieldScale.moc"
