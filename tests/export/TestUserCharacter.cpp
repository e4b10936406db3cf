// A user's own rigged glTF character loads in place of a built-in: its skeleton, mesh and
// walk cycle come through (turned from glTF's +Z forward to Throng's +X), a crowd wearing
// it exports cleanly, and files without a skin or without clips are refused clearly.
#include "CharacterFile.h"
#include "CrowdFixture.h"
#include "ExternalReader.h"
#include "TestRegistry.h"

#include "export/GltfExporter.h"
#include "export/character/BuiltinCharacters.h"
#include "export/character/UserCharacter.h"
#include "simcore/io/SceneIO.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <glm/mat4x4.hpp>

using namespace throng;
using namespace throng::exporting;

namespace {

std::optional<Character> writeAndLoad(const QTemporaryDir& dir, const char* name, const test::CharacterFileSpec& spec,
                                      std::string& error, const ClipNames& clips = {})
{
    const std::string path = dir.filePath(name).toStdString();
    if (!test::writeCharacterFile(*makeBuiltinCharacter("man"), spec, path, error))
        return std::nullopt;
    return loadCharacterFile(path, clips, error);
}

glm::vec3 jointAt(const Character& c, const Pose& p, std::size_t j) { return glm::vec3(jointGlobalTransforms(c, p)[j][3]); }

}  // namespace

class TestUserCharacter : public QObject {
    Q_OBJECT

private slots:
    // The man, written as a DCC would and loaded back, walks as Throng's own man does.
    void loadsARiggedCharacter()
    {
        QTemporaryDir dir;
        std::string error;
        const std::optional<Character> loaded = writeAndLoad(dir, "hero.glb", {}, error);
        QVERIFY2(loaded, error.c_str());
        const Character man = *makeBuiltinCharacter("man");
        QCOMPARE(loaded->joints.size(), man.joints.size());
        QCOMPARE(loaded->joints[kFootL].name, std::string("foot_l"));
        QCOMPARE(loaded->mesh.positions.size(), man.mesh.positions.size());
        QCOMPARE(checkCharacter(*loaded), std::string());
        QCOMPARE(loaded->walk.samples.size(), std::size_t(30));  // a 1 s clip sampled at 30 per second
        QCOMPARE(loaded->idle.samples.size(), std::size_t(1));
        // No root motion in the clip: the stride is 0.8 x the character's height (its
        // mesh's, the man's hat and backpack included: the file has them).
        float lowY = 1e9f, highY = -1e9f;
        for (const glm::vec3& p : man.mesh.positions) {
            lowY = std::min(lowY, p.y);
            highY = std::max(highY, p.y);
        }
        QVERIFY(highY - lowY > 1.7f);
        QVERIFY2(std::abs(loaded->walk.strideM - 0.8f * (highY - lowY)) < 0.02f,
                 qPrintable(QString::number(loaded->walk.strideM)));
        // Feet and hands where the built-in puts them, facing +X again, through the cycle.
        for (int k = 0; k < 30; k += 7) {
            const double phase = k / 30.0;
            for (std::size_t j : {std::size_t(kFootL), std::size_t(kFootR), std::size_t(kHandL), std::size_t(kHead)}) {
                const glm::vec3 a = jointAt(*loaded, sampleClip(loaded->walk, phase), j);
                const glm::vec3 b = jointAt(man, sampleClip(man.walk, phase), j);
                QVERIFY2(glm::length(a - b) < 2e-3f, qPrintable(QString("joint %1 phase %2: off by %3 m")
                                                                     .arg(j).arg(phase).arg(glm::length(a - b))));
            }
        }
    }

    // Clips named otherwise are mapped by name; without run, the walk serves.
    void mapsClipsByName()
    {
        QTemporaryDir dir;
        std::string error;
        test::CharacterFileSpec spec;
        spec.clips = {"Stand", "Walk_Slow", "Walk", "Sprint"};
        std::optional<Character> c = writeAndLoad(dir, "named.gltf", spec, error);
        QVERIFY2(c, error.c_str());
        QCOMPARE(c->run.samples.size(), c->walk.samples.size());  // no clip called *run*: walk serves
        ClipNames names;
        names.run = "Sprint";
        names.walk = "Walk_Slow";
        c = writeAndLoad(dir, "named2.gltf", spec, error, names);
        QVERIFY2(c, error.c_str());
        names.walk = "Jog";
        c = writeAndLoad(dir, "named3.gltf", spec, error, names);
        QVERIFY(!c);
        QVERIFY2(error.find("no walk clip named 'Jog'") != std::string::npos, error.c_str());
        QVERIFY2(error.find("'Sprint'") != std::string::npos, error.c_str());  // lists what there is
    }

    // A file's clip mapped to an action plays it: `clips: {wave: Hello}` loads the clip as
    // the wave (the hand goes above the head), over walking on the arms and head but not
    // the legs or hips; a clip the file lacks is refused by name; an unknown action is a
    // warning at its line; the mapping survives a save and a load.
    void mapsClipsToActions()
    {
        QTemporaryDir dir;
        std::string error;
        test::CharacterFileSpec spec;
        spec.clips = {"Idle", "Walk", "Wave"};
        QVERIFY2(test::writeCharacterFile(*makeBuiltinCharacter("man"), spec, dir.filePath("hero.glb").toStdString(),
                                          error),
                 error.c_str());
        const std::string yaml = "throng: 1\n"
                                 "agent_types:\n"
                                 "  - name: hero\n"
                                 "    character: hero.glb\n"
                                 "    clips: {walk: Walk, wave: Wave, cheer: Wave}\n"
                                 "agents:\n"
                                 "  - {id: 1, type: hero, position: [0, 0, 0]}\n";
        const sim::LoadResult loaded = sim::parseScene(yaml, "scene.yaml", dir.path().toStdString());
        QVERIFY2(loaded.ok(), loaded.ok() ? "" : loaded.diagnostics[0].format().c_str());
        const sim::CharacterClips& clips = loaded.scene.agentTypes.at(0).clips;
        using Mapping = std::vector<std::pair<std::string, std::string>>;
        QVERIFY(clips.actions == (Mapping{{"wave", "Wave"}, {"cheer", "Wave"}}));
        const sim::LoadResult again =
            sim::parseScene(sim::sceneToYaml(loaded.scene), "scene.yaml", dir.path().toStdString());
        QVERIFY(again.ok());
        QCOMPARE(again.scene.agentTypes.at(0).clips, clips);

        ClipNames names;
        names.actions = clips.actions;
        const std::optional<Character> c =
            loadCharacterFile(dir.filePath("hero.glb").toStdString(), names, error);
        QVERIFY2(c, error.c_str());
        QCOMPARE(checkCharacter(*c), std::string());
        const int wave = c->actionIndex("wave");
        QVERIFY(wave >= 0 && c->actionIndex("cheer") >= 0 && c->actionIndex("talk") < 0);
        const ActionClip& a = c->actions[std::size_t(wave)];
        auto jointNamed = [&](const std::string& name) {
            for (std::size_t j = 0; j < c->joints.size(); ++j)
                if (c->joints[j].name == name)
                    return j;
            return c->joints.size();
        };
        const std::size_t hand = jointNamed("hand_r"), head = jointNamed("head"), shin = jointNamed("lower_leg_l"),
                          hips = jointNamed("hips"), chest = jointNamed("chest");
        QVERIFY(hand < c->joints.size() && head < c->joints.size() && shin < c->joints.size());
        // The hand above the head all through the wave.
        for (double phase : {0.0, 0.25, 0.5, 0.75}) {
            const std::vector<glm::mat4> at = jointGlobalTransforms(*c, sampleClip(a.clip, phase));
            QVERIFY2(at[hand][3].y > at[head][3].y, qPrintable(QString("%1: hand %2, head %3")
                                                                   .arg(phase)
                                                                   .arg(at[hand][3].y)
                                                                   .arg(at[head][3].y)));
        }
        QCOMPARE(int(a.layered[hand]), 1);
        QCOMPARE(int(a.layered[chest]), 1);
        QCOMPARE(int(a.layered[shin]), 0);
        QCOMPARE(int(a.layered[hips]), 0);
        QCOMPARE(int(a.layered[0]), 0);

        names.actions = {{"talk", "Chatter"}};
        QVERIFY(!loadCharacterFile(dir.filePath("hero.glb").toStdString(), names, error));
        QVERIFY2(error.find("no clip named 'Chatter' for the action 'talk'") != std::string::npos, error.c_str());
        QVERIFY2(error.find("'Wave'") != std::string::npos, error.c_str());  // lists what there is

        // Every action of Clip.h is a key the reader knows (no warning), in the file's order.
        std::string all = yaml, keys;
        Mapping every;
        for (int k = int(sim::Clip::Wait); k < sim::kClipCount; ++k) {
            const std::string action = sim::toString(sim::Clip(k));
            keys += ", " + action + ": Wave";
            every.emplace_back(action, "Wave");
        }
        all.replace(all.find(", wave: Wave, cheer: Wave"), 25, keys);
        const sim::LoadResult allLoaded = sim::parseScene(all, "scene.yaml", dir.path().toStdString());
        QVERIFY2(allLoaded.ok() && allLoaded.diagnostics.empty(),
                 allLoaded.diagnostics.empty() ? "" : allLoaded.diagnostics[0].format().c_str());
        QVERIFY(allLoaded.scene.agentTypes.at(0).clips.actions == every);

        std::string bad = yaml;
        bad.replace(bad.find("cheer: Wave"), 11, "dance: Wave");
        const sim::LoadResult warned = sim::parseScene(bad, "scene.yaml", dir.path().toStdString());
        QVERIFY(warned.ok() && !warned.diagnostics.empty());
        const std::string message = warned.diagnostics[0].format();
        QVERIFY2(message.find("scene.yaml:5:") != std::string::npos &&
                     message.find("unknown key 'dance' is ignored") != std::string::npos,
                 message.c_str());
        QVERIFY(warned.scene.agentTypes.at(0).clips.actions == (Mapping{{"wave", "Wave"}}));
    }

    // The scene file names the clips: `clips: {walk: ..., run: ...}` under the agent type
    // reaches the loader, and survives a save and a load.
    void sceneNamesTheClips()
    {
        QTemporaryDir dir;
        std::string error;
        test::CharacterFileSpec spec;
        spec.clips = {"Loiter", "Amble", "Dash"};
        QVERIFY2(test::writeCharacterFile(*makeBuiltinCharacter("man"), spec, dir.filePath("hero.glb").toStdString(), error),
                 error.c_str());
        const std::string yaml = "throng: 1\n"
                                 "agent_types:\n"
                                 "  - name: hero\n"
                                 "    character: hero.glb\n"
                                 "    clips: {idle: Loiter, walk: Amble, run: Dash}\n"
                                 "agents:\n"
                                 "  - {id: 1, type: hero, position: [0, 0, 0]}\n";
        const sim::LoadResult loaded = sim::parseScene(yaml, "scene.yaml", dir.path().toStdString());
        QVERIFY(loaded.ok());
        const sim::CharacterClips& clips = loaded.scene.agentTypes.at(0).clips;
        QCOMPARE(clips.walk, std::string("Amble"));
        QCOMPARE(clips.run, std::string("Dash"));
        const sim::LoadResult again = sim::parseScene(sim::sceneToYaml(loaded.scene), "scene.yaml", dir.path().toStdString());
        QVERIFY(again.ok());
        QCOMPARE(again.scene.agentTypes.at(0).clips, clips);

        test::CrowdFixture fx = test::CrowdFixture::make();
        fx.scene.agentTypes[0].character = "hero.glb";
        GltfOptions options;
        options.path = dir.filePath("crowd.glb").toStdString();
        options.sceneDirectory = dir.path().toStdString();
        QVERIFY(!exportGltf(fx.scene, fx.cache, options).ok());  // no clip is called walk
        fx.scene.agentTypes[0].clips = clips;
        const ExportResult result = exportGltf(fx.scene, fx.cache, options);
        QVERIFY2(result.ok(), result.error.c_str());
    }

    void refusesBadFiles_data()
    {
        QTest::addColumn<bool>("skin");
        QTest::addColumn<QStringList>("clips");
        QTest::addColumn<QString>("message");
        QTest::newRow("no skin") << false << QStringList{"Walk"} << "has no skin";
        QTest::newRow("no clips") << true << QStringList{} << "has no animation clips";
        QTest::newRow("no walk") << true << QStringList{"Dance"} << "no walk clip (no clip name contains 'walk'); its clips are 'Dance'";
    }

    void refusesBadFiles()
    {
        QFETCH(bool, skin);
        QFETCH(QStringList, clips);
        QFETCH(QString, message);
        QTemporaryDir dir;
        test::CharacterFileSpec spec;
        spec.skin = skin;
        spec.clips.clear();
        for (const QString& c : clips)
            spec.clips.push_back(c.toStdString());
        std::string error;
        QVERIFY(!writeAndLoad(dir, "bad.glb", spec, error));
        QVERIFY2(error.find(message.toStdString()) != std::string::npos, error.c_str());
        QVERIFY2(error.find(dir.filePath("bad.glb").toStdString()) != std::string::npos, error.c_str());
    }

    void refusesWhatIsNotGltf()
    {
        QTemporaryDir dir;
        QFile junk(dir.filePath("junk.glb"));
        QVERIFY(junk.open(QIODevice::WriteOnly));
        junk.write("this is not a character\n");
        junk.close();
        std::string error;
        QVERIFY(!loadCharacterFile(dir.filePath("junk.glb").toStdString(), {}, error));
        QVERIFY2(error.find("cannot load character file '" + dir.filePath("junk.glb").toStdString() + "'") != std::string::npos,
                 error.c_str());
        QVERIFY(!loadCharacterFile(dir.filePath("missing.gltf").toStdString(), {}, error));
        QVERIFY2(error.find("missing.gltf") != std::string::npos, error.c_str());
    }

    // A character a DCC tool exported (Blender, from Debian's minetest-data: 6 bones, clips
    // Stand, Walk, Mine, ...) loads with Walk as walk, Stand as idle, and exports cleanly.
    void loadsTheSharedSampleCharacter()
    {
        if (!QFile::exists(test::externalReaderPath("make-sample-character-glb")))
            QSKIP("../shared/tools/make-sample-character-glb is not beside the repository");
        QTemporaryDir dir;
        const QString file = dir.filePath("sample.glb");
        const test::ExternalReaderRun made = test::runExternalReader("make-sample-character-glb", {file});
        if (made.exitCode == 2 || !QFile::exists(file))
            QSKIP(qPrintable("no sample character on this machine: " + made.output.right(300)));
        std::string error;
        const std::optional<Character> c = loadCharacterFile(file.toStdString(), {}, error);
        QVERIFY2(c, error.c_str());
        QCOMPARE(c->joints.size(), std::size_t(6));
        QCOMPARE(c->joints[0].name, std::string("Body"));
        QVERIFY(c->walk.samples.size() >= 8);
        QCOMPARE(c->idle.samples.size(), std::size_t(1));
        QCOMPARE(checkCharacter(*c), std::string());
        test::CrowdFixture fx = test::CrowdFixture::make();
        fx.scene.agentTypes[0].character = "sample.glb";
        GltfOptions options;
        options.path = dir.filePath("crowd.glb").toStdString();
        options.sceneDirectory = dir.path().toStdString();
        const ExportResult result = exportGltf(fx.scene, fx.cache, options);
        QVERIFY2(result.ok(), result.error.c_str());
        if (QFile::exists(test::externalReaderPath("gltf-validate"))) {
            const test::ExternalReaderRun run = test::runExternalReader("gltf-validate", {dir.filePath("crowd.glb")});
            QVERIFY2(run.exitCode == 0 && run.summary["warnings"].toInt(-1) == 0, qPrintable(run.output));
        }
    }

    // A crowd wearing the file, found relative to the scene's folder, exports in both
    // modes and the Khronos validator finds nothing.
    void crowdWearsIt()
    {
        QTemporaryDir dir;
        std::string error;
        QVERIFY2(test::writeCharacterFile(*makeBuiltinCharacter("woman"), {}, dir.filePath("hero.glb").toStdString(), error),
                 error.c_str());
        test::CrowdFixture fx = test::CrowdFixture::make();
        fx.scene.agentTypes[0].character = "hero.glb";
        for (GltfMode mode : {GltfMode::Exact, GltfMode::Compact}) {
            GltfOptions options;
            options.path = dir.filePath(mode == GltfMode::Exact ? "exact.glb" : "compact.glb").toStdString();
            options.sceneDirectory = dir.path().toStdString();
            options.mode = mode;
            const ExportResult result = exportGltf(fx.scene, fx.cache, options);
            QVERIFY2(result.ok(), result.error.c_str());
            if (!QFile::exists(test::externalReaderPath("gltf-validate")))
                continue;
            const test::ExternalReaderRun run = test::runExternalReader("gltf-validate", {QString::fromStdString(options.path)});
            QVERIFY2(run.exitCode == 0 && run.summary["warnings"].toInt(-1) == 0, qPrintable(run.output));
        }
    }
};

THRONG_REGISTER_TEST(TestUserCharacter)
#include "TestUserCharacter.moc"
