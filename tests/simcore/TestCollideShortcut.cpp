// The collide pass's shortcut for boids (WorldStep.cpp, BoidKernel.cpp): the kernel flags
// birds none of whose neighbours can end the step within contact distance, and the pass
// skips their overlap search. It must change nothing: the same flock run with and without
// the shortcut ends bit-identical, for 1 and 2 threads, whether birds start packed
// (overlaps everywhere), at the bench's density, or skimming the ground (where the floor
// lifts birds further than the kernel's slack and the pass must run in full).
#include "RunBits.h"
#include "TestRegistry.h"

#include "simcore/scenarios/BenchScenarios.h"
#include "simcore/world/World.h"

#include <QTest>

using namespace throng::sim;

namespace {

// The bench flock, 1,500 birds on a jittered lattice of the given spacing from height y0.
Scene packedFlock(float spacingM, float y0 = 30.0f)
{
    Scene s = makeFlockScenario(1500, 5);
    throng::test::packOnLattice(s, spacingM, 0.15f * spacingM, y0);
    return s;
}

throng::test::RunBits run(const Scene& s, bool shortcut, int threads, int steps)
{
    WorldOptions o;
    o.threads = threads;
    o.collideShortcut = shortcut;
    return throng::test::runToEnd(s, o, steps);
}

// Runs the scene without the shortcut (1 thread) and with it (1 and 2 threads); all three
// must agree bit for bit. Returns the overlaps counted.
std::uint64_t checkSame(const Scene& s, int steps)
{
    const throng::test::RunBits full = run(s, false, 1, steps);
    for (int threads : {1, 2}) {
        const throng::test::RunBits fast = run(s, true, threads, steps);
        if (!full.sameStateAs(fast) || full.overlaps != fast.overlaps) {
            qWarning("shortcut with %d threads differs: overlaps %llu vs %llu", threads,
                     static_cast<unsigned long long>(fast.overlaps), static_cast<unsigned long long>(full.overlaps));
            return UINT64_MAX;
        }
    }
    return full.overlaps;
}

}  // namespace

class TestCollideShortcut : public QObject {
    Q_OBJECT
private slots:
    void packedStartIsUnchanged()
    {
        // Bodies 0.4 m across, 0.38 m apart: the collide pass has work nearly everywhere.
        const std::uint64_t overlaps = checkSame(packedFlock(0.38f), 24);
        qInfo("packed start: %llu overlapping pairs over 24 steps", static_cast<unsigned long long>(overlaps));
        QVERIFY(overlaps != UINT64_MAX);
        QVERIFY(overlaps > 24 * 50);
    }

    void benchDensityIsUnchanged()
    {
        // About one bird per 8 m^3, flying for 4 s: most birds are flagged, some collide.
        const std::uint64_t overlaps = checkSame(packedFlock(2.0f), 96);
        qInfo("bench density: %llu overlapping pairs over 96 steps", static_cast<unsigned long long>(overlaps));
        QVERIFY(overlaps != UINT64_MAX);
    }

    void skimmingTheGroundIsUnchanged()
    {
        // Birds packed just above the ground: the floor lifts those that dive, further than
        // the kernel's slack, so the pass has to notice and run in full.
        const std::uint64_t overlaps = checkSame(packedFlock(0.5f, 0.05f), 24);
        QVERIFY(overlaps != UINT64_MAX);
    }
};

THRONG_REGISTER_TEST(TestCollideShortcut)
#include "TestCollideShortcut.moc"
