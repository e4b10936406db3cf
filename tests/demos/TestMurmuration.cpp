// The murmuration demo, reduced to 2,000 starlings in the same density: they stay one
// flock (fly one way, nobody strays) and follow the migrating target round its circuit.
#include "DemoRuns.h"
#include "TestRegistry.h"

#include "simcore/world/FlockFigures.h"

#include <QTest>

#include <algorithm>
#include <cmath>

using namespace throng::sim;
using namespace throng::test::demos;

namespace {

Scene reducedMurmuration()
{
    Scene s = demo("murmuration.yaml");
    SpawnGroup& flock = s.groups.at(0);
    // The same density: the spawn disk's area scales with the count.
    flock.radiusM *= std::sqrt(2000.0f / float(flock.count));
    flock.count = 2000;
    return s;
}

}  // namespace

class TestMurmuration : public QObject {
    Q_OBJECT
private slots:
    void starlingsFlockAndFollowTheTarget()
    {
        const Scene scene = reducedMurmuration();
        World world(scene, threads(2));
        const glm::vec3 targetStart = world.positions()[0];
        float worstPolarisation = 1.0f;
        while (world.timeS() < 20.0) {
            world.step();
            if (world.timeS() > 5.0)  // after the first seconds of sorting out
                worstPolarisation = std::min(worstPolarisation, float(FlockFigures::of(world).polarisation));
        }
        QCOMPARE(world.counters().nonFiniteValues, std::uint64_t(0));
        const FlockFigures f = FlockFigures::of(world);
        QCOMPARE(f.fliers, std::uint64_t(2001));
        // The target migrated...
        QVERIFY(glm::distance(world.positions()[0], targetStart) > 100.0f);
        // ...and the flock flies one way, together, beside it.
        QVERIFY2(worstPolarisation > 0.8f, qPrintable(QString::number(worstPolarisation)));
        QVERIFY2(f.centreToLeaderM < 20.0f, qPrintable(QString::number(f.centreToLeaderM)));
        glm::dvec3 centre(0.0);
        for (glm::vec3 p : world.positions())
            centre += glm::dvec3(p);
        centre /= double(world.agentCount());
        float furthest = 0.0f;
        for (glm::vec3 p : world.positions())
            furthest = std::max(furthest, float(glm::distance(glm::dvec3(p), centre)));
        qInfo("2,000 starlings at 20 s: polarisation %.3f (worst after 5 s %.3f), RMS spread %.1f m, furthest %.1f m "
              "from the centre, centre to target %.1f m", f.polarisation, double(worstPolarisation), f.spreadM,
              double(furthest), f.centreToLeaderM);
        QVERIFY2(furthest < 40.0f, qPrintable(QString::number(furthest)));
    }

    void identicalOnOneAndTwoThreads()
    {
        const Scene s = reducedMurmuration();
        QCOMPARE(runHash(s, 2, 120), runHash(s, 1, 120));
    }
};

THRONG_REGISTER_TEST(TestMurmuration)
#include "TestMurmuration.moc"
