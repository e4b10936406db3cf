// Agents that leave through an exit leave the shot: their recorded frames say so from the
// step they left, the glTF export scales them to nothing from that time on (STEP, so they
// never shrink on the way), the CSV has no rows for them after it and the per-agent text
// files end there; the Khronos validator still finds nothing wrong with the export.
#include "ExternalReader.h"
#include "GltfReadBack.h"
#include "NavRig.h"
#include "TestRegistry.h"

#include "export/AgentTextCache.h"
#include "export/GltfExporter.h"
#include "export/TrajectoryCsv.h"
#include "simcore/world/FrameCache.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <fstream>

using namespace throng;
using namespace throng::sim;

namespace {

// Six walkers head for a 2 m exit 6 m away; two stay behind at a bench (no exit).
const char* kHall = R"(throng: 1
settings: {fps: 24, bounds: {min: [-10, -10], max: [10, 10]}}
agent_types:
  - {name: walker, behaviours: {arrival: 1, separation: 1}}
goals:
  - {name: door, position: [6, 0], radius: 1, exit: true}
  - {name: bench, position: [-6, 0], radius: 1}
groups:
  - {name: leavers, type: walker, count: 6, rect: {min: [-1, -2], max: [1, 2]}, goal: door}
  - {name: sitters, type: walker, count: 2, rect: {min: [-7, -1], max: [-5, 1]}, goal: bench}
)";

struct Recorded {
    Scene scene;
    FrameCache cache;
    std::vector<std::size_t> exitFrame;  // per agent: the first frame it is out; frameCount() = never
};

Recorded record(double seconds)
{
    Recorded r;
    r.scene = test::parse(kHall);
    World world(r.scene);
    world.startRecording(r.cache);
    r.exitFrame.assign(world.agentCount(), std::size_t(-1));
    std::vector<AgentFrame> frame;
    while (world.timeS() < seconds) {
        world.step();
        world.snapshot(frame);
        r.cache.append(frame);
        for (std::size_t i = 0; i < world.agentCount(); ++i)
            if (world.isOut(i) && r.exitFrame[i] == std::size_t(-1))
                r.exitFrame[i] = r.cache.frameCount() - 1;
    }
    for (std::size_t& f : r.exitFrame)
        f = std::min(f, r.cache.frameCount());
    return r;
}

std::size_t countLines(const std::string& path)
{
    std::ifstream in(path);
    std::size_t n = 0;
    for (std::string line; std::getline(in, line);)
        ++n;
    return n;
}

}  // namespace

class TestExitedAgents : public QObject {
    Q_OBJECT
private slots:
    void framesMarkAgentsOutFromTheStepTheyLeft()
    {
        const Recorded r = record(30.0);
        const std::size_t frames = r.cache.frameCount();
        for (std::size_t i = 0; i < 6; ++i) {
            QVERIFY2(r.exitFrame[i] > 0 && r.exitFrame[i] < frames - 24, "every leaver is out well before the end");
            for (std::size_t f = 0; f < frames; ++f)
                QCOMPARE(r.cache.at(f, i).out, f >= r.exitFrame[i]);
            // Out at the door, not somewhere else.
            const glm::vec3 p = r.cache.at(frames - 1, i).position;
            QVERIFY(std::hypot(p.x - 6.0f, p.z) < 2.0f);
        }
        for (std::size_t i = 6; i < 8; ++i)
            for (std::size_t f = 0; f < frames; ++f)
                QVERIFY(!r.cache.at(f, i).out);

        // The flag is part of the recording's identity.
        FrameCache changed = r.cache;
        changed.truncate(frames - 1);
        std::vector<AgentFrame> last(r.cache.frame(frames - 1).begin(), r.cache.frame(frames - 1).end());
        const std::uint64_t same = [&] { FrameCache c = changed; c.append(last); return c.hash(); }();
        QCOMPARE(same, r.cache.hash());
        last[0].out = false;
        changed.append(last);
        QVERIFY(changed.hash() != r.cache.hash());
    }

    void exportsHideThemAfterTheyLeft()
    {
        const Recorded r = record(30.0);
        const std::size_t frames = r.cache.frameCount();
        const float fps = r.cache.fps();
        QTemporaryDir dir;
        for (const exporting::GltfMode mode : {exporting::GltfMode::Exact, exporting::GltfMode::Compact}) {
            exporting::GltfOptions options;
            options.path = dir.filePath(mode == exporting::GltfMode::Exact ? "exact.glb" : "compact.glb").toStdString();
            options.mode = mode;
            const exporting::ExportResult result = exporting::exportGltf(r.scene, r.cache, options);
            QVERIFY2(result.ok(), result.error.c_str());
            tinygltf::Model model;
            std::string error;
            QVERIFY2(test::loadGltf(options.path, model, error), error.c_str());
            for (std::size_t i = 0; i < r.cache.agentCount(); ++i) {
                const std::string name = "agent_" + std::to_string(r.cache.agents()[i].id) + "_walker";
                const int node = test::nodeNamed(model, name);
                QVERIFY2(node >= 0, name.c_str());
                const tinygltf::AnimationSampler* sampler = test::samplerFor(model, node, "scale");
                if (r.exitFrame[i] >= frames) {
                    QVERIFY2(!sampler, "an agent that stays has no scale channel");
                    continue;
                }
                QVERIFY(sampler);
                QCOMPARE(sampler->interpolation, std::string("STEP"));
                const std::vector<float> times = test::accessorFloats(model, sampler->input);
                const std::vector<float> scales = test::accessorFloats(model, sampler->output);
                QCOMPARE(times.size(), std::size_t(2));
                QCOMPARE(scales.size(), std::size_t(6));
                // Shown (its height scale, > 0) until the frame it left, nothing from then on.
                QCOMPARE(times[1], float(r.exitFrame[i]) / fps);
                QVERIFY(scales[0] > 0.5f && scales[0] == scales[1] && scales[1] == scales[2]);
                QCOMPARE(scales[3], 0.0f);
                QCOMPARE(scales[4], 0.0f);
                QCOMPARE(scales[5], 0.0f);
            }
            if (QFile::exists(test::externalReaderPath("gltf-validate"))) {
                const test::ExternalReaderRun run = test::runExternalReader(
                    "gltf-validate", {"--agent-regex", "^agent_\\d+_[a-z]+$", QString::fromStdString(options.path)});
                QVERIFY2(run.started && run.exitCode == 0, qPrintable(run.output));
                QCOMPARE(run.summary["errors"].toInt(-1), 0);
                QVERIFY2(run.summary["warnings"].toInt(-1) == 0, qPrintable(run.output));
            }
        }

        // CSV: one row per agent per frame while it is in the shot.
        const std::string csv = dir.filePath("trajectories.csv").toStdString();
        QVERIFY(exporting::writeTrajectoryCsv(r.cache, csv).ok());
        std::size_t rows = 0;
        for (std::size_t i = 0; i < r.cache.agentCount(); ++i)
            rows += std::min(r.exitFrame[i], frames);
        QCOMPARE(countLines(csv), rows + 1);
        // Per-agent text files: one line per frame before it left.
        const std::string cacheDir = dir.filePath("cache").toStdString();
        QVERIFY(exporting::writeAgentTextCache(r.cache, cacheDir).ok());
        for (std::size_t i = 0; i < r.cache.agentCount(); ++i)
            QCOMPARE(countLines(cacheDir + "/agent_" + std::to_string(r.cache.agents()[i].id) + ".txt"),
                     std::min(r.exitFrame[i], frames));
    }
};

THRONG_REGISTER_TEST(TestExitedAgents)
#include "TestExitedAgents.moc"
