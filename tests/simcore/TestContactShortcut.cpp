// The contact rounds' shortcut (Collide.cpp: settleContacts): the first round passes by the
// walkers the collide pass found clear of contact, and each later round those round whom
// nothing moved in the round before. It must change nothing: the same scene run with and
// without it ends bit-identical, with the same overlaps counted, for 1 and 2 threads, in a
// room packed at its door (walls that push walkers back, at 12, 24 and 60 fps, and at map
// coordinates), in the cross's rings through their dense middle, and in two armies
// charging each other. And it must be taken: a good part of the work is passed by, and
// some is not.
#include "RunBits.h"
#include "TestRegistry.h"

#include "simcore/io/SceneIO.h"
#include "simcore/scenarios/BenchScenarios.h"
#include "simcore/world/World.h"

#include <QTest>

#include <cstdio>
#include <string>

using namespace throng::sim;

namespace {

// A 14 m x 16 m room whose east wall has a 1.2 m door with an exit across it, and 300
// walkers spawned over 12 m x 14 m (2.1 persons/m²) who all make for it at up to `speed`
// m/s; everything shifted by (dx, dz) m.
Scene packedRoom(float fps, float speed, double dx = 0.0, double dz = 0.0)
{
    auto p = [&](double x, double z) {
        char t[64];
        std::snprintf(t, sizeof t, "[%.3f, %.3f]", x + dx, z + dz);
        return std::string(t);
    };
    char settings[256];
    std::snprintf(settings, sizeof settings, "settings: {fps: %g, seed: 7, bounds: {min: %s, max: %s}}\n", double(fps),
                  p(-16, -10).c_str(), p(4, 10).c_str());
    const std::string yaml = "throng: 1\n" + std::string(settings) +
                             "agent_types:\n"
                             "  - {name: walker, radius: 0.3, max_speed: " + std::to_string(speed) + "}\n"
                             "walls:\n"
                             "  - {points: [" + p(0, 0.6) + ", " + p(0, 8) + ", " + p(-14, 8) + ", " + p(-14, -8) +
                             ", " + p(0, -8) + ", " + p(0, -0.6) + "]}\n"
                             "goals:\n"
                             "  - {name: door, position: " + p(0.3, 0) + ", radius: 0.6, exit: true}\n"
                             "groups:\n"
                             "  - {name: crowd, type: walker, count: 300, rect: {min: " + p(-13, -7) + ", max: " +
                             p(-1, 7) + "}, goal: door}\n";
    const LoadResult r = parseScene(yaml, "room.yaml", ".");
    if (!r.ok())
        qFatal("%s", r.diagnostics[0].format().c_str());
    return r.scene;
}

// 144 runners (up to 6 m/s, radius 0.3 m) placed 0.4 m apart on a 12 x 12 square, each
// making for the far side of a wide field.
Scene huddle()
{
    std::string yaml = "throng: 1\n"
                       "settings: {fps: 24, seed: 3, bounds: {min: [-40, -40], max: [40, 40]}}\n"
                       "agent_types:\n"
                       "  - {name: runner, radius: 0.3, max_speed: 6}\n"
                       "goals:\n"
                       "  - {name: east, position: [35, 0], radius: 4}\n"
                       "  - {name: west, position: [-35, 0], radius: 4}\n"
                       "agents:\n";
    for (int k = 0; k < 144; ++k) {
        char line[160];
        std::snprintf(line, sizeof line, "  - {id: %d, type: runner, position: [%.2f, 0, %.2f], goal: %s}\n", k + 1,
                      0.4 * (k % 12), 0.4 * (k / 12), k % 2 ? "east" : "west");
        yaml += line;
    }
    const LoadResult r = parseScene(yaml, "huddle.yaml", ".");
    if (!r.ok())
        qFatal("%s", r.diagnostics[0].format().c_str());
    return r.scene;
}

Scene bench(const char* name, std::uint32_t agents)
{
    Scene s;
    if (!makeBenchScenario(name, agents, s))
        qFatal("no bench scenario %s", name);
    return s;
}

struct Run {
    throng::test::RunBits bits;
    ContactRounds rounds;
};

Run run(const Scene& s, bool shortcut, int threads, int steps)
{
    WorldOptions o;
    o.threads = threads;
    o.contactShortcut = shortcut;
    World w(s, o);
    for (int k = 0; k < steps; ++k)
        w.step();
    return {throng::test::bitsOf(w), w.contactRounds()};
}

// Runs the scene without the shortcut (1 thread) and with it (1 and 2 threads): all three
// must agree bit for bit, the runs without it pass nobody by, and those with it pass by
// more than `leastPassed` of the agents the rounds go through, and work out some. In
// marginBroken: the decisions whose first round went through every agent
// (ContactRounds::marginBroken).
void checkSame(const Scene& s, int steps, double leastPassed, std::uint64_t* marginBroken = nullptr)
{
    const Run full = run(s, false, 1, steps);
    QCOMPARE(full.rounds.passedBy, std::uint64_t(0));
    QVERIFY(full.rounds.agents > 0);
    for (int threads : {1, 2}) {
        const Run fast = run(s, true, threads, steps);
        QVERIFY2(full.bits.sameStateAs(fast.bits), qPrintable(QString("%1 threads").arg(threads)));
        QCOMPARE(fast.bits.overlaps, full.bits.overlaps);
        QCOMPARE(fast.rounds.agents, full.rounds.agents);
        const double passed = double(fast.rounds.passedBy) / double(fast.rounds.agents);
        qInfo("%d threads: %.1f %% of %llu passed by, %llu overlapping pairs", threads, 100.0 * passed,
              static_cast<unsigned long long>(fast.rounds.agents), static_cast<unsigned long long>(full.bits.overlaps));
        QVERIFY(passed > leastPassed);
        QVERIFY(fast.rounds.passedBy < fast.rounds.agents);
        if (marginBroken)
            *marginBroken = fast.rounds.marginBroken;
    }
}

}  // namespace

class TestContactShortcut : public QObject {
    Q_OBJECT
private slots:
    void packedRoomIsUnchanged_data()
    {
        QTest::addColumn<float>("fps");
        QTest::addColumn<float>("speed");
        QTest::addColumn<double>("offset");
        QTest::newRow("24 fps") << 24.0f << 1.4f << 0.0;
        QTest::newRow("12 fps") << 12.0f << 1.4f << 0.0;
        QTest::newRow("30 fps") << 30.0f << 1.4f << 0.0;
        QTest::newRow("60 fps") << 60.0f << 1.4f << 0.0;
        QTest::newRow("24 fps, 500 km out") << 24.0f << 1.4f << 500000.0;
        QTest::newRow("runners at 24 fps") << 24.0f << 6.0f << 0.0;
    }
    void packedRoomIsUnchanged()
    {
        QFETCH(float, fps);
        QFETCH(float, speed);
        QFETCH(double, offset);
        // 12 s: the crowd presses into the door and the first walkers are out.
        std::uint64_t marginBroken = 0;
        checkSame(packedRoom(fps, speed, offset, -offset), int(12.0f * fps), 0.2, &marginBroken);
        if (QTest::currentTestFailed())
            return;
        QCOMPARE(marginBroken, std::uint64_t(0));
    }

    void huddleOfRunnersIsUnchanged()
    {
        // Runners placed a third into each other: the collide pass pushes them apart by up
        // to half a step at 6 m/s, farther than the first round's proofs allow, and that
        // round then goes through everyone.
        std::uint64_t marginBroken = 0;
        checkSame(huddle(), 96, 0.2, &marginBroken);
        if (QTest::currentTestFailed())
            return;
        qInfo("%llu decisions with the first round in full", static_cast<unsigned long long>(marginBroken));
        QVERIFY(marginBroken > 0);
    }

    void crossThroughItsMiddleIsUnchanged()
    {
        // 2,000 walkers on the rings for 40 s: the inner rings meet in the middle.
        checkSame(bench("cross", 2000), 960, 0.5);
    }

    void armiesChargingAreUnchanged()
    {
        checkSame(bench("army", 1000), 480, 0.2);
    }
};

THRONG_REGISTER_TEST(TestContactShortcut)
#include "TestContactShortcut.moc"
