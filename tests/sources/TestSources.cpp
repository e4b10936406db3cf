// Sources (issue 26): streams of agents that enter the scene during the run. The file
// format reads, writes and refuses them with their line; arrivals come on time (steady),
// as a Poisson process of the asked rate (seeded), within their windows, up to their cap,
// with the asked mix of types; an agent is off stage (not present, not simulated, not
// perceived) until its time and enters only where its body fits; the stats count every
// entry (checked against a recount from the frames); checkpoints, edits, thread counts,
// frame rates and the CSV export all handle agents that appear mid-shot.
#include "TestRegistry.h"

#include "export/TrajectoryCsv.h"
#include "simcore/io/SceneIO.h"
#include "simcore/world/FrameCache.h"
#include "simcore/world/RunStats.h"
#include "simcore/world/Sources.h"
#include "simcore/world/World.h"
#include "simcore/world/WorldState.h"

#include <QTemporaryDir>
#include <QTest>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <numeric>
#include <set>
#include <sstream>

using namespace throng;
using namespace throng::sim;

namespace {

sim::Scene parseSources(const std::string& yaml)
{
    const LoadResult r = parseScene(yaml, "sources.yaml", "");
    if (!r.ok())
        qFatal("%s", r.diagnostics[0].format().c_str());
    return r.scene;
}

// A corridor 40 m long: walkers come in at the west end and leave through the east door.
std::string corridor(const std::string& source, float fps = 24.0f, float duration = 30.0f)
{
    std::ostringstream y;
    y << "throng: 1\nsettings: {fps: " << fps << ", seed: 5, duration: " << duration
      << ", bounds: {min: [-30, -10], max: [30, 10]}}\n"
         "agent_types:\n"
         "  - {name: walker, max_speed: 1.3, behaviours: {seek: 1, separation: 1}}\n"
         "  - {name: runner, max_speed: 2.5, behaviours: {seek: 1, separation: 1}}\n"
         "goals:\n  - {name: door, position: [20, 0], radius: 1.5, exit: true}\n"
         "paths:\n  - {name: p, points: [[-20, 0], [20, 0]]}\n"
         "sources:\n"
      << source;
    return y.str();
}

struct Run {
    Scene scene;
    FrameCache cache;
    RunStats stats;
};

Run record(const std::string& yaml, double seconds, int threads = 1)
{
    Run r;
    r.scene = parseSources(yaml);
    World world(r.scene, WorldOptions{0, false, threads});
    world.startRecording(r.cache);
    std::vector<AgentFrame> frame;
    std::vector<std::uint64_t> inScene;
    RunStats::sampleInScene(world, inScene);
    while (world.timeS() < seconds - 1e-9) {
        world.step();
        world.snapshot(frame);
        r.cache.append(frame);
        RunStats::sampleInScene(world, inScene);
    }
    r.stats = RunStats::from(world, r.cache.frameCount(), 0.0);
    r.stats.inSceneEachSecond = inScene;
    return r;
}

// The first frame agent i is present on; frameCount() if never.
std::size_t firstPresent(const FrameCache& cache, std::size_t i)
{
    std::size_t f = 0;
    while (f < cache.frameCount() && !cache.at(f, i).present)
        ++f;
    return f;
}

}  // namespace

class TestSources : public QObject {
    Q_OBJECT

private slots:
    // Every key reads, writes and reads back the same.
    void theFileRoundTrips()
    {
        const Scene s = parseSources(corridor(
            "  - {name: west, type: walker, line: [[-20, -1], [-20, 1]], rate: 0.5, goal: door}\n"
            "  - {name: yard, types: {walker: 3, runner: 1.5}, rect: {min: [-25, 4], max: [-22, 8]}, rate: 2,\n"
            "     arrivals: poisson, windows: [[0, 10], [20, 25.5]], goal: door, cap: 40, heading: 90}\n"));
        QCOMPARE(s.sources.size(), std::size_t(2));
        const Source& yard = s.sources[1];
        QCOMPARE(yard.types.size(), std::size_t(2));
        QCOMPARE(yard.types[0].type, std::string("walker"));
        QCOMPARE(yard.types[1].weight, 1.5f);
        QCOMPARE(int(yard.shape), int(SourceShape::Rect));
        QCOMPARE(int(yard.arrivals), int(Arrivals::Poisson));
        QCOMPARE(yard.windows.size(), std::size_t(2));
        QCOMPARE(yard.windows[1].y, 25.5f);
        QCOMPARE(yard.cap, 40u);
        QVERIFY(yard.headed);
        QCOMPARE(s.sources[0].from, glm::vec2(-20.0f, -1.0f));
        const std::string written = sceneToYaml(s);
        const Scene again = parseSources(written);
        QVERIFY2(again.sources == s.sources, written.c_str());
        QCOMPARE(sceneToYaml(again), written);
    }

    void badSourcesNameTheirLine_data()
    {
        QTest::addColumn<QString>("source");
        QTest::addColumn<QString>("message");
        QTest::newRow("no type") << "  - {name: a, line: [[0, 0], [0, 1]], rate: 1, goal: door}\n"
                                 << "give the agents' 'type'";
        QTest::newRow("unknown type") << "  - {name: a, type: ghost, line: [[0, 0], [0, 1]], rate: 1, goal: door}\n"
                                      << "ghost";
        QTest::newRow("unknown type in a mix")
            << "  - {name: a, types: {walker: 1, ghost: 2}, line: [[0, 0], [0, 1]], rate: 1, goal: door}\n"
            << "no agent type named 'ghost'";
        QTest::newRow("zero weight")
            << "  - {name: a, types: {walker: 0}, line: [[0, 0], [0, 1]], rate: 1, goal: door}\n" << "types.walker";
        QTest::newRow("no place") << "  - {name: a, type: walker, rate: 1, goal: door}\n" << "where agents enter";
        QTest::newRow("three points") << "  - {name: a, type: walker, line: [[0, 0], [0, 1], [1, 1]], rate: 1}\n"
                                      << "two points";
        QTest::newRow("rect backwards")
            << "  - {name: a, type: walker, rect: {min: [5, 0], max: [0, 5]}, rate: 1, goal: door}\n"
            << "min must not exceed max";
        QTest::newRow("no rate") << "  - {name: a, type: walker, line: [[0, 0], [0, 1]], goal: door}\n" << "rate";
        QTest::newRow("negative rate") << "  - {name: a, type: walker, line: [[0, 0], [0, 1]], rate: -1}\n"
                                       << "rate";
        QTest::newRow("bad arrivals")
            << "  - {name: a, type: walker, line: [[0, 0], [0, 1]], rate: 1, arrivals: bursty}\n"
            << "'steady' or 'poisson'";
        QTest::newRow("window backwards")
            << "  - {name: a, type: walker, line: [[0, 0], [0, 1]], rate: 1, windows: [[5, 2]]}\n"
            << "start must come before its end";
        QTest::newRow("windows overlap")
            << "  - {name: a, type: walker, line: [[0, 0], [0, 1]], rate: 1, windows: [[0, 5], [4, 8]]}\n"
            << "must not overlap";
        QTest::newRow("goal and path")
            << "  - {name: a, type: walker, line: [[0, 0], [0, 1]], rate: 1, goal: door, path: p}\n" << "not both";
        QTest::newRow("unknown goal") << "  - {name: a, type: walker, line: [[0, 0], [0, 1]], rate: 1, goal: gate}\n"
                                      << "gate";
        QTest::newRow("too many") << "  - {name: a, type: walker, line: [[0, 0], [0, 1]], rate: 1000000}\n"
                                  << "10,000,000";
    }

    // A wrong source is refused with its file and line (the sources' first).
    void badSourcesNameTheirLine()
    {
        QFETCH(QString, source);
        QFETCH(QString, message);
        const std::string text = corridor(source.toStdString());
        const auto sourcesAt = text.begin() + std::ptrdiff_t(text.find("sources:"));
        const auto sourcesLine = std::count(text.begin(), sourcesAt, '\n') + 1;
        const std::string where = "bad.yaml:" + std::to_string(sourcesLine + 1) + ":";
        const LoadResult r = parseScene(text, "bad.yaml", "");
        QVERIFY(!r.ok());
        bool found = false;
        for (const Diagnostic& d : r.diagnostics)
            if (d.severity == Severity::Error) {
                const std::string text = d.format();
                found = found || (text.find(message.toStdString()) != std::string::npos && text.find(where) == 0);
            }
        QVERIFY2(found, qPrintable(QString::fromStdString(r.diagnostics[0].format())));
    }

    // Steady: one every 1 / rate seconds from each window's start; the last before its end.
    void steadyArrivalsComeOnTime()
    {
        const Scene s = parseSources(corridor(
            "  - {name: west, type: walker, line: [[-20, -1], [-20, 1]], rate: 2, windows: [[1, 3], [5, 6.2]], "
            "goal: door}\n"));
        const std::vector<SourceArrival> a = sourceArrivals(s, 0, 5);
        std::vector<double> times;
        for (const SourceArrival& x : a)
            times.push_back(x.timeS);
        QCOMPARE(times, (std::vector<double>{1.0, 1.5, 2.0, 2.5, 5.0, 5.5, 6.0}));
        for (const SourceArrival& x : a) {
            QCOMPARE(x.place.x, -20.0f);
            QVERIFY(x.place.y >= -1.0f && x.place.y <= 1.0f);
            // Facing the door, to the east.
            QVERIFY(std::abs(x.headingRad - std::atan2(-(0.0f - x.place.y), 40.0f)) < 1e-5f);
        }
        // A cap of 3 stops it after three.
        const Scene capped = parseSources(corridor(
            "  - {name: west, type: walker, line: [[-20, -1], [-20, 1]], rate: 2, cap: 3, goal: door}\n"));
        QCOMPARE(sourceArrivals(capped, 0, 5).size(), std::size_t(3));
        // Without windows, over the whole duration (30 s): 60.
        const Scene whole = parseSources(corridor(
            "  - {name: west, type: walker, line: [[-20, -1], [-20, 1]], rate: 2, goal: door}\n"));
        QCOMPARE(sourceArrivals(whole, 0, 5).size(), std::size_t(60));
    }

    // Poisson: about rate x time arrivals, exponential gaps (their spread equals their
    // mean), only inside the windows; seeded: the same seed the same, another differs.
    void poissonArrivalsHaveTheirRate()
    {
        const Scene s = parseSources(corridor(
            "  - {name: west, types: {walker: 3, runner: 1}, line: [[-20, -1], [-20, 1]], rate: 0.5, "
            "arrivals: poisson, windows: [[100, 1100], [1500, 2500]], goal: door}\n",
            24.0f, 3000.0f));
        const std::vector<SourceArrival> a = sourceArrivals(s, 0, 11);
        // 2,000 s open at 0.5 a second: 1,000 expected, standard deviation about 32.
        QVERIFY2(a.size() > 870 && a.size() < 1130, qPrintable(QString::number(a.size())));
        std::vector<double> gaps;
        std::size_t runners = 0;
        for (std::size_t k = 0; k < a.size(); ++k) {
            const double t = a[k].timeS;
            QVERIFY2((t >= 100.0 && t < 1100.0) || (t >= 1500.0 && t < 2500.0), qPrintable(QString::number(t)));
            if (k > 0 && (t < 1100.0) == (a[k - 1].timeS < 1100.0))
                gaps.push_back(t - a[k - 1].timeS);
            if (k > 0)
                QVERIFY(t >= a[k - 1].timeS);
            runners += a[k].type == 1 ? 1 : 0;
        }
        const double mean = std::accumulate(gaps.begin(), gaps.end(), 0.0) / double(gaps.size());
        double var = 0.0;
        for (double g : gaps)
            var += (g - mean) * (g - mean);
        const double sd = std::sqrt(var / double(gaps.size()));
        QVERIFY2(std::abs(mean - 2.0) < 0.25, qPrintable(QString::number(mean)));
        QVERIFY2(sd / mean > 0.85 && sd / mean < 1.15, qPrintable(QString::number(sd / mean)));
        // The mix: a quarter runners (within 4 standard deviations).
        const double share = double(runners) / double(a.size());
        QVERIFY2(std::abs(share - 0.25) < 0.06, qPrintable(QString::number(share)));
        // Seeded.
        const std::vector<SourceArrival> same = sourceArrivals(s, 0, 11), other = sourceArrivals(s, 0, 12);
        QCOMPARE(same.size(), a.size());
        for (std::size_t k = 0; k < a.size(); ++k)
            QCOMPARE(same[k].timeS, a[k].timeS);
        QVERIFY(other.size() != a.size() || other[0].timeS != a[0].timeS);
    }

    // Until its time an agent is off stage: not present in the frames, standing where it
    // will enter, out of everyone's way; it enters at the first step at or after its time
    // and walks to the door, where it leaves.
    void agentsEnterOnTimeAndLeaveAtTheDoor()
    {
        const Run r = record(corridor("  - {name: west, type: walker, line: [[-20, -1], [-20, 1]], rate: 0.5, "
                                      "windows: [[0, 10]], goal: door}\n"),
                             50.0);
        const std::vector<SourceArrival> due = sourceArrivals(r.scene, 0, 5);
        QCOMPARE(due.size(), std::size_t(5));
        QCOMPARE(r.cache.agents().size(), std::size_t(5));
        const float fps = 24.0f;
        for (std::size_t i = 0; i < 5; ++i) {
            const std::size_t f = firstPresent(r.cache, i);
            // It enters on the step that starts at or after its time: present from the frame after.
            const auto expected = std::size_t(std::ceil(due[i].timeS * fps - 1e-6)) + 1;
            QCOMPARE(f, expected);
            for (std::size_t g = 0; g < f; ++g)
                QVERIFY(!r.cache.at(g, i).present && !r.cache.at(g, i).out);
            // It came in where its arrival says, and moved on from there.
            QVERIFY(glm::distance(glm::vec2(r.cache.at(f, i).position.x, r.cache.at(f, i).position.z), due[i].place) <
                    0.1f);
            // It reached the door and left.
            QVERIFY2(r.cache.at(r.cache.frameCount() - 1, i).out, qPrintable(QString("agent %1").arg(i)));
        }
        QCOMPARE(r.stats.sourceAgents, std::uint64_t(5));
        QCOMPARE(r.stats.offstage, std::uint64_t(0));
        QCOMPARE(r.stats.nav.agentsOut, std::uint64_t(5));
        QCOMPARE(r.stats.inScene, std::uint64_t(0));
    }

    // A place another body covers: the arrival waits there, and those after it from the
    // same source wait behind it. A walker standing on a one-point source keeps them all
    // out; when it has gone, they come in one at a time, each where nobody stands.
    void aStreamWaitsForRoom()
    {
        const std::string scene = "throng: 1\nsettings: {fps: 24, seed: 2, duration: 40, bounds: {min: [-30, -10], "
                                  "max: [30, 10]}}\n"
                                  "agent_types:\n"
                                  "  - {name: walker, max_speed: 1.3, behaviours: {seek: 1, separation: 1}}\n"
                                  "  - {name: slow, max_speed: 0.1, behaviours: {seek: 1}}\n"
                                  "goals:\n  - {name: door, position: [20, 0], radius: 1.5, exit: true}\n"
                                  "  - {name: aside, position: [0, 8], radius: 0.5}\n"
                                  "agents:\n  - {id: 1, type: slow, position: [0, 0], goal: aside}\n"
                                  "sources:\n"
                                  "  - {name: spot, type: walker, line: [[0, 0], [0, 0]], rate: 4, windows: [[0, 2]], "
                                  "goal: door}\n";
        const Run r = record(scene, 40.0);
        const std::size_t n = r.cache.agents().size();
        QCOMPARE(n, std::size_t(9));
        // The slow walker leaves the spot (0.6 m, two radii) after about 6 s: nobody before.
        std::size_t clearFrame = 0;
        while (glm::length(r.cache.at(clearFrame, 0).position) < 0.6f)
            ++clearFrame;
        QVERIFY2(clearFrame > 5 * 24, qPrintable(QString::number(clearFrame)));
        std::set<std::size_t> entries;
        for (std::size_t i = 1; i < n; ++i) {
            const std::size_t f = firstPresent(r.cache, i);
            QVERIFY2(f >= clearFrame, qPrintable(QString("agent %1 at frame %2, the spot clear at %3")
                                                     .arg(i).arg(f).arg(clearFrame)));
            QVERIFY2(f < r.cache.frameCount(), qPrintable(QString("agent %1 never came in").arg(i)));
            QVERIFY2(entries.insert(f).second, "two came in on one frame, on one spot");
            // Nobody overlaps it as it comes in (the step it entered already moved it a little).
            for (std::size_t j = 0; j < n; ++j) {
                const AgentFrame& other = r.cache.at(f, j);
                if (j == i || !other.present || other.out)
                    continue;
                const float d = glm::distance(r.cache.at(f, i).position, other.position);
                QVERIFY2(d > 0.6f - 0.1f,
                         qPrintable(QString("agent %1 came in %2 m from agent %3").arg(i).arg(d).arg(j)));
            }
        }
        QCOMPARE(r.stats.offstage, std::uint64_t(0));
        // A spot that never clears keeps them all off stage, and the stats say so.
        std::string blocked = scene;
        blocked.replace(blocked.find("goal: aside"), 11, "heading: 0");
        const Run b = record(blocked, 10.0);
        QCOMPARE(b.stats.sourceAgents, std::uint64_t(8));
        QCOMPARE(b.stats.offstage, std::uint64_t(8));
        QCOMPARE(b.stats.inScene, std::uint64_t(1));
        for (std::size_t i = 1; i < b.cache.agents().size(); ++i)
            QCOMPARE(firstPresent(b.cache, i), b.cache.frameCount());
    }

    // The stats against a recount from the frames: the source's agents, those that came
    // in, those still off stage, and the agents in the scene at each whole second.
    void statsCountEveryEntry()
    {
        const Run r = record(corridor("  - {name: west, type: walker, line: [[-20, -2], [-20, 2]], rate: 1.5, "
                                      "arrivals: poisson, goal: door}\n"
                                      "  - {name: late, type: runner, line: [[-20, 5], [-20, 6]], rate: 1, "
                                      "windows: [[25, 60]], goal: door}\n"),
                             30.0);
        const std::vector<std::uint32_t> counts = sourceCounts(r.scene, 5);
        QCOMPARE(r.stats.sourceAgents, std::uint64_t(counts[0] + counts[1]));
        QCOMPARE(counts[1], 5u);  // 25, 26, 27, 28, 29 s: the run ends at 30
        std::uint64_t entered = 0;
        for (std::size_t i = 0; i < r.cache.agents().size(); ++i)
            entered += firstPresent(r.cache, i) < r.cache.frameCount() ? 1 : 0;
        QCOMPARE(r.stats.sourceAgents - r.stats.offstage, entered);
        QVERIFY(entered > 30);
        QCOMPARE(r.stats.inSceneEachSecond.size(), std::size_t(31));
        for (std::size_t s = 0; s <= 30; ++s) {
            const std::size_t f = s * 24;
            std::uint64_t in = 0;
            for (std::size_t i = 0; i < r.cache.agents().size(); ++i)
                in += r.cache.at(f, i).present && !r.cache.at(f, i).out ? 1 : 0;
            QCOMPARE(r.stats.inSceneEachSecond[s], in);
        }
        QCOMPARE(r.stats.inSceneEachSecond[0], std::uint64_t(0));
        QVERIFY(r.stats.inSceneEachSecond[20] > 10);
        const std::string json = r.stats.toJson();
        QVERIFY(json.find("\"source_agents\": " + std::to_string(r.stats.sourceAgents)) != std::string::npos);
        QVERIFY(json.find("\"agents_in_scene_each_second\": [0, ") != std::string::npos);
    }

    // Put back a checkpoint taken before some came in: the run from it is the run.
    void aCheckpointPutsThemBackOffStage()
    {
        const Scene s = parseSources(
            corridor("  - {name: west, type: walker, line: [[-20, -2], [-20, 2]], rate: 2, arrivals: poisson, "
                     "goal: door}\n"));
        World world(s);
        for (int k = 0; k < 5 * 24; ++k)
            world.step();
        const WorldState at5 = world.saveState();
        const std::size_t offstageAt5 = world.offstageAgents();
        FrameCache first, second;
        std::vector<AgentFrame> frame;
        world.startRecording(first);
        for (int k = 0; k < 10 * 24; ++k) {
            world.step();
            world.snapshot(frame);
            first.append(frame);
        }
        QVERIFY(world.offstageAgents() < offstageAt5);
        world.restoreState(at5);
        QCOMPARE(world.offstageAgents(), offstageAt5);
        world.startRecording(second);
        for (int k = 0; k < 10 * 24; ++k) {
            world.step();
            world.snapshot(frame);
            second.append(frame);
        }
        QCOMPARE(second.hash(), first.hash());
    }

    // An edit elsewhere keeps the stream as it was (its agents matched by source and
    // arrival); an edit of the source starts its stream again (its agents in the scene
    // are gone, and its arrivals come in from the edit frame on, one a step where each fits).
    void anEditKeepsOrRestartsTheStream()
    {
        const std::string yaml =
            corridor("  - {name: west, type: walker, line: [[-20, -2], [-20, 2]], rate: 1, goal: door}\n");
        const Scene s = parseSources(yaml);
        World world(s);
        for (int k = 0; k < 8 * 24; ++k)
            world.step();
        const WorldState at8 = world.saveState();
        const std::size_t inAt8 = world.agentsInScene();
        QVERIFY(inAt8 >= 7);
        FrameCache plain, kept;
        std::vector<AgentFrame> frame;
        world.startRecording(plain);
        for (int k = 0; k < 4 * 24; ++k) {
            world.step();
            world.snapshot(frame);
            plain.append(frame);
        }
        Scene other = s;
        other.goals.push_back(Goal{"bench", glm::vec2(0.0f, 8.0f), 1.0f, false});
        World edited(other);
        QVERIFY(edited.adoptState(at8, s, other));
        QCOMPARE(edited.agentsInScene(), inAt8);
        edited.startRecording(kept);
        for (int k = 0; k < 4 * 24; ++k) {
            edited.step();
            edited.snapshot(frame);
            kept.append(frame);
        }
        QCOMPARE(kept.hash(), plain.hash());

        Scene faster = s;
        faster.sources[0].rate = 2.0f;
        World restarted(faster);
        std::vector<std::int32_t> previous;
        QVERIFY(restarted.adoptState(at8, s, faster, &previous));
        for (std::int32_t p : previous)
            QCOMPARE(p, -1);
        QCOMPARE(restarted.agentsInScene(), std::size_t(0));
        restarted.step();
        QCOMPARE(restarted.agentsInScene(), std::size_t(1));  // one at a time where each fits
        for (int k = 0; k < 4 * 24; ++k)
            restarted.step();
        QVERIFY(restarted.agentsInScene() > 10);
    }

    // One thread or two (each with chunks to run), the same frames.
    void threadCountsAgree()
    {
        // Enough agents that a loaded machine still hands the second thread some chunks.
        const std::string yaml = corridor("  - {name: west, type: walker, line: [[-20, -8], [-20, 8]], rate: 120, "
                                          "arrivals: poisson, goal: door}\n"
                                          "  - {name: yard, type: runner, rect: {min: [-28, -8], max: [-24, 8]}, "
                                          "rate: 60, goal: door}\n",
                                          24.0f, 12.0f);
        const Run one = record(yaml, 12.0, 1);
        const Scene s = parseSources(yaml);
        World world(s, WorldOptions{0, false, 2});
        QCOMPARE(world.threads(), 2);
        FrameCache cache;
        world.startRecording(cache);
        std::vector<AgentFrame> frame;
        while (world.timeS() < 12.0 - 1e-9) {
            world.step();
            world.snapshot(frame);
            cache.append(frame);
        }
        QVERIFY(world.agentCount() > 2000);
        for (const std::uint64_t chunks : world.team().chunksRun())
            QVERIFY2(chunks > 0, "a thread ran no chunk");
        QCOMPARE(cache.hash(), one.cache.hash());
    }

    // At 24 and at 60 fps each agent enters on the first step that starts at or after its
    // time (present from the frame after): never early, and later only while its place
    // is covered or an earlier one of its source still waits.
    void frameRatesAgree()
    {
        const std::string source =
            "  - {name: west, type: walker, line: [[-20, -2], [-20, 2]], rate: 0.7, arrivals: poisson, goal: door}\n";
        const Run at24 = record(corridor(source, 24.0f), 20.0);
        const Run at60 = record(corridor(source, 60.0f), 20.0);
        QCOMPARE(at60.cache.agents().size(), at24.cache.agents().size());
        const std::vector<SourceArrival> due = sourceArrivals(at24.scene, 0, 5);
        QVERIFY(due.size() > 8);
        int onTime = 0, waited = 0;
        for (const Run* run : {&at24, &at60}) {
            const double fps = run->scene.settings.fps;
            for (std::size_t i = 0; i < due.size() && due[i].timeS < 19.0; ++i) {
                const std::size_t present = firstPresent(run->cache, i);
                const double entered = double(present - 1) / fps;  // its step's start
                QVERIFY2(entered >= due[i].timeS - 1e-9,
                         qPrintable(QString("agent %1 due at %2 s came in at %3 s at %4 fps")
                                        .arg(i).arg(due[i].timeS).arg(entered).arg(fps)));
                if (entered < due[i].timeS + 1.0 / fps) {
                    ++onTime;
                    continue;
                }
                // Late: at the start of the step it was due, its place was covered, or one
                // before it from its source had not come in yet.
                const auto dueFrame = std::size_t(std::ceil(due[i].timeS * fps - 1e-6));
                bool held = i > 0 && !run->cache.at(dueFrame, i - 1).present;
                for (std::size_t j = 0; j < run->cache.agents().size() && !held; ++j) {
                    const AgentFrame& a = run->cache.at(dueFrame, j);
                    held = j != i && a.present && !a.out &&
                           glm::distance(glm::vec2(a.position.x, a.position.z), due[i].place) < 0.6f;
                }
                QVERIFY2(held, qPrintable(QString("due at %1 s, came in at %2 s at %3 fps with room")
                                              .arg(due[i].timeS).arg(entered).arg(fps)));
                ++waited;
            }
        }
        QVERIFY2(onTime > 2 * waited, qPrintable(QString("%1 on time, %2 waited").arg(onTime).arg(waited)));
        qInfo("%d entries on time, %d waited for room", onTime, waited);
    }

    // A path whose end is an exit: walkers from a source at its start follow it round its
    // corner and leave at its end (out in the frames, counted in agents_out), instead of
    // piling up there; a closed path cannot be an exit.
    void anOpenPathsEndCanBeAnExit()
    {
        const std::string scene =
            "throng: 1\nsettings: {fps: 24, seed: 3, duration: 60, bounds: {min: [-30, -30], max: [30, 30]}}\n"
            "agent_types:\n  - {name: walker, max_speed: 1.3, behaviours: {path_following: 1, separation: 1}}\n"
            "paths:\n  - {name: round, radius: 0.8, exit: true, points: [[-20, -20], [-20, 0], [0, 0]]}\n"
            "sources:\n  - {name: in, type: walker, line: [[-20.5, -19], [-19.5, -19]], rate: 0.5, windows: [[0, 10]], "
            "path: round}\n";
        const Run r = record(scene, 60.0);
        QCOMPARE(r.scene.paths[0].exit, true);
        QVERIFY(sceneToYaml(r.scene).find("exit: true") != std::string::npos);
        const std::size_t n = r.cache.agents().size();
        QCOMPARE(n, std::size_t(5));
        for (std::size_t i = 0; i < n; ++i) {
            std::size_t outFrame = 0;
            while (outFrame < r.cache.frameCount() && !r.cache.at(outFrame, i).out)
                ++outFrame;
            QVERIFY2(outFrame < r.cache.frameCount(), qPrintable(QString("agent %1 never left").arg(i)));
            // It left within the path's radius of the end, after walking the corner.
            const glm::vec3 at = r.cache.at(outFrame, i).position;
            QVERIFY2(glm::distance(glm::vec2(at.x, at.z), glm::vec2(0.0f, 0.0f)) < 0.8f + 0.1f,
                     qPrintable(QString("agent %1 left at (%2, %3)").arg(i).arg(at.x).arg(at.z)));
        }
        QCOMPARE(r.stats.nav.exitAgents, std::uint64_t(5));
        QCOMPARE(r.stats.nav.agentsOut, std::uint64_t(5));
        QCOMPARE(r.stats.inScene, std::uint64_t(0));
        const LoadResult closed = parseScene(
            "throng: 1\npaths:\n  - {name: loop, closed: true, exit: true, points: [[0, 0], [5, 0], [5, 5]]}\n",
            "closed.yaml", "");
        QVERIFY(!closed.ok());
        QVERIFY2(closed.diagnostics[0].format().find("closed.yaml:3:") == 0 &&
                     closed.diagnostics[0].format().find("no end to leave by") != std::string::npos,
                 closed.diagnostics[0].format().c_str());
    }

    // The CSV has rows for an agent only from the frame it came in until it left.
    void theCsvHasThemFromTheirEntry()
    {
        const Run r = record(corridor("  - {name: west, type: walker, line: [[-20, -1], [-20, 1]], rate: 0.5, "
                                      "windows: [[2, 8]], goal: door}\n"),
                             50.0);
        QTemporaryDir dir;
        const std::string path = dir.filePath("run.csv").toStdString();
        QVERIFY(exporting::writeTrajectoryCsv(r.cache, path).ok());
        std::ifstream in(path);
        std::string line;
        std::getline(in, line);  // header
        std::map<std::uint32_t, std::pair<std::size_t, std::size_t>> rows;  // id -> (first frame, rows)
        while (std::getline(in, line)) {
            std::istringstream fields(line);
            std::string frameText, idText;
            std::getline(fields, frameText, ',');
            std::getline(fields, idText, ',');
            auto [it, fresh] = rows.try_emplace(std::uint32_t(std::stoul(idText)), std::stoul(frameText), 0);
            ++it->second.second;
        }
        QCOMPARE(rows.size(), r.cache.agents().size());
        for (std::size_t i = 0; i < r.cache.agents().size(); ++i) {
            const auto& [first, count] = rows.at(r.cache.agents()[i].id);
            QCOMPARE(first, firstPresent(r.cache, i));
            std::size_t inScene = 0;
            for (std::size_t f = 0; f < r.cache.frameCount(); ++f)
                inScene += r.cache.at(f, i).present && !r.cache.at(f, i).out ? 1 : 0;
            QCOMPARE(count, inScene);
            QVERIFY(count > 24 && count < r.cache.frameCount() - 48);
        }
    }
};

THRONG_REGISTER_TEST(TestSources)
#include "TestSources.moc"
