// The glTF export opens in other readers with the crowd of the simulation: one skinned
// character per agent where the cache puts it, facing where it walks, shared geometry and
// clocks, zero validator complaints in both modes; a cancelled or failed export leaves
// nothing behind.
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
#include <map>
#include <set>

using namespace throng;
using throng::test::CrowdFixture;

namespace {

// Agent roots only: not their joints (agent_7_walker__hips) nor bodies (agent_7_walker_body).
const char* const kAgentRegex = "^agent_\\d+_[a-z]+$";

exporting::ExportResult exportTo(const CrowdFixture& fx, const QString& path, const exporting::ProgressFn& progress = {},
                                 exporting::GltfMode mode = exporting::GltfMode::Exact, int threads = 0)
{
    exporting::GltfOptions options;
    options.path = path.toStdString();
    options.mode = mode;
    options.threads = threads;
    return exporting::exportGltf(fx.scene, fx.cache, options, progress);
}

glm::vec3 positionAt(const tinygltf::Model& model, const char* agent, std::size_t frame)
{
    const std::vector<float> p = test::evaluateChannel(model, test::nodeNamed(model, agent), "translation",
                                                       static_cast<float>(frame) / CrowdFixture::kFps);
    return p.size() == 3 ? glm::vec3(p[0], p[1], p[2]) : glm::vec3(1e9f);
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

    // Per agent: a root agent_<id>_<type> with its 17 joints under it, and a body node with
    // the agent's own mesh entry and skin over geometry every agent of that look shares;
    // besides them the set: a node `set` over the ground of the fixture's bounds.
    void format()
    {
        QFETCH(QString, name);
        QTemporaryDir dir;
        tinygltf::Model model;
        exportAndLoad(dir, name, model);
        if (QTest::currentTestFailed())
            return;
        QCOMPARE(model.nodes.size(), std::size_t(3 * (1 + 17 + 1) + 2));
        QCOMPARE(model.nodes[std::size_t(test::nodeNamed(model, "set"))].children,
                 std::vector<int>{test::nodeNamed(model, "set_ground")});
        const int n7 = test::nodeNamed(model, "agent_7_walker");
        const int n42 = test::nodeNamed(model, "agent_42_runner");
        const int n1000 = test::nodeNamed(model, "agent_1000_walker");
        QVERIFY(n7 >= 0 && n42 >= 0 && n1000 >= 0);
        QCOMPARE(model.nodes[n7].mesh, -1);
        QCOMPARE(model.nodes[n7].children, std::vector<int>{test::nodeNamed(model, "agent_7_walker__hips")});
        QVERIFY(test::nodeNamed(model, "agent_42_runner__foot_r") >= 0);
        const int body7 = test::nodeNamed(model, "agent_7_walker_body");
        const int body1000 = test::nodeNamed(model, "agent_1000_walker_body");
        QVERIFY(body7 >= 0 && body1000 >= 0);
        // Own mesh entries (assimp binds one skin per mesh), one set of vertex accessors.
        QCOMPARE(model.meshes.size(), std::size_t(3 + 1));  // and the ground's
        QVERIFY(model.nodes[body7].mesh != model.nodes[body1000].mesh);
        QCOMPARE(model.meshes[model.nodes[body7].mesh].primitives[0].attributes,
                 model.meshes[model.nodes[body1000].mesh].primitives[0].attributes);
        QCOMPARE(model.skins.size(), std::size_t(3));
        QCOMPARE(model.skins[model.nodes[body7].skin].inverseBindMatrices,
                 model.skins[model.nodes[body1000].skin].inverseBindMatrices);
        QCOMPARE(model.skins[model.nodes[body7].skin].joints.size(), std::size_t(17));
        // Roots, bodies and the set are the scene's roots; joints hang under the roots.
        QCOMPARE(model.scenes.at(model.defaultScene).nodes.size(), std::size_t(6 + 1));
    }

    // Root channels share clocks: a straight walk at constant speed keeps two keys read
    // through the one {0, 2 s} accessor, and every input runs within 0 .. 2 s.
    void sharedClocks()
    {
        QTemporaryDir dir;
        tinygltf::Model model;
        exportAndLoad(dir, "crowd.glb", model);
        if (QTest::currentTestFailed())
            return;
        QCOMPARE(model.animations.size(), std::size_t(1));
        const tinygltf::Animation& animation = model.animations[0];
        QCOMPARE(animation.name, std::string("crowd"));
        QCOMPARE(animation.channels.size(), std::size_t(3 * (2 + 1 + 17)));
        std::set<int> rootInputs;
        for (const char* agent : {"agent_7_walker", "agent_42_runner", "agent_1000_walker"})
            for (const char* path : {"translation", "rotation"})
                rootInputs.insert(test::samplerFor(model, test::nodeNamed(model, agent), path)->input);
        QCOMPARE(rootInputs.size(), std::size_t(1));
        QCOMPARE(test::accessorFloats(model, *rootInputs.begin()), (std::vector<float>{0.0f, 2.0f}));
        double latest = 0.0;
        for (const tinygltf::AnimationSampler& s : animation.samplers) {
            const tinygltf::Accessor& input = model.accessors.at(s.input);
            QVERIFY(input.minValues.at(0) >= 0.0 && input.maxValues.at(0) <= 2.0 + 1e-6);
            latest = std::max(latest, input.maxValues.at(0));
        }
        QCOMPARE(latest, 2.0);
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
            for (std::size_t f = 0; f < CrowdFixture::kFrames; ++f) {
                const glm::vec3 exported = positionAt(model, names[agent], f);
                QVERIFY2(glm::length(exported - fx.cache.at(f, agent).position) < 1e-3f,
                         qPrintable(QString("%1 frame %2").arg(names[agent]).arg(f)));
                QVERIFY(glm::length(exported - CrowdFixture::truePosition(agent, f)) < 1e-3f);
            }
        }
        // Agent 42 ran 6 m north (-z) in 2 s.
        QVERIFY(std::abs(positionAt(model, "agent_42_runner", CrowdFixture::kFrames - 1).z - -4.0f) < 1e-5f);
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
        const char* names[] = {"agent_7_walker", "agent_42_runner", "agent_1000_walker"};
        for (std::size_t agent = 0; agent < 3; ++agent) {
            const int node = test::nodeNamed(model, names[agent]);
            QVERIFY(test::samplerFor(model, node, "rotation"));
            QCOMPARE(model.accessors.at(test::samplerFor(model, node, "rotation")->output).componentType,
                     TINYGLTF_COMPONENT_TYPE_SHORT);  // normalised 16-bit, as glTF allows for rotations
            for (std::size_t f : {std::size_t(0), CrowdFixture::kMiddleFrame, CrowdFixture::kFrames - 1}) {
                const std::vector<float> q = test::evaluateChannel(model, node, "rotation", float(f) / CrowdFixture::kFps);
                const glm::quat rotation(q[3], q[0], q[1], q[2]);  // w, x, y, z
                QVERIFY(std::abs(glm::length(rotation) - 1.0f) < 1e-4f);
                const glm::vec3 nose = rotation * glm::vec3(1.0f, 0.0f, 0.0f);
                QVERIFY2(glm::length(nose - CrowdFixture::trueGroundDirection(agent)) < 1e-4f,
                         qPrintable(QString("node %1 frame %2 nose (%3, %4, %5)")
                                        .arg(node).arg(f).arg(nose.x).arg(nose.y).arg(nose.z)));
            }
            // A viewer that ignores animation still shows frame 0's pose.
            QCOMPARE(model.nodes[node].rotation.size(), std::size_t(4));
            QCOMPARE(model.nodes[node].translation.size(), std::size_t(3));
        }
    }

    // The walkers wear the default man: on the ground, about 1.75 m tall; the runner its tint.
    void charactersAreHumanSizedAndTinted()
    {
        QTemporaryDir dir;
        tinygltf::Model model;
        exportAndLoad(dir, "crowd.glb", model);
        if (QTest::currentTestFailed())
            return;
        auto meshOf = [&](const std::string& body) -> const tinygltf::Mesh& {
            return model.meshes.at(model.nodes.at(test::nodeNamed(model, body)).mesh);
        };
        const tinygltf::Mesh& walker = meshOf("agent_7_walker_body");
        const tinygltf::Primitive& body = walker.primitives.at(0);
        QVERIFY(body.attributes.count("NORMAL") && body.attributes.count("JOINTS_0") && body.attributes.count("WEIGHTS_0"));
        const tinygltf::Accessor& position = model.accessors.at(body.attributes.at("POSITION"));
        QVERIFY(std::abs(position.minValues[1]) < 0.02);
        QVERIFY(model.bufferViews.at(position.bufferView).byteStride > 0);  // interleaved
        // The body's height: the top of the parts every agent wears (a hat is an accessory).
        const std::vector<float> xyz = test::accessorFloats(model, body.attributes.at("POSITION"));
        float top = 0.0f;
        for (const tinygltf::Primitive& p : walker.primitives) {
            const std::string& material = model.materials.at(p.material).name;
            if (material.rfind("hat", 0) == 0 || material.rfind("bag", 0) == 0)
                continue;
            for (std::uint32_t index : test::accessorIndices(model, p.indices))
                top = std::max(top, xyz.at(3 * std::size_t(index) + 1));
        }
        QVERIFY2(top > 1.65f && top < 1.85f, qPrintable(QString::number(top)));
        // The runner's type is tinted blue: its top wears the tint.
        bool tinted = false;
        for (const tinygltf::Primitive& p : meshOf("agent_42_runner_body").primitives) {
            const std::vector<double> colour = model.materials.at(p.material).pbrMetallicRoughness.baseColorFactor;
            tinted = tinted || (model.materials.at(p.material).name.rfind("runner_tint", 0) == 0 &&
                                std::abs(colour[2] - 0.9) < 1e-6);
        }
        QVERIFY(tinted);
    }

    // Every body has skin, a top in its tint, a bottom, hair and shoes, each in its own
    // material; hats and backpacks are worn by about the share each build gives them
    // (the child always wears its hat), and a body's hat or bag primitive is there
    // exactly when its extras say it wears one. Skin tones vary over the crowd.
    void bodiesWearSkinClothesAndAccessoriesByShare()
    {
        QTemporaryDir dir;
        const CrowdFixture fx = CrowdFixture::makeCrowd(800, 2);
        const QString path = dir.filePath("crowd.glb");
        const exporting::ExportResult result = exportTo(fx, path);
        QVERIFY2(result.ok(), result.error.c_str());
        tinygltf::Model model;
        std::string error;
        QVERIFY2(test::loadGltf(path.toStdString(), model, error), error.c_str());
        std::map<std::string, int> agents, hats, bags;
        std::set<std::string> skins;
        for (const sim::AgentInfo& info : fx.cache.agents()) {
            const std::string root = "agent_" + std::to_string(info.id) + "_walker";
            const tinygltf::Value& extras = model.nodes.at(test::nodeNamed(model, root)).extras;
            const std::string character = extras.Get("character").Get<std::string>();
            std::set<std::string> wears;
            if (extras.Has("wears"))
                for (const tinygltf::Value& w : extras.Get("wears").Get<tinygltf::Value::Array>())
                    wears.insert(w.Get<std::string>());
            std::map<std::string, int> parts;
            const tinygltf::Mesh& body = model.meshes.at(model.nodes.at(test::nodeNamed(model, root + "_body")).mesh);
            for (const tinygltf::Primitive& p : body.primitives) {
                const std::string material = model.materials.at(p.material).name;
                const std::string part =
                    material.rfind("walker_tint", 0) == 0 ? "top" : material.substr(0, material.rfind('_'));
                ++parts[part];
                if (part == "skin")
                    skins.insert(material);
            }
            const QString what = QString::fromStdString(root + " (" + character + ")");
            for (const char* always : {"skin", "top", "bottom", "shoes"})
                QVERIFY2(parts[always] == 1, qPrintable(what + " lacks " + always));
            QVERIFY2(parts["hair"] + parts["grey_hair"] == 1, qPrintable(what));
            QCOMPARE(parts["hat"], int(wears.count("hat")));
            QCOMPARE(parts["bag"], int(wears.count("bag")));
            ++agents[character];
            hats[character] += parts["hat"];
            bags[character] += parts["bag"];
        }
        for (const char* look : {"man", "woman", "tall_man", "child"})
            QVERIFY2(agents[look] > 120, look);
        QCOMPARE(hats["child"], agents["child"]);
        auto share = [](int n, int of) { return double(n) / double(of); };
        QVERIFY2(std::abs(share(hats["man"], agents["man"]) - 0.15) < 0.08, qPrintable(QString::number(hats["man"])));
        QVERIFY2(std::abs(share(bags["woman"], agents["woman"]) - 0.3) < 0.1,
                 qPrintable(QString::number(bags["woman"])));
        QVERIFY2(std::abs(share(bags["child"], agents["child"]) - 0.5) < 0.12,
                 qPrintable(QString::number(bags["child"])));
        QVERIFY(skins.size() >= 5);
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
            QCOMPARE(extras->Get("mode").Get<std::string>(), std::string("exact"));
        }
        const tinygltf::Value& agent = model.nodes.at(test::nodeNamed(model, "agent_42_runner")).extras;
        QCOMPARE(agent.Get("agentId").GetNumberAsInt(), 42);
        QCOMPARE(agent.Get("character").Get<std::string>(), std::string("man"));
        QVERIFY(agent.Get("heightScale").GetNumberAsDouble() > 0.0);
    }

    void khronosValidatorFindsNothing_data()
    {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QStringList>("written");
        QTest::addColumn<bool>("compact");
        QTest::newRow("exact glb") << "crowd.glb" << QStringList{"crowd.glb"} << false;
        QTest::newRow("exact gltf") << "crowd.gltf" << QStringList{"crowd.bin", "crowd.gltf"} << false;
        QTest::newRow("compact glb") << "crowd.glb" << QStringList{"crowd.glb"} << true;
        QTest::newRow("compact gltf") << "crowd.gltf" << QStringList{"crowd.bin", "crowd.gltf"} << true;
        QTest::newRow("gltf, name needing URI escapes") << "shot 12 (final).gltf"
                                                        << QStringList{"shot 12 (final).gltf", "shot_12__final_.bin"} << false;
    }

    // Zero errors and zero warnings from the Khronos glTF Validator, one shared input.
    void khronosValidatorFindsNothing()
    {
        QFETCH(QString, name);
        QFETCH(QStringList, written);
        QFETCH(bool, compact);
        if (!QFile::exists(test::externalReaderPath("gltf-validate")))
            QSKIP("../shared/tools/gltf-validate is not beside the repository");
        const CrowdFixture fx = CrowdFixture::make();
        QTemporaryDir dir;
        const exporting::ExportResult result =
            exportTo(fx, dir.filePath(name), {}, compact ? exporting::GltfMode::Compact : exporting::GltfMode::Exact);
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
        QCOMPARE(stats["meshes"].toInt(), 3 + 1);  // the agents' and the ground's
        QCOMPARE(stats["skins"].toInt(), 3);
        QCOMPARE(stats["distinctInverseBindMatrixAccessors"].toInt(), 1);
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
                QVERIFY2(glm::length(seen - cached) < 1e-3f, qPrintable(QString("%1 %2").arg(names[agent], key)));
            }
        }
    }

    // The same recording exports to the same bytes, in both modes, on 1 and on 2 threads.
    void sameInputSameBytes()
    {
        const CrowdFixture fx = CrowdFixture::makeCrowd(300, 24);
        QTemporaryDir dir;
        for (exporting::GltfMode mode : {exporting::GltfMode::Exact, exporting::GltfMode::Compact}) {
            QByteArray bytes[2];
            for (int t = 0; t < 2; ++t) {
                const QString path = dir.filePath(QString("crowd%1.glb").arg(t));
                QVERIFY(exportTo(fx, path, {}, mode, t + 1).ok());
                QFile file(path);
                QVERIFY(file.open(QIODevice::ReadOnly));
                bytes[t] = file.readAll();
            }
            QVERIFY(bytes[0].size() > 100000);
            QVERIFY(bytes[0] == bytes[1]);
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

        CrowdFixture missing = CrowdFixture::make();
        missing.scene.agentTypes[0].character = "no-such-character.glb";
        result = exportTo(missing, path);
        QVERIFY(!result.ok());
        QVERIFY2(result.error.find("agent type 'walker'") != std::string::npos, result.error.c_str());
        QVERIFY2(result.error.find("no-such-character.glb") != std::string::npos, result.error.c_str());
        QCOMPARE(entries(dir.path()), QStringList{});
    }
};

THRONG_REGISTER_TEST(TestGltfExporter)
#include "TestGltfExporter.moc"
