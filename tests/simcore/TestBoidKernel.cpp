// The fused boids kernel (BoidKernel.cpp) against the general steering path: the same
// bench flock, run both ways, must fly the same way. One step apart they agree to
// rounding; after a run (where rounding has long grown chaotically) their quality figures
// agree: polarisation, nearest-neighbour distance, overlaps per step, distance to the
// lead bird. And the kernel is bit-identical for 1 and 2 threads.
#include "CrowdChecks.h"
#include "TestRegistry.h"

#include "simcore/scenarios/BenchScenarios.h"
#include "simcore/world/FlockFigures.h"

#include <QTest>

#include <cmath>
#include <cstring>

using namespace throng::sim;

namespace {

// The bench flock (separation, alignment, cohesion, pursuit of a lead bird, containment,
// wander), 1,500 birds packed at the bench's density of about one bird per 8 m^3 (the
// bench's own lattice only gets that dense at its larger counts), so every behaviour acts
// from the first step.
Scene denseFlock(float spacingM = 2.0f)
{
    Scene s = makeFlockScenario(1500, 3);
    for (std::size_t k = 1; k < s.agents.size(); ++k) {
        const auto i = float(k);
        const float jitter = 0.15f * spacingM;
        s.agents[k].position =
            glm::vec3(100.0f + spacingM * std::fmod(i, 12.0f) + jitter * std::sin(i * 12.9898f),
                      30.0f + spacingM * std::fmod(std::floor(i / 12.0f), 12.0f),
                      -12.0f + spacingM * std::floor(i / 144.0f) + jitter * std::cos(i * 78.233f));
    }
    return s;
}

World makeWorld(const Scene& s, bool kernel, int threads = 1)
{
    WorldOptions o;
    o.threads = threads;
    o.boidKernel = kernel;
    return World(s, o);
}

struct Figures {
    double polarisation = 0.0, nearestM = 0.0, overlapsPerStep = 0.0, toLeaderM = 0.0;
};

// Mean distance from each bird to its nearest other bird (brute force: the test does not
// trust the grid it checks).
double meanNearest(const World& w)
{
    const auto p = w.positions();
    double sum = 0.0;
    for (std::size_t i = 1; i < p.size(); ++i) {
        float best = INFINITY;
        for (std::size_t j = 1; j < p.size(); ++j)
            if (j != i)
                best = std::min(best, glm::distance(p[i], p[j]));
        sum += double(best);
    }
    return sum / double(p.size() - 1);
}

Figures run(const Scene& s, bool kernel, int steps)
{
    World w = makeWorld(s, kernel);
    for (int k = 0; k < steps; ++k)
        w.step();
    const FlockFigures f = FlockFigures::of(w);
    return {f.polarisation, meanNearest(w), double(w.counters().overlappingPairs) / double(steps), f.centreToLeaderM};
}

}  // namespace

class TestBoidKernel : public QObject {
    Q_OBJECT
private slots:
    void benchFlockTakesTheKernel()
    {
        // The starlings fuse; the lead bird (path following) keeps the general path.
        const World on = makeWorld(denseFlock(), true), off = makeWorld(denseFlock(), false);
        QVERIFY(on.usesBoidKernel(0));
        QVERIFY(!on.usesBoidKernel(1));
        QVERIFY(!off.usesBoidKernel(0));
    }

    void oneStepAgreesWithTheGeneralPath()
    {
        const Scene s = denseFlock();
        World a = makeWorld(s, true), b = makeWorld(s, false);
        float posDiff = 0.0f, velDiff = 0.0f, fwdDiff = 0.0f, upDiff = 0.0f, moved = 0.0f, turned = 0.0f;
        for (int k = 0; k < 3; ++k) {
            const std::vector<glm::vec3> before = throng::test::crowd::copyPositions(b);
            const std::vector<glm::vec3> velBefore(b.velocities().begin(), b.velocities().end());
            a.step();
            b.step();
            for (std::size_t i = 0; i < a.agentCount(); ++i) {
                posDiff = std::max(posDiff, glm::distance(a.positions()[i], b.positions()[i]));
                velDiff = std::max(velDiff, glm::distance(a.velocities()[i], b.velocities()[i]));
                fwdDiff = std::max(fwdDiff, glm::distance(a.forwards()[i], b.forwards()[i]));
                upDiff = std::max(upDiff, glm::distance(a.ups()[i], b.ups()[i]));
                moved = std::max(moved, glm::distance(before[i], b.positions()[i]));
                turned = std::max(turned, glm::distance(velBefore[i], b.velocities()[i]));
            }
        }
        qInfo("3 steps: largest difference kernel vs general: position %.2e m, velocity %.2e m/s, forward %.2e, "
              "up %.2e (largest move %.3f m, velocity change %.3f m/s)",
              double(posDiff), double(velDiff), double(fwdDiff), double(upDiff), double(moved), double(turned));
        // The birds do move and turn, and both paths move them the same way to rounding.
        QVERIFY(moved > 0.1f && turned > 0.1f);
        QVERIFY2(posDiff < 1e-4f, qPrintable(QString("positions differ by %1 m").arg(posDiff)));
        QVERIFY2(velDiff < 1e-3f, qPrintable(QString("velocities differ by %1 m/s").arg(velDiff)));
        QVERIFY2(fwdDiff < 1e-4f, qPrintable(QString("headings differ by %1").arg(fwdDiff)));
        // The same banking and square frame: up leans the same way.
        QVERIFY2(upDiff < 1e-4f, qPrintable(QString("ups differ by %1").arg(upDiff)));
    }

    void qualityFiguresMatchTheGeneralPath()
    {
        const Scene s = denseFlock();
        const int steps = 24 * 12;
        const Figures k = run(s, true, steps), g = run(s, false, steps);
        qInfo("after %d steps, kernel / general: polarisation %.4f / %.4f, nearest neighbour %.3f / %.3f m, "
              "overlaps per step %.2f / %.2f, centre to lead %.2f / %.2f m",
              steps, k.polarisation, g.polarisation, k.nearestM, g.nearestM, k.overlapsPerStep, g.overlapsPerStep,
              k.toLeaderM, g.toLeaderM);
        // A flock at all (else the comparison says nothing), and the same one.
        QVERIFY(g.polarisation > 0.5);
        QVERIFY(std::fabs(k.polarisation - g.polarisation) < 0.03);
        QVERIFY(std::fabs(k.nearestM - g.nearestM) < 0.05 * g.nearestM);
        QVERIFY(std::fabs(k.overlapsPerStep - g.overlapsPerStep) < std::max(0.5, 0.15 * g.overlapsPerStep));
        QVERIFY(std::fabs(k.toLeaderM - g.toLeaderM) < std::max(1.0, 0.05 * g.toLeaderM));
    }

    void packedStartSeparatesLikeTheGeneralPath()
    {
        // Birds 0.38 m apart (bodies 0.4 m across, so most start overlapping): separation
        // and the collide pass part them; both paths must do it at the same pace.
        const Scene s = denseFlock(0.38f);
        const int steps = 24;
        const Figures k = run(s, true, steps), g = run(s, false, steps);
        qInfo("packed start, %d steps, kernel / general: overlaps per step %.1f / %.1f, nearest neighbour %.3f / "
              "%.3f m",
              steps, k.overlapsPerStep, g.overlapsPerStep, k.nearestM, g.nearestM);
        QVERIFY(g.overlapsPerStep > 50.0);
        QVERIFY(std::fabs(k.overlapsPerStep - g.overlapsPerStep) < 0.05 * g.overlapsPerStep);
        QVERIFY(std::fabs(k.nearestM - g.nearestM) < 0.05 * g.nearestM);
    }

    void kernelIsBitIdenticalForOneAndTwoThreads()
    {
        const Scene s = denseFlock();
        World one = makeWorld(s, true, 1), two = makeWorld(s, true, 2);
        for (int k = 0; k < 48; ++k) {
            one.step();
            two.step();
        }
        QCOMPARE(one.agentCount(), two.agentCount());
        const std::size_t bytes = one.agentCount() * sizeof(glm::vec3);
        QVERIFY(std::memcmp(one.positions().data(), two.positions().data(), bytes) == 0);
        QVERIFY(std::memcmp(one.velocities().data(), two.velocities().data(), bytes) == 0);
        QVERIFY(std::memcmp(one.ups().data(), two.ups().data(), bytes) == 0);
    }
};

THRONG_REGISTER_TEST(TestBoidKernel)
#include "TestBoidKernel.moc"
