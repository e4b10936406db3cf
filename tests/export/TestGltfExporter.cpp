// The glTF export opens in other readers with the crowd of the simulation: one node per
// agent where the cache puts it, facing where it walks, one shared clock, zero validator
// complaints; and a cancelled or failed export leaves nothing behind.
#include "CrowdFixture.h"
#include "ExternalReader.h"
#include "GltfReadBack.h"
#include "TestRegistry.h"

#include "export/GltfExporter.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QTemporaryDir>
#include <QTest>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <set>

using namespace throng;
using throng::test::CrowdFixture;

namespace {

const char* const kAgentRegex = "^agent_\\d+_";

exporting::ExportResult exportTo(const CrowdFixture& fx, const QString& path, const exporting::ProgressFn& progress = {})
{
    exporting::GltfOptions options;
    options.path = path.toStdString();
    return exporting::exportGltf(fx.scene, fx.cache, options, progress);
}

QStringList entries(const QString& dir) { return QDir(dir).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot); }

}  // namespace

class TestGltfExporter : public QObject {
    Q_OBJECT

    // Exports the fixture to `name` in `dir` and loads it back.
    static void exportAndLoad(const QTemporaryDir& dir, const QString& name, tinygltf::Model& model)
    {
        const CrowdFixture fx = CrowdFixture::make();
        const exporting::ExportResult result = exportTo(fx, dir.filePath(name));
        QVERIFY2(result.ok(), result.error.c_str());
        std::string error;
        QVERIFY2(test::loadGltf(dir.filePath(name).toStdString(), model, error), error.c_str());
    }

private slots:
    void format_data()
    {
        QTest::addColumn<QString>("name");
        QTest::newRow("glb") << "crowd.glb";
        QTest::newRow("gltf") << "crowd.gltf";
    }

    // One node per agent, named agent_<id>_<type>, using its type's one shared mesh.
    void format()
    {
        QFETCH(QString, name);
        QTemporaryDir dir;
        tinygltf::Model model;
        exportAndLoad(dir, name, model);
        if (QTest::currentTestFailed())
            return;
        QCOMPARE(model.nodes.size(), std::size_t(3));
        const int n7 = test::nodeNamed(model, "agent_7_walker");
        const int n42 = test::nodeNamed(model, "agent_42_runner");
        const int n1000 = test::nodeNamed(model, "agent_1000_walker");
        QVERIFY(n7 >= 0 && n42 >= 0 && n1000 >= 0);
        QCOMPARE(model.meshes.size(), std::size_t(2));
        QCOMPARE(model.nodes[n7].mesh, model.nodes[n1000].mesh);
        QVERIFY(model.nodes[n7].mesh != model.nodes[n42].mesh);
        QCOMPARE(model.scenes.at(model.defaultScene).nodes.size(), std::size_t(3));
    }

    // Every sampler reads one time accessor: frame f at f / fps seconds, 0 .. 2 s.
    void oneSharedTimeAccessor()
    {
        QTemporaryDir dir;
        tinygltf::Model model;
        exportAndLoad(dir, "crowd.glb", model);
        if (QTest::currentTestFailed())
            return;
        QCOMPARE(model.animations.size(), std::size_t(1));
        const tinygltf::Animation& animation = model.animations[0];
        QCOMPARE(animation.name, std::string("crowd"));
        QCOMPARE(animation.channels.size(), std::size_t(6));  // translation + rotation per agent
        std::set<int> inputs;
        for (const tinygltf::AnimationSampler& s : animation.samplers)
            inputs.insert(s.input);
        QCOMPARE(inputs.size(), std::size_t(1));
        const std::vector<float> times = test::accessorFloats(model, *inputs.begin());
        QCOMPARE(times.size(), CrowdFixture::kFrames);
        QCOMPARE(times.front(), 0.0f);
        QVERIFY(std::abs(times[24] - 1.0f) < 1e-6f);
        QVERIFY(std::abs(times.back() - 2.0f) < 1e-6f);
        const tinygltf::Accessor& accessor = model.accessors[*inputs.begin()];
        QCOMPARE(accessor.minValues, std::vector<double>{0.0});
        QCOMPARE(accessor.maxValues, std::vector<double>{double(times.back())});
    }

    void translationsMatchTheCache_data() { format_data(); }

    // At the first, middle and last keyframe each agent is where the cache (and the
    // straight line it walks) puts it.
    void translationsMatchTheCache()
    {
        QFETCH(QString, name);
        QTemporaryDir dir;
        tinygltf::Model model;
        exportAndLoad(dir, name, model);
        if (QTest::currentTestFailed())
            return;
        const CrowdFixture fx = CrowdFixture::make();
        const char* names[] = {"agent_7_walker", "agent_42_runner", "agent_1000_walker"};
        for (std::size_t agent = 0; agent < 3; ++agent) {
            const tinygltf::AnimationSampler* sampler =
                test::samplerFor(model, test::nodeNamed(model, names[agent]), "translation");
            QVERIFY(sampler);
            const std::vector<float> xyz = test::accessorFloats(model, sampler->output);
            QCOMPARE(xyz.size(), 3 * CrowdFixture::kFrames);
            for (std::size_t f : {std::size_t(0), CrowdFixture::kMiddleFrame, CrowdFixture::kFrames - 1}) {
                const glm::vec3 cached = fx.cache.at(f, agent).position;
                const glm::vec3 exported(xyz[3 * f], xyz[3 * f + 1], xyz[3 * f + 2]);
                QVERIFY2(glm::length(exported - cached) < 1e-5f, qPrintable(QString("%1 frame %2").arg(names[agent]).arg(f)));
                QVERIFY(glm::length(exported - CrowdFixture::truePosition(agent, f)) < 1e-5f);
            }
        }
        // Agent 42 ran 6 m north (-z) in 2 s.
        const auto* sampler = test::samplerFor(model, test::nodeNamed(model, "agent_42_runner"), "translation");
        const std::vector<float> xyz = test::accessorFloats(model, sampler->output);
        QVERIFY(std::abs(xyz[3 * (CrowdFixture::kFrames - 1) + 2] - -4.0f) < 1e-5f);
    }

    // The body's nose (+X of the mesh) turned by each keyframe's rotation points along
    // the agent's direction of travel, and the rotations are unit quaternions.
    void bodiesFaceTheirDirectionOfTravel()
    {
        QTemporaryDir dir;
        tinygltf::Model model;
        exportAndLoad(dir, "crowd.gltf", model);
        if (QTest::currentTestFailed())
            return;
        for (std::size_t agent = 0; agent < 3; ++agent) {
            const int node = static_cast<int>(agent);  // nodes come in the cache's dense order
            const tinygltf::AnimationSampler* sampler = test::samplerFor(model, node, "rotation");
            QVERIFY(sampler);
            const std::vector<float> q = test::accessorFloats(model, sampler->output);
            QCOMPARE(q.size(), 4 * CrowdFixture::kFrames);
            for (std::size_t f : {std::size_t(0), CrowdFixture::kMiddleFrame, CrowdFixture::kFrames - 1}) {
                const glm::quat rotation(q[4 * f + 3], q[4 * f], q[4 * f + 1], q[4 * f + 2]);  // w, x, y, z
                QVERIFY(std::abs(glm::length(rotation) - 1.0f) < 1e-6f);
                const glm::vec3 nose = rotation * glm::vec3(1.0f, 0.0f, 0.0f);
                QVERIFY2(glm::length(nose - CrowdFixture::trueGroundDirection(agent)) < 1e-5f,
                         qPrintable(QString("node %1 frame %2 nose (%3, %4, %5)")
                                        .arg(node).arg(f).arg(nose.x).arg(nose.y).arg(nose.z)));
            }
            // A viewer that ignores animation still shows frame 0's pose.
            QCOMPARE(model.nodes[node].rotation.size(), std::size_t(4));
            QCOMPARE(model.nodes[node].translation.size(), std::size_t(3));
        }
    }

    // The stand-in body of a 0.3 m walker stands on the ground, about 1.7 m tall, nose forward.
    void bodyIsHumanSizedWithANoseOnPlusX()
    {
        QTemporaryDir dir;
        tinygltf::Model model;
        exportAndLoad(dir, "crowd.glb", model);
        if (QTest::currentTestFailed())
            return;
        const tinygltf::Primitive& body = model.meshes.at(model.nodes.at(0).mesh).primitives.at(0);
        QVERIFY(body.attributes.count("NORMAL"));
        const tinygltf::Accessor& position = model.accessors.at(body.attributes.at("POSITION"));
        QCOMPARE(position.minValues.size(), std::size_t(3));
        QCOMPARE(position.minValues[1], 0.0);
        QVERIFY(std::abs(position.maxValues[1] - 1.7) < 1e-3);
        QVERIFY(position.maxValues[0] > 0.4);             // the nose sticks out past the 0.3 m body
        QVERIFY(-position.minValues[0] < 0.31);           // nothing sticks out at the back
        QVERIFY(std::abs(position.maxValues[2] + position.minValues[2]) < 1e-6);  // symmetric sideways
        // Every face is wound counter-clockwise seen from outside, with its normal agreeing
        // (back-face culling and shading rely on both), and the solid it encloses has a
        // positive volume of about a 0.3 m x 1.7 m cylinder.
        const std::vector<float> xyz = test::accessorFloats(model, body.attributes.at("POSITION"));
        const std::vector<float> normals = test::accessorFloats(model, body.attributes.at("NORMAL"));
        QCOMPARE(xyz.size() % 9, std::size_t(0));
        QCOMPARE(normals.size(), xyz.size());
        double volume = 0.0;
        for (std::size_t t = 0; t < xyz.size(); t += 9) {
            const glm::vec3 a(xyz[t], xyz[t + 1], xyz[t + 2]), b(xyz[t + 3], xyz[t + 4], xyz[t + 5]),
                c(xyz[t + 6], xyz[t + 7], xyz[t + 8]);
            const glm::vec3 n(normals[t], normals[t + 1], normals[t + 2]);
            QVERIFY(glm::length(glm::normalize(glm::cross(b - a, c - a)) - n) < 1e-5f);
            volume += glm::dot(a, glm::cross(b, c)) / 6.0;
        }
        const double cylinder = 3.14159 * 0.3 * 0.3 * 1.7;
        QVERIFY2(volume > 0.75 * cylinder && volume < cylinder, qPrintable(QString::number(volume)));
        // The runner carries its tint.
        const tinygltf::Primitive& runner = model.meshes.at(model.nodes.at(1).mesh).primitives.at(0);
        const std::vector<double> colour = model.materials.at(runner.material).pbrMetallicRoughness.baseColorFactor;
        QVERIFY(std::abs(colour[2] - 0.9) < 1e-6);
    }

    void extrasDescribeTheRun()
    {
        QTemporaryDir dir;
        tinygltf::Model model;
        exportAndLoad(dir, "crowd.gltf", model);
        if (QTest::currentTestFailed())
            return;
        for (const tinygltf::Value* extras : {&model.scenes.at(0).extras, &model.asset.extras}) {
            QVERIFY(extras->IsObject());
            QCOMPARE(extras->Get("generator").Get<std::string>(), std::string("Throng"));
            QCOMPARE(extras->Get("fps").GetNumberAsDouble(), 24.0);
            QCOMPARE(extras->Get("frameCount").GetNumberAsInt(), 49);
            QCOMPARE(extras->Get("agentCount").GetNumberAsInt(), 3);
        }
    }

    void khronosValidatorFindsNothing_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QStringList>("written");
        QTest::newRow("glb") << "crowd.glb" << QStringList{"crowd.glb"};
        QTest::newRow("gltf") << "crowd.gltf" << QStringList{"crowd.bin", "crowd.gltf"};
        QTest::newRow("gltf, name needing URI escapes") << "shot 12 (final).gltf"
                                                        << QStringList{"shot 12 (final).gltf", "shot_12__final_.bin"};
    }

    // Zero errors and zero warnings from the Khronos glTF Validator, one shared input.
    void khronosValidatorFindsNothing()
    {
        QFETCH(QString, name);
        QFETCH(QStringList, written);
        if (!QFile::exists(test::externalReaderPath("gltf-validate")))
            QSKIP("../shared/tools/gltf-validate is not beside the repository");
        const CrowdFixture fx = CrowdFixture::make();
        QTemporaryDir dir;
        const exporting::ExportResult result = exportTo(fx, dir.filePath(name));
        QVERIFY2(result.ok(), result.error.c_str());
        QStringList files = entries(dir.path());
        files.sort();
        QCOMPARE(files, written);
        QCOMPARE(result.writtenPaths.size(), std::size_t(written.size()));

        const test::ExternalReaderRun run =
            test::runExternalReader("gltf-validate", {"--agent-regex", kAgentRegex, dir.filePath(name)});
        QVERIFY2(run.started && !run.summary.isEmpty(), qPrintable(run.output));
        QVERIFY2(run.exitCode == 0, qPrintable(run.output));
        QCOMPARE(run.summary["errors"].toInt(-1), 0);
        QVERIFY2(run.summary["warnings"].toInt(-1) == 0, qPrintable(run.output));
        const QJsonObject stats = run.summary["stats"].toObject();
        QCOMPARE(stats["agentNodes"].toInt(), 3);
        QCOMPARE(stats["distinctSamplerInputs"].toInt(), 1);
        QCOMPARE(stats["meshes"].toInt(), 2);
    }

    // three.js's AnimationMixer, an independent evaluator, puts agents where the cache does.
    void threeJsPlaysTheCrowd()
    {
        if (!QFile::exists(test::externalReaderPath("three-gltf-check")))
            QSKIP("../shared/tools/three-gltf-check is not beside the repository");
        const CrowdFixture fx = CrowdFixture::make();
        QTemporaryDir dir;
        QVERIFY(exportTo(fx, dir.filePath("crowd.glb")).ok());
        const test::ExternalReaderRun run = test::runExternalReader(
            "three-gltf-check", {"--agent-regex", kAgentRegex, "--expect-agents", "3", "--require-motion", "--times",
                                 "0,1,2", dir.filePath("crowd.glb")});
        QVERIFY2(run.started && run.exitCode == 0, qPrintable(run.output));
        const QJsonObject locations = run.summary["locations"].toObject();
        const char* names[] = {"agent_7_walker", "agent_42_runner", "agent_1000_walker"};
        const std::pair<const char*, std::size_t> samples[] = {{"t=0", 0}, {"t=1", 24}, {"t=2", 48}};
        for (std::size_t agent = 0; agent < 3; ++agent) {
            for (const auto& [key, frame] : samples) {
                const QJsonArray p = locations[names[agent]].toObject()[key].toArray();
                QVERIFY2(p.size() == 3, qPrintable(run.output));
                const glm::vec3 cached = fx.cache.at(frame, agent).position;
                const glm::vec3 seen(p[0].toDouble(), p[1].toDouble(), p[2].toDouble());
                QVERIFY2(glm::length(seen - cached) < 1e-4f, qPrintable(QString("%1 %2").arg(names[agent], key)));
            }
        }
    }

    void cancelLeavesNothing_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<float>("cancelAt");
        QTest::newRow("glb, at the start") << "crowd.glb" << 0.0f;
        QTest::newRow("glb, with the file written") << "crowd.glb" << 0.9f;
        QTest::newRow("gltf, at the start") << "crowd.gltf" << 0.0f;
        QTest::newRow("gltf, with the files written") << "crowd.gltf" << 0.9f;
    }

    // Cancelling, early or with the temporaries on disk, leaves the folder as it was.
    void cancelLeavesNothing()
    {
        QFETCH(QString, name);
        QFETCH(float, cancelAt);
        const CrowdFixture fx = CrowdFixture::make();
        QTemporaryDir dir;
        float last = -1.0f;
        bool monotonic = true;
        const exporting::ExportResult result = exportTo(fx, dir.filePath(name), [&](float fraction) {
            monotonic = monotonic && fraction >= last && fraction <= 1.0f;
            last = fraction;
            return fraction < cancelAt;
        });
        QVERIFY(result.cancelled);
        QVERIFY(!result.ok());
        QVERIFY(monotonic);
        QVERIFY(last >= cancelAt);
        QVERIFY2(result.error.find(name.toStdString()) != std::string::npos, result.error.c_str());
        QCOMPARE(entries(dir.path()), QStringList{});
    }

    void progressRunsFromZeroToOne()
    {
        const CrowdFixture fx = CrowdFixture::make();
        QTemporaryDir dir;
        std::vector<float> seen;
        const exporting::ExportResult result = exportTo(fx, dir.filePath("crowd.glb"), [&](float fraction) {
            seen.push_back(fraction);
            return true;
        });
        QVERIFY(result.ok());
        QVERIFY(seen.size() >= 3);
        QCOMPARE(seen.front(), 0.0f);
        QCOMPARE(seen.back(), 1.0f);
        QVERIFY(std::is_sorted(seen.begin(), seen.end()));
    }

    void unwritablePathGivesErrorNamingIt_data() { format_data(); }

    // The parent is a regular file: no user (root included) can create anything under it.
    void unwritablePathGivesErrorNamingIt()
    {
        QFETCH(QString, name);
        const CrowdFixture fx = CrowdFixture::make();
        QTemporaryDir dir;
        QFile blocker(dir.filePath("plain-file"));
        QVERIFY(blocker.open(QIODevice::WriteOnly));
        blocker.close();
        const QString path = dir.filePath("plain-file/" + name);
        const exporting::ExportResult result = exportTo(fx, path);
        QVERIFY(!result.ok());
        QVERIFY(!result.cancelled);
        QVERIFY(result.writtenPaths.empty());
        QVERIFY2(result.error.find(path.toStdString()) != std::string::npos, result.error.c_str());
        QCOMPARE(entries(dir.path()), QStringList{"plain-file"});
    }

    void badInputGivesErrorNamingIt()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("crowd.glb");
        CrowdFixture empty = CrowdFixture::make();
        empty.cache.truncate(0);
        exporting::ExportResult result = exportTo(empty, path);
        QVERIFY(!result.ok());
        QVERIFY2(result.error.find("nothing recorded") != std::string::npos, result.error.c_str());

        CrowdFixture oneType = CrowdFixture::make();
        oneType.scene.agentTypes.pop_back();  // agent 42's "runner" is gone
        result = exportTo(oneType, path);
        QVERIFY(!result.ok());
        QVERIFY2(result.error.find("agent 42") != std::string::npos, result.error.c_str());
        QVERIFY(result.error.find(path.toStdString()) != std::string::npos);

        CrowdFixture flat = CrowdFixture::make();
        flat.scene.agentTypes[0].radiusM = 0.0f;
        result = exportTo(flat, path);
        QVERIFY2(result.error.find("'walker' has radius 0") != std::string::npos, result.error.c_str());
        QCOMPARE(entries(dir.path()), QStringList{});
    }
};

THRONG_REGISTER_TEST(TestGltfExporter)
#include "TestGltfExporter.moc"
