// Mutated scene and brain files never crash, hang or poison a run. A demanding user
// mutated the shipped files 4,400 times and found 44 crashes (a sketched field asking for
// a dense matrix of 30,000 squared doubles, `nav_cell: 0.001`, a group of 10,000,000),
// 8 hangs and 25 accepted files that gave NaN positions within 24 frames, all of which
// `throng-cli check` had called valid. Here every mutant is loaded and checked; an accepted
// one is built into a World and stepped with every position checked finite. Every error
// must name file:line:col. Each mutant runs in a forked child: a crash or a hang is
// reported with its seed and index, and THRONG_FUZZ_SEED=S THRONG_FUZZ_ONLY=I replays it
// in-process with the mutant's text printed.
#include "FileMutator.h"
#include "IsolatedRuns.h"
#include "TestRegistry.h"

#include "simcore/io/SceneIO.h"
#include "simcore/world/FrameCache.h"
#include "simcore/world/World.h"
#include "simcore/world/WorldBrain.h"

#include <QDir>
#include <QTest>

#include <chrono>
#include <thread>

#include <unistd.h>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace throng;
using namespace throng::test;

namespace {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr std::size_t kDefaultMutants = 500;  // ASan + UBSan make each run ~10 times slower
constexpr double kHangS = 120.0;
#else
constexpr std::size_t kDefaultMutants = 1500;
constexpr double kHangS = 20.0;
#endif
// Accepted scenes with more agents than this are loaded and checked but not stepped: the
// fuzz budget is seconds, and a 10,000,000-agent crowd is a valid scene.
constexpr std::size_t kMaxSteppedAgents = 20'000;

std::string readText(const std::string& path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

struct FuzzFile {
    std::string path;     // the original, for the message
    std::string baseDir;  // where its relative references resolve
    std::string text;
    bool brain = false;   // a .brain.yaml, run inside hostScene()
};

std::vector<FuzzFile> fuzzFiles()
{
    std::vector<FuzzFile> out;
    const std::string root = THRONG_SOURCE_DIR;
    for (const char* dir : {"/resources/scenes", "/resources/brains", "/tests/data/scenes"})
        for (const auto& e : std::filesystem::directory_iterator(root + dir)) {
            const std::string p = e.path().string();
            if (e.path().extension() != ".yaml")
                continue;
            out.push_back({p, e.path().parent_path().string(), readText(p), p.ends_with(".brain.yaml")});
        }
    std::sort(out.begin(), out.end(), [](const FuzzFile& a, const FuzzFile& b) { return a.path < b.path; });
    return out;
}

// A small street for a mutated brain to drive: walkers with a goal, walls, a pillar.
std::string hostScene(const std::string& brainPath)
{
    return "throng: 1\n"
           "settings: {fps: 24, seed: 3, bounds: {min: [-30, -30], max: [30, 30]}}\n"
           "brains:\n  - {name: fuzzed, file: \"" + brainPath + "\"}\n"
           "agent_types:\n  - {name: walker, brain: fuzzed, behaviours: {seek: 1, separation: 1, wall_following: 2, obstacle_avoidance: 2}}\n"
           "goals:\n  - {name: exit, position: [20, 0], radius: 2}\n"
           "walls:\n  - {name: w, points: [[-25, 10], [25, 10]]}\n"
           "obstacles:\n  - {name: p, shape: circle, center: [5, 0], radius: 1}\n"
           "groups:\n  - {name: g, type: walker, count: 60, rect: {min: [-20, -8], max: [-5, 8]}, goal: exit}\n";
}

std::string checkDiagnostics(const std::vector<sim::Diagnostic>& ds)
{
    for (const sim::Diagnostic& d : ds)
        // An empty file is the one error about the file as a whole (docs/scene-format.md).
        if (d.severity == sim::Severity::Error && (d.file.empty() || d.line < 1 || d.column < 1) &&
            d.message != "the file is empty")
            return "an error without file:line:col: " + d.format();
    return {};
}

std::string nonFinite(const std::vector<sim::AgentFrame>& frame, int f)
{
    for (std::size_t i = 0; i < frame.size(); ++i) {
        const sim::AgentFrame& a = frame[i];
        if (!std::isfinite(a.position.x) || !std::isfinite(a.position.y) || !std::isfinite(a.position.z) ||
            !std::isfinite(a.headingRad) || !std::isfinite(a.speed) || !std::isfinite(a.phase))
            return "accepted, but agent " + std::to_string(i) + " is not finite at frame " + std::to_string(f);
    }
    return {};
}

// Loads, checks and (when accepted) steps one mutant; empty when all is well.
std::string runMutant(const FuzzFile& src, const Mutant& m, const std::string& scratch, bool verbose)
{
    sim::LoadResult r;
    if (src.brain) {
        const std::string brainPath = scratch + "/mutant-" + std::to_string(getpid()) + ".brain.yaml";
        std::ofstream(brainPath, std::ios::binary) << m.text;
        r = sim::parseScene(hostScene(brainPath), "host.yaml", scratch);
    } else {
        r = sim::parseScene(m.text, "mutant.yaml", src.baseDir);
    }
    if (std::string why = checkDiagnostics(r.diagnostics); !why.empty())
        return why;
    if (!r.ok())
        return {};
    const std::vector<sim::Diagnostic> brains = sim::checkSceneBrains(r.scene);
    if (std::string why = checkDiagnostics(brains); !why.empty())
        return why;
    const bool checkAccepts = !sim::hasErrors(brains);
    std::size_t agents = r.scene.agents.size() + r.scene.vehicles.size() + r.scene.heroes.size();
    for (const sim::SpawnGroup& g : r.scene.groups)
        agents += g.count;
    if (agents > kMaxSteppedAgents)
        return {};
    sim::WorldOptions options;
    options.threads = 1;
    sim::World world(r.scene, options);
    // `check` and `run` must agree: run refuses exactly when a brain it runs fails.
    if (checkAccepts != world.brainErrors().empty())
        return checkAccepts ? "check accepts, run refuses: " + world.brainErrors().front()
                            : "check refuses a scene that run runs";
    if (!checkAccepts)
        return {};
    const int frames = agents <= 2000 ? 24 : 4;
    std::vector<sim::AgentFrame> frame;
    world.snapshot(frame);
    if (std::string why = nonFinite(frame, 0); !why.empty())
        return why;
    for (int f = 1; f < frames; ++f) {
        world.step();
        world.snapshot(frame);
        if (std::string why = nonFinite(frame, f); !why.empty())
            return why;
    }
    if (verbose)
        std::fprintf(stderr, "accepted and stepped %d frames of %zu agents\n", frames, world.agentCount());
    return {};
}

}  // namespace

class TestFileFuzz : public QObject {
    Q_OBJECT
private slots:
    // The harness tells each way a job can go wrong, and goes on with the next job.
    void isolatedRunsTellHangsCrashesAndFailures()
    {
        const std::vector<IsolatedFailure> failures = runIsolated(6, [](std::size_t i) -> std::string {
            if (i == 1) {  // computes for ever
                volatile std::uint64_t x = 0;
                for (;;)
                    x = x + 1;
            }
            if (i == 2)  // waits for ever without computing
                std::this_thread::sleep_for(std::chrono::hours(1));
            if (i == 3) {
                // QtTest's crash handler, inherited from the parent, reports an abort and
                // exits (under the sanitizers): the harness would see an exit status, which
                // it reports too. Here the default handler, so that it sees the signal.
                std::signal(SIGABRT, SIG_DFL);
                std::abort();
            }
            return i == 4 ? "bad" : "";
        }, 0.5);
        QCOMPARE(failures.size(), std::size_t(4));
        QCOMPARE(failures[0].job, std::size_t(1));
        QCOMPARE(QString::fromStdString(failures[0].what), QString("hung: still running after 0.5 s of processor time"));
        QCOMPARE(failures[1].job, std::size_t(2));
        QCOMPARE(QString::fromStdString(failures[1].what), QString("hung: still running after 2.5 s of waiting"));
        QCOMPARE(failures[2].job, std::size_t(3));
        QVERIFY(failures[2].what.starts_with("crashed: "));
        QCOMPARE(failures[3].job, std::size_t(4));
        QCOMPARE(QString::fromStdString(failures[3].what), QString("bad"));
    }

    void mutantsNeverCrashHangOrPoisonARun()
    {
        const std::vector<FuzzFile> files = fuzzFiles();
        QVERIFY(files.size() >= 8);
        const char* seedEnv = std::getenv("THRONG_FUZZ_SEED");
        const char* countEnv = std::getenv("THRONG_FUZZ_MUTANTS");
        const char* onlyEnv = std::getenv("THRONG_FUZZ_ONLY");
        const std::uint64_t seed = seedEnv ? std::strtoull(seedEnv, nullptr, 10) : 1;
        const std::size_t count = countEnv ? std::strtoull(countEnv, nullptr, 10) : kDefaultMutants;
        const std::string scratch = QDir::tempPath().toStdString();
        const auto source = [&](std::size_t i) -> const FuzzFile& { return files[i % files.size()]; };
        if (onlyEnv) {
            const std::size_t i = std::strtoull(onlyEnv, nullptr, 10);
            const Mutant m = mutateText(source(i).text, seed, i);
            std::fprintf(stderr, "--- mutant %zu of %s (%s)\n%s\n---\n", i, source(i).path.c_str(), m.what.c_str(),
                         m.text.c_str());
            const std::string why = runMutant(source(i), m, scratch, true);
            QVERIFY2(why.empty(), why.c_str());
            return;
        }
        const std::vector<IsolatedFailure> failures = runIsolated(
            count, [&](std::size_t i) { return runMutant(source(i), mutateText(source(i).text, seed, i), scratch, false); },
            kHangS);
        for (const IsolatedFailure& f : failures) {
            const Mutant m = mutateText(source(f.job).text, seed, f.job);
            qWarning("THRONG_FUZZ_SEED=%llu THRONG_FUZZ_ONLY=%zu: %s (%s): %s", (unsigned long long)seed, f.job,
                     source(f.job).path.c_str(), m.what.c_str(), f.what.c_str());
        }
        qInfo("%zu mutants of %zu files, seed %llu: %zu failures", count, files.size(), (unsigned long long)seed,
              failures.size());
        QVERIFY2(failures.empty(), "mutated files crash, hang or poison a run (see the warnings above)");
    }
};

THRONG_REGISTER_TEST(TestFileFuzz)
#include "TestFileFuzz.moc"
