// Exports of a recording whose agent set changed mid-way (issue 6: a brush stroke resumed
// at the edit frame): an agent added at frame k is hidden in the glTF before k (scale 0,
// STEP) and shown from k, an erased one hidden from k; the CSV has rows only where an
// agent is present; the Khronos validator finds nothing wrong.
#include "ExternalReader.h"
#include "GltfReadBack.h"
#include "TestRegistry.h"

#include "export/AgentTextCache.h"
#include "export/GltfExporter.h"
#include "export/TrajectoryCsv.h"
#include "simcore/io/SceneIO.h"
#include "simcore/world/World.h"
#include "simcore/world/WorldState.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <fstream>
#include <string>

using namespace throng;
using namespace throng::sim;

namespace {

const char* kYard = R"(throng: 1
settings: {fps: 24, bounds: {min: [-10, -10], max: [10, 10]}}
agent_types:
  - {name: walker, behaviours: {arrival: 1, separation: 1}}
goals:
  - {name: east, position: [8, 0], radius: 1}
agents:
  - {id: 1, type: walker, position: [-6, 0, -2], goal: east}
  - {id: 2, type: walker, position: [-6, 0, 2], goal: east}
groups:
  - {name: crowd, type: walker, count: 4, rect: {min: [-4, -3], max: [-2, 3]}, goal: east}
)";

Scene parse(const char* yaml)
{
    LoadResult r = parseScene(yaml, "yard.yaml", THRONG_SOURCE_DIR "/resources");
    if (!r.ok())
        qFatal("%s", r.diagnostics.front().format().c_str());
    return r.scene;
}

std::size_t countLines(const std::string& path)
{
    std::ifstream in(path);
    std::size_t n = 0;
    for (std::string line; std::getline(in, line);)
        ++n;
    return n;
}

std::string firstLine(const std::string& path)
{
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    return line;
}

constexpr std::size_t kEdit = 24, kFrames = 49;

}  // namespace

class TestResumedExport : public QObject {
    Q_OBJECT

private slots:
    void anAgentAddedMidwayIsHiddenBeforeIt()
    {
        const Scene scene = parse(kYard);
        World world(scene);
        FrameCache cache;
        world.startRecording(cache);
        std::vector<AgentFrame> frame;
        for (std::size_t f = 1; f <= kEdit; ++f) {
            world.step();
            world.snapshot(frame);
            cache.append(frame);
        }
        // At frame 24 a stroke adds agent 7 and erases agent 2; frames 25 on are the edit's.
        Scene edited = scene;
        edited.agents.erase(edited.agents.begin() + 1);
        Agent added = edited.agents.front();
        added.id = 7;
        added.position = {-6.0f, 0.0f, 5.0f};
        edited.agents.push_back(added);
        World resumed(edited);
        std::vector<std::int32_t> previous;
        QVERIFY(resumed.adoptState(world.saveState(), scene, edited, &previous));
        cache.changeAgents(resumed.agentInfo(), previous);
        while (cache.frameCount() < kFrames) {
            resumed.step();
            resumed.snapshot(frame);
            cache.append(frame);
        }
        QCOMPARE(cache.agentCount(), std::size_t(7));
        const std::size_t agent7 = 6, agent2 = 1;
        QCOMPARE(cache.agents()[agent7].id, AgentId(7));
        QCOMPARE(cache.agents()[agent2].id, AgentId(2));

        QTemporaryDir dir;
        for (const exporting::GltfMode mode : {exporting::GltfMode::Exact, exporting::GltfMode::Compact}) {
            exporting::GltfOptions options;
            options.path = dir.filePath(mode == exporting::GltfMode::Exact ? "exact.glb" : "compact.glb").toStdString();
            options.mode = mode;
            const exporting::ExportResult result = exporting::exportGltf(edited, cache, options);
            QVERIFY2(result.ok(), result.error.c_str());
            tinygltf::Model model;
            std::string error;
            QVERIFY2(test::loadGltf(options.path, model, error), error.c_str());
            const float t = float(kEdit + 1) / cache.fps();
            // Agent 7: nothing until frame 25, its height scale from then on.
            const int node7 = test::nodeNamed(model, "agent_7_walker");
            QVERIFY(node7 >= 0);
            const tinygltf::AnimationSampler* s7 = test::samplerFor(model, node7, "scale");
            QVERIFY(s7);
            QCOMPARE(s7->interpolation, std::string("STEP"));
            QCOMPARE(test::accessorFloats(model, s7->input), (std::vector<float>{0.0f, t}));
            const std::vector<float> scales7 = test::accessorFloats(model, s7->output);
            QCOMPARE(scales7.size(), std::size_t(6));
            QCOMPARE(scales7[0], 0.0f);
            QVERIFY(scales7[3] > 0.5f);
            // Where it first stands from the start (no slide in from the origin).
            const std::vector<float> at0 = test::evaluateChannel(model, node7, "translation", 0.0f);
            QCOMPARE(at0[0], cache.at(kEdit + 1, agent7).position.x);
            // Agent 2: shown, then nothing from frame 25 on.
            const int node2 = test::nodeNamed(model, "agent_2_walker");
            const tinygltf::AnimationSampler* s2 = test::samplerFor(model, node2, "scale");
            QVERIFY(s2);
            QCOMPARE(test::accessorFloats(model, s2->input), (std::vector<float>{0.0f, t}));
            const std::vector<float> scales2 = test::accessorFloats(model, s2->output);
            QVERIFY(scales2[0] > 0.5f);
            QCOMPARE(scales2[3], 0.0f);
            // Agents there all along have no scale channel.
            QVERIFY(!test::samplerFor(model, test::nodeNamed(model, "agent_1_walker"), "scale"));
            if (QFile::exists(test::externalReaderPath("gltf-validate"))) {
                const test::ExternalReaderRun run = test::runExternalReader(
                    "gltf-validate", {"--agent-regex", "^agent_\\d+_[a-z]+$", QString::fromStdString(options.path)});
                QVERIFY2(run.started && run.exitCode == 0, qPrintable(run.output));
                QCOMPARE(run.summary["errors"].toInt(-1), 0);
                QVERIFY2(run.summary["warnings"].toInt(-1) == 0, qPrintable(run.output));
            } else {
                qWarning("gltf-validate not found: the export was not validated");
            }
        }
        // CSV: rows only where present: 5 agents all along, agent 2 to frame 24, agent 7 from 25.
        const std::string csv = dir.filePath("trajectories.csv").toStdString();
        QVERIFY(exporting::writeTrajectoryCsv(cache, csv).ok());
        QCOMPARE(countLines(csv), 5 * kFrames + (kEdit + 1) + (kFrames - kEdit - 1) + 1);
        // Text cache: agent 7's file starts at frame 25 and says so; agent 2's ends at 24.
        const std::string cacheDir = dir.filePath("cache").toStdString();
        QVERIFY(exporting::writeAgentTextCache(cache, cacheDir).ok());
        QCOMPARE(countLines(cacheDir + "/agent_7.txt"), 1 + (kFrames - kEdit - 1));
        QCOMPARE(firstLine(cacheDir + "/agent_7.txt"), "# first_frame " + std::to_string(kEdit + 1));
        QCOMPARE(countLines(cacheDir + "/agent_2.txt"), kEdit + 1);
        QCOMPARE(countLines(cacheDir + "/agent_1.txt"), kFrames);
        QVERIFY(firstLine(cacheDir + "/agent_1.txt").rfind('#', 0) == std::string::npos);
    }
};

THRONG_REGISTER_TEST(TestResumedExport)
#include "TestResumedExport.moc"
