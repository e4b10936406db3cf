// The results a restructuring of the engine must not change: every demo, the demos at
// other frame rates, the bench scenarios and a family of random scenes that use every
// section and key, each run for a while and hashed (every recorded frame and the run's
// counters). tests/data/golden/runs.txt holds the hashes taken before the restructuring
// began; a change of behaviour that is meant writes them again, in its own commit, with
// THRONG_WRITE_GOLDEN=1 (then this test rewrites the file and passes).
#include "DemoRuns.h"
#include "RandomScene.h"
#include "TestRegistry.h"

#include "simcore/scenarios/BenchScenarios.h"

#include <QTest>

#include <algorithm>
#include <bit>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

using namespace throng::sim;
using namespace throng::test::demos;

namespace {

const char* const kGoldenFile = THRONG_TEST_DATA_DIR "/golden/runs.txt";

struct GoldenRun {
    std::string name;
    std::function<Scene()> scene;
    int frames;
};

Scene atFps(Scene s, float fps)
{
    s.settings.fps = fps;
    return s;
}

Scene bench(const std::string& name, std::uint32_t agents)
{
    Scene s;
    if (!makeBenchScenario(name, agents, s))
        qFatal("no bench scenario %s", name.c_str());
    return s;
}

std::vector<GoldenRun> goldenRuns()
{
    std::vector<GoldenRun> runs{
        {"crossroads@24", [] { return demo("crossroads.yaml"); }, 240},
        {"crossroads@60", [] { return atFps(demo("crossroads.yaml"), 60.0f); }, 240},
        {"crossroads@12", [] { return atFps(demo("crossroads.yaml"), 12.0f); }, 72},
        {"cavalry@24", [] { return demo("cavalry.yaml"); }, 72},
        {"evacuation@12", [] { return demo("evacuation.yaml"); }, 36},
        {"evacuation@30", [] { return atFps(demo("evacuation.yaml"), 30.0f); }, 30},
        {"murmuration@24", [] { return demo("murmuration.yaml"); }, 16},
        {"bench-cross-3000", [] { return bench("cross", 3000); }, 120},
        {"bench-flock-3000", [] { return bench("flock", 3000); }, 48},
        {"bench-army-1000", [] { return bench("army", 1000); }, 48},
        {"bench-corridor-1000", [] { return bench("corridor", 1000); }, 96},
    };
    for (std::uint32_t seed = 1; seed <= 8; ++seed)
        runs.push_back({"random-" + std::to_string(seed),
                        [seed] { return throng::test::makeRandomScene(seed, seed % 2 ? 40 : 90); }, 48});
    return runs;
}

std::uint64_t countersHash(const StepCounters& c)
{
    std::uint64_t h = 1469598103934665603ull;
    auto add = [&](std::uint64_t v) {
        for (int b = 0; b < 8; ++b) {
            h ^= (v >> (8 * b)) & 0xffu;
            h *= 1099511628211ull;
        }
    };
    for (const std::uint64_t v : {c.wallPenetrations, c.obstaclePenetrations, c.overlappingPairs,
                                  c.redLightViolations, c.nonFiniteValues, c.leaderOvertaken, c.agentSteps})
        add(v);
    for (const std::uint64_t v : c.overlapDepths.bins)
        add(v);
    add(std::bit_cast<std::uint32_t>(c.overlapDepths.deepest));
    add(std::bit_cast<std::uint32_t>(c.peakDensity));
    add(std::bit_cast<std::uint64_t>(c.peakDensityTimeS));
    return h;
}

// "frames-hash counters-hash" of a run, as the golden file holds it.
std::string runHashes(const GoldenRun& run, GridCells cells = GridCells::ByCrowd)
{
    WorldOptions options = threads(2);
    options.gridCells = cells;
    World world(run.scene(), options);
    FrameCache cache;
    world.startRecording(cache);
    std::vector<AgentFrame> frame;
    for (int f = 0; f < run.frames; ++f) {
        world.step();
        world.snapshot(frame);
        cache.append(frame);
    }
    char text[64];
    std::snprintf(text, sizeof text, "%016llx %016llx", static_cast<unsigned long long>(cache.hash()),
                  static_cast<unsigned long long>(countersHash(world.counters())));
    return text;
}

std::map<std::string, std::string> readGolden()
{
    std::map<std::string, std::string> golden;
    std::ifstream in(kGoldenFile);
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#')
            continue;
        std::istringstream fields(line);
        std::string name, frames, counters;
        fields >> name >> frames >> counters;
        golden[name] = frames + " " + counters;
    }
    return golden;
}

}  // namespace

class TestGoldenRuns : public QObject {
    Q_OBJECT
private slots:
    // Every run gives the hashes recorded for it, frame for frame and counter for counter.
    void runsAreUnchanged()
    {
        const std::vector<GoldenRun> runs = goldenRuns();
        const bool write = std::getenv("THRONG_WRITE_GOLDEN") != nullptr;
        const std::map<std::string, std::string> golden = readGolden();
        if (!write)
            QVERIFY2(golden.size() == runs.size(), kGoldenFile);
        std::ostringstream out;
        out << "# Hashes of recorded runs (TestGoldenRuns): name, every frame's hash, the counters' hash.\n";
        QStringList changed;
        for (const GoldenRun& run : runs) {
            const std::string now = runHashes(run);
            out << run.name << ' ' << now << '\n';
            const auto it = golden.find(run.name);
            if (it == golden.end() || it->second != now)
                changed << QString::fromStdString(run.name + " was " + (it == golden.end() ? "absent" : it->second) +
                                                  ", now " + now);
        }
        if (write) {
            std::ofstream(kGoldenFile) << out.str();
            qInfo("wrote %s", kGoldenFile);
            return;
        }
        QVERIFY2(changed.isEmpty(), qPrintable("runs changed:\n" + changed.join('\n')));
    }

    // The neighbour grid's cells change no result, only the time: every run gives its
    // recorded hashes with the fine cells throughout and with the coarse ones throughout
    // (runsAreUnchanged runs them with the cells the World chooses as it goes).
    void cellsChangeNoRun()
    {
        const std::map<std::string, std::string> golden = readGolden();
        QStringList changed;
        for (const GridCells cells : {GridCells::Fine, GridCells::Coarse})
            for (const GoldenRun& run : goldenRuns()) {
                const std::string now = runHashes(run, cells);
                if (golden.at(run.name) != now)
                    changed << QString::fromStdString(run.name + (cells == GridCells::Fine ? " fine" : " coarse") +
                                                      " gave " + now + ", recorded " + golden.at(run.name));
            }
        QVERIFY2(changed.isEmpty(), qPrintable("runs changed with the cells:\n" + changed.join('\n')));
    }

    // A crowd that gathers: rings of walkers 3 m apart crossing to the far side through one
    // middle. While they stand spread out the World's grid has the coarsest cells (four
    // times the fine edge); as they pack into the middle it takes the fine ones, and once
    // they have passed through and spread again, wider ones. The frames and counters are
    // those of the run on fine cells throughout, and of the one on the coarsest cells.
    void cellsFollowTheCrowd()
    {
        CrossLayout layout;
        layout.innerRadiusM = 6.0f;
        layout.ringGapM = 3.0f;
        layout.spacingM = 3.0f;
        const Scene scene = makeCrossScenario(400, 3, layout);
        const int frames = 24 * 90;
        World world(scene, threads(2));
        const float fine = 0.5f * scene.agentTypes.at(0).perceptionM;  // World.cpp: half the perception
        std::vector<float> cells;
        for (int f = 0; f < frames; ++f) {
            cells.push_back(world.neighbourCellM());
            world.step();
        }
        QCOMPARE(cells.front(), 4.0f * fine);
        const auto firstFine = std::find(cells.begin(), cells.end(), fine);
        QVERIFY2(firstFine != cells.end(), "the grid never took the fine cells in the packed middle");
        QVERIFY2(std::find_if(firstFine, cells.end(), [&](float c) { return c > fine; }) != cells.end(),
                 "the grid kept the fine cells after the crowd spread again");
        for (const float c : cells)
            QVERIFY(c == fine || c == 2.0f * fine || c == 4.0f * fine);
        const GoldenRun run{"gathering", [&] { return scene; }, frames};
        const std::string chosen = runHashes(run);
        QCOMPARE(runHashes(run, GridCells::Fine), chosen);
        QCOMPARE(runHashes(run, GridCells::Coarse), chosen);
    }

    // The hashes see a change: a spawn area moved by a millimetre, or one more frame,
    // changes them.
    void hashesSeeAChange()
    {
        const GoldenRun run{"crossroads", [] { return demo("crossroads.yaml"); }, 24};
        const std::string plain = runHashes(run);
        QCOMPARE(runHashes(run), plain);
        const GoldenRun longer{"crossroads", run.scene, 25};
        QVERIFY(runHashes(longer).substr(0, 16) != plain.substr(0, 16));
        const GoldenRun moved{"crossroads", [] {
                                  Scene s = demo("crossroads.yaml");
                                  s.groups.at(0).min.x += 0.001f;
                                  return s;
                              },
                              24};
        QVERIFY(runHashes(moved).substr(0, 16) != plain.substr(0, 16));
    }
};

THRONG_REGISTER_TEST(TestGoldenRuns)
#include "TestGoldenRuns.moc"
