// What Blender, three.js and assimp make of real exports: the crossroads demo imports into
// Blender with one skinned, animated object per agent exactly where the trajectories CSV
// puts it; every export of the demo passes the Khronos validator; a 1,000-agent crowd
// loads in three.js and assimp in both modes. Slow (external programs): one class.
#include "CrowdFixture.h"
#include "ExternalReader.h"
#include "GltfReadBack.h"
#include "TestRegistry.h"

#include "export/GltfExporter.h"
#include "export/TrajectoryCsv.h"
#include "simcore/io/SceneIO.h"
#include "simcore/world/World.h"

#include <QFile>
#include <QJsonArray>
#include <QTemporaryDir>
#include <QTest>
#include <QTextStream>

#include <map>

using namespace throng;

namespace {

const char* const kAgentRegex = "^agent_\\d+_[a-z]+$";
// Roots and bodies: a body of several parts (skin, top, ...) is a group of skinned meshes
// in three.js, one per part, each centroid keyed by its own name.
const char* const kAgentOrBodyRegex = "^agent_\\d+_[a-z]+(_body)?$";

// Primitives of all meshes: what three.js makes skinned meshes of and assimp meshes.
// The primitives of the skinned meshes, the agents' bodies (skinnedOnly), or of every mesh
// (the set's too: they have no skin).
int primitiveCount(const std::string& path, bool skinnedOnly = true)
{
    tinygltf::Model model;
    std::string error;
    if (!test::loadGltf(path, model, error))
        return -1;
    int n = 0;
    for (const tinygltf::Node& node : model.nodes)
        if ((node.skin >= 0 || !skinnedOnly) && node.mesh >= 0)
            n += int(model.meshes[std::size_t(node.mesh)].primitives.size());
    return n;
}
constexpr std::size_t kCrossroadsFrames = 96;

QString crossroadsPath() { return QStringLiteral(THRONG_SOURCE_DIR "/resources/scenes/crossroads.yaml"); }

// frame -> agent id -> position, from the trajectories CSV.
std::map<int, std::map<int, glm::vec3>> readCsv(const QString& path)
{
    std::map<int, std::map<int, glm::vec3>> rows;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return rows;
    QTextStream in(&file);
    in.readLine();  // header
    while (!in.atEnd()) {
        const QStringList f = in.readLine().split(',');
        if (f.size() >= 5)
            rows[f[0].toInt()][f[1].toInt()] = {f[2].toFloat(), f[3].toFloat(), f[4].toFloat()};
    }
    return rows;
}

}  // namespace

class TestExternalReaders : public QObject {
    Q_OBJECT

    sim::Scene m_scene;
    std::size_t m_expected = 0;  // agents in the crossroads export: walkers, cars, the hero
    sim::FrameCache m_cache;
    QTemporaryDir m_dir;

    exporting::ExportResult exportCrossroads(const QString& name, exporting::GltfMode mode)
    {
        exporting::GltfOptions options;
        options.path = m_dir.filePath(name).toStdString();
        options.mode = mode;
        options.sceneDirectory = THRONG_SOURCE_DIR "/resources/scenes";
        return exporting::exportGltf(m_scene, m_cache, options);
    }

private slots:
    void initTestCase()
    {
        const sim::LoadResult loaded = sim::loadScene(crossroadsPath().toStdString());
        QVERIFY(loaded.ok());
        m_scene = loaded.scene;
        sim::World world(m_scene, sim::WorldOptions{});
        world.startRecording(m_cache);
        std::vector<sim::AgentFrame> frame;
        for (std::size_t f = 1; f < kCrossroadsFrames; ++f) {
            world.step();
            world.snapshot(frame);
            m_cache.append(frame);
        }
        // Every walker, car and the hero is an agent of the export.
        m_expected = m_scene.agents.size() + m_scene.vehicles.size() + m_scene.heroes.size();
        for (const sim::SpawnGroup& g : m_scene.groups)
            m_expected += g.count;
        QCOMPARE(m_scene.vehicles.size() > 0 && m_scene.heroes.size() > 0, true);
        QCOMPARE(m_cache.agentCount(), m_expected);
    }

    void crossroadsValidates_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<bool>("compact");
        QTest::newRow("exact glb") << "exact.glb" << false;
        QTest::newRow("exact gltf") << "exact.gltf" << false;
        QTest::newRow("compact glb") << "compact.glb" << true;
        QTest::newRow("compact gltf") << "compact.gltf" << true;
    }

    void crossroadsValidates()
    {
        QFETCH(QString, name);
        QFETCH(bool, compact);
        if (!QFile::exists(test::externalReaderPath("gltf-validate")))
            QSKIP("../shared/tools/gltf-validate is not beside the repository");
        const exporting::ExportResult r = exportCrossroads(name, compact ? exporting::GltfMode::Compact : exporting::GltfMode::Exact);
        QVERIFY2(r.ok(), r.error.c_str());
        const test::ExternalReaderRun run =
            test::runExternalReader("gltf-validate", {"--agent-regex", kAgentRegex, m_dir.filePath(name)});
        QVERIFY2(run.started && run.exitCode == 0, qPrintable(run.output));
        QCOMPARE(run.summary["errors"].toInt(-1), 0);
        QVERIFY2(run.summary["warnings"].toInt(-1) == 0, qPrintable(run.output));
        QCOMPARE(run.summary["stats"].toObject()["agentNodes"].toInt(), int(m_expected));
    }

    // Blender: one armature object per agent with its skinned body, animated over the
    // whole shot, roots at the first, middle and last frame within 1 cm of the CSV.
    void crossroadsInBlender()
    {
        if (!QFile::exists(test::externalReaderPath("blender-import-check")))
            QSKIP("../shared/tools/blender-import-check is not beside the repository");
        QVERIFY(exportCrossroads("blender.glb", exporting::GltfMode::Exact).ok());
        const QString csv = m_dir.filePath("trajectories.csv");
        QVERIFY(exporting::writeTrajectoryCsv(m_cache, csv.toStdString()).ok());
        const test::ExternalReaderRun run = test::runExternalReader(
            "blender-import-check", {"--no-centroid", "--expect-agents", QString::number(m_expected),
                                     "--expect-skinned", QString::number(m_expected),
                                     "--pattern", "agent_*", m_dir.filePath("blender.glb")});
        if (run.exitCode == 2)
            QSKIP(qPrintable("Blender is not available here: " + run.output.right(300)));
        QVERIFY2(run.started && run.exitCode == 0, qPrintable(run.output.right(3000)));
        const QJsonArray range = run.summary["frameRange"].toArray();
        QCOMPARE(range[0].toDouble(), 0.0);
        QCOMPARE(range[1].toDouble(), double(kCrossroadsFrames - 1));
        QCOMPARE(run.summary["counts"].toObject()["armatures"].toInt(), int(m_expected));
        const auto rows = readCsv(csv);
        const QJsonObject locations = run.summary["locations"].toObject();
        int checked = 0;
        for (std::size_t i = 0; i < m_cache.agentCount(); ++i) {
            const sim::AgentInfo& info = m_cache.agents()[i];
            const QString name = QString("agent_%1_%2").arg(info.id).arg(QString::fromStdString(m_scene.agentTypes[info.typeIndex].name));
            const QJsonObject frames = locations[name].toObject()["frames"].toObject();
            QVERIFY2(frames.size() == 3, qPrintable(name));
            for (const QString& key : frames.keys()) {
                const QJsonArray p = frames[key].toArray();
                const glm::vec3 seen(p[0].toDouble(), p[1].toDouble(), p[2].toDouble());
                const glm::vec3 truth = rows.at(key.toInt()).at(static_cast<int>(info.id));
                QVERIFY2(glm::length(seen - truth) < 0.01f, qPrintable(QString("%1 frame %2").arg(name, key)));
                ++checked;
            }
        }
        QCOMPARE(checked, int(3 * m_expected));  // every agent at three frames
    }

    // three.js skins the compact file's shared-cycle windows to the same bodies as the
    // exact bake for agents in a steady walk: skinned centroids of every part within 5 mm.
    void compactSkinsLikeExactInThree()
    {
        if (!QFile::exists(test::externalReaderPath("three-gltf-check")))
            QSKIP("../shared/tools/three-gltf-check is not beside the repository");
        const test::CrowdFixture fx = test::CrowdFixture::make();
        QJsonObject centroids[2];
        for (int compact = 0; compact < 2; ++compact) {
            exporting::GltfOptions options;
            options.path = m_dir.filePath(compact ? "steady-compact.glb" : "steady-exact.glb").toStdString();
            options.mode = compact ? exporting::GltfMode::Compact : exporting::GltfMode::Exact;
            QVERIFY(exporting::exportGltf(fx.scene, fx.cache, options).ok());
            const test::ExternalReaderRun run = test::runExternalReader(
                "three-gltf-check",
                {"--agent-regex", kAgentOrBodyRegex, "--times", "0.5,1,1.5", QString::fromStdString(options.path)});
            QVERIFY2(run.started && run.exitCode == 0, qPrintable(run.output.right(2000)));
            centroids[compact] = run.summary["centroids"].toObject();
        }
        QCOMPARE(centroids[1].keys(), centroids[0].keys());
        int parts = 0;
        for (const QString& body : centroids[0].keys()) {
            if (!body.startsWith("agent_7_walker") && !body.startsWith("agent_1000_walker"))
                continue;
            ++parts;
            for (const char* t : {"t=0.5", "t=1", "t=1.5"}) {
                const QJsonArray a = centroids[0][body].toObject()[t].toArray(), b = centroids[1][body].toObject()[t].toArray();
                QVERIFY2(a.size() == 3 && b.size() == 3, qPrintable(body));
                const glm::vec3 d(a[0].toDouble() - b[0].toDouble(), a[1].toDouble() - b[1].toDouble(), a[2].toDouble() - b[2].toDouble());
                QVERIFY2(glm::length(d) < 0.005f, qPrintable(QString("%1 %2: %3 m apart").arg(body, t).arg(glm::length(d))));
            }
        }
        QVERIFY2(parts >= 10, qPrintable(QString::number(parts)));  // two bodies of five parts or more
    }

    void bigCrowdInThreeAndAssimp_data()
    {
        QTest::addColumn<bool>("compact");
        QTest::newRow("exact") << false;
        QTest::newRow("compact") << true;
    }

    // 1,000 agents: three.js loads and plays every one (positions as recorded), and assimp
    // binds each agent's own 17-bone skin to every part of its body (a mesh a part, 17 bones each).
    void bigCrowdInThreeAndAssimp()
    {
        QFETCH(bool, compact);
        const test::CrowdFixture fx = test::CrowdFixture::makeCrowd(1000, 48);
        exporting::GltfOptions options;
        options.path = m_dir.filePath(compact ? "big-compact.glb" : "big-exact.glb").toStdString();
        options.mode = compact ? exporting::GltfMode::Compact : exporting::GltfMode::Exact;
        QVERIFY(exporting::exportGltf(fx.scene, fx.cache, options).ok());
        const QString file = QString::fromStdString(options.path);
        const int parts = primitiveCount(options.path);
        QVERIFY2(parts >= 5000, qPrintable(QString::number(parts)));  // five parts or more a body
        if (QFile::exists(test::externalReaderPath("three-gltf-check"))) {
            const test::ExternalReaderRun run = test::runExternalReader(
                "three-gltf-check", {"--agent-regex", kAgentRegex, "--expect-agents", "1000", "--no-centroid",
                                     "--max-objects", "20", "--times", "0,1,1.9583333", file});
            QVERIFY2(run.started && run.exitCode == 0, qPrintable(run.output.right(2000)));
            QCOMPARE(run.summary["counts"].toObject()["skinnedMeshes"].toInt(), parts);
            const QJsonObject locations = run.summary["locations"].toObject();
            QVERIFY(!locations.isEmpty());
            for (const QString& name : locations.keys()) {
                const int id = name.split('_')[1].toInt();
                const QJsonArray p = locations[name].toObject()["t=1"].toArray();
                const glm::vec3 truth = fx.cache.at(24, static_cast<std::size_t>(id - 1)).position;
                QVERIFY2(glm::length(glm::vec3(p[0].toDouble(), p[1].toDouble(), p[2].toDouble()) - truth) < 0.01f,
                         qPrintable(name));
            }
        }
        if (QFile::exists(test::externalReaderPath("assimp-info-check"))) {
            const test::ExternalReaderRun run =
                test::runExternalReader("assimp-info-check", {"--expect-bones", QString::number(17 * parts), file});
            QVERIFY2(run.started && run.exitCode == 0, qPrintable(run.output.right(2000)));
            // A mesh per primitive: the bodies', and the set's (the fixture's ground).
            QCOMPARE(run.summary["meshes"].toInt(), primitiveCount(options.path, false));
            QVERIFY(primitiveCount(options.path, false) > parts);
        }
    }
};

THRONG_REGISTER_TEST(TestExternalReaders)
#include "TestExternalReaders.moc"
