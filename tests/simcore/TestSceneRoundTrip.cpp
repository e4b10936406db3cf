// Save then load gives the same scene: demo scenes, the documented examples and random
// scenes using every key. Saving is atomic.
#include "RandomScene.h"
#include "TestRegistry.h"

#include "simcore/io/SceneIO.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

using namespace throng::sim;

class TestSceneRoundTrip : public QObject {
    Q_OBJECT

    static void checkRoundTrip(const Scene& scene, const QString& dirPath)
    {
        const std::string path = QDir(dirPath).filePath("saved.yaml").toStdString();
        const SaveResult saved = saveScene(scene, path);
        QVERIFY2(saved.ok, saved.error.c_str());
        const LoadResult again = loadScene(path);
        QVERIFY2(again.diagnostics.empty(), again.diagnostics.empty() ? "" : again.diagnostics[0].format().c_str());
        QVERIFY(again.scene == scene);
        // And saving the reloaded scene gives the same text: the format is stable.
        QCOMPARE(sceneToYaml(again.scene), sceneToYaml(scene));
    }

private slots:
    void sceneFile_data()
    {
        QTest::addColumn<QString>("path");
        const QStringList dirs{QStringLiteral(THRONG_SOURCE_DIR "/resources/scenes"),
                               QStringLiteral(THRONG_TEST_DATA_DIR "/scenes")};
        int count = 0;
        for (const QString& d : dirs)
            for (const QString& f : QDir(d).entryList({"*.yaml"}, QDir::Files))
                if (!f.endsWith(".brain.yaml")) {
                    QTest::newRow(qPrintable(f)) << QDir(d).filePath(f);
                    ++count;
                }
        QVERIFY(count >= 1);
    }

    // Every shipped and documented scene loads without a warning and round-trips.
    void sceneFile()
    {
        QFETCH(QString, path);
        const LoadResult loaded = loadScene(path.toStdString());
        QVERIFY2(loaded.diagnostics.empty(), loaded.diagnostics.empty() ? "" : loaded.diagnostics[0].format().c_str());
        // Saved one folder down: a demo's "../brains/" then stays inside the temporary folder.
        QTemporaryDir top;
        QVERIFY(QDir(top.path()).mkpath("scenes"));
        const QDir dir(top.filePath("scenes"));
        // Referenced files (brains, keyframes) live beside the scene: copy them along.
        for (const QString& f : QDir(QFileInfo(path).path()).entryList(QDir::Files))
            if (!f.endsWith(".yaml") || f.endsWith(".brain.yaml"))
                QFile::copy(QFileInfo(path).dir().filePath(f), dir.filePath(f));
        checkRoundTrip(loaded.scene, dir.path());
    }

    void randomScene_data()
    {
        QTest::addColumn<int>("seed");
        QTest::addColumn<int>("agents");
        for (int seed = 1; seed <= 6; ++seed)
            QTest::newRow(qPrintable(QString("seed %1").arg(seed))) << seed << (seed % 2 ? 5 : 300);
    }

    // Random scenes with every key, awkward floats, quoted text, the list and table forms.
    void randomScene()
    {
        QFETCH(int, seed);
        QFETCH(int, agents);
        const Scene scene = throng::test::makeRandomScene(std::uint32_t(seed), std::uint32_t(agents));
        QTemporaryDir dir;
        checkRoundTrip(scene, dir.path());
        const std::string text = sceneToYaml(scene);
        QCOMPARE(text.find("columns:") != std::string::npos, agents >= 64);
        QVERIFY(text.find("shape: polygon") != std::string::npos);
    }

    void brainFileIsWrittenBesideTheScene()
    {
        Scene scene = throng::test::makeRandomScene(9, 3);
        scene.brains[0].file = "brains/walker.brain.yaml";
        QTemporaryDir dir;
        QVERIFY(QDir(dir.path()).mkpath("brains"));
        checkRoundTrip(scene, dir.path());
        QVERIFY(QFile::exists(dir.filePath("brains/walker.brain.yaml")));
        QFile sceneFile(dir.filePath("saved.yaml"));
        QVERIFY(sceneFile.open(QIODevice::ReadOnly));
        const QByteArray text = sceneFile.readAll();
        QVERIFY(text.contains("file: brains/walker.brain.yaml"));
        QVERIFY(!text.contains("fuzz.triangle"));  // the graph itself lives in the brain file
    }

    // Save As into an empty folder: brain and keyframe files come along.
    void saveAsElsewhereKeepsReferencedFiles()
    {
        const QString source = QStringLiteral(THRONG_TEST_DATA_DIR "/scenes/brain-file.yaml");
        const LoadResult loaded = loadScene(source.toStdString());
        QVERIFY(loaded.ok());
        QVERIFY(!loaded.scene.heroes.empty() && !loaded.scene.heroes[0].keyframesFile.empty());
        QTemporaryDir dir;
        const std::string path = dir.filePath("copy.yaml").toStdString();
        QVERIFY(saveScene(loaded.scene, path).ok);
        const LoadResult again = loadScene(path);
        QVERIFY2(again.ok(), again.diagnostics.empty() ? "" : again.diagnostics[0].format().c_str());
        QVERIFY(again.scene == loaded.scene);
    }

    // A shipped demo refers to "../brains/": saved into a fresh folder, that folder's
    // sibling is made, and the copy loads.
    void saveMakesTheFoldersOfReferencedFiles()
    {
        const QString source = QStringLiteral(THRONG_SOURCE_DIR "/resources/scenes/crossroads.yaml");
        const LoadResult loaded = loadScene(source.toStdString());
        QVERIFY(loaded.ok());
        QTemporaryDir dir;
        QVERIFY(QDir(dir.path()).mkpath("shots"));
        const std::string path = dir.filePath("shots/crossroads.yaml").toStdString();
        const SaveResult saved = saveScene(loaded.scene, path);
        QVERIFY2(saved.ok, saved.error.c_str());
        QVERIFY(QFile::exists(dir.filePath("brains/pedestrian.brain.yaml")));
        QVERIFY(QFile::exists(dir.filePath("brains/car.brain.yaml")));
        const LoadResult again = loadScene(path);
        QVERIFY2(again.ok(), again.diagnostics.empty() ? "" : again.diagnostics[0].format().c_str());
        QVERIFY(again.scene == loaded.scene);
    }

    void saveLeavesNoTemporaryFile()
    {
        QTemporaryDir dir;
        const Scene scene = throng::test::makeRandomScene(4, 10);
        QVERIFY(saveScene(scene, dir.filePath("a.yaml").toStdString()).ok);
        QVERIFY(saveScene(scene, dir.filePath("a.yaml").toStdString()).ok);  // overwrite
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{"a.yaml"});
    }

    void failedSaveKeepsWhatWasThere()
    {
        QTemporaryDir dir;
        // The target is a directory with a file in it: the rename must fail, and neither
        // the directory's content nor a temporary file may be left changed behind.
        QVERIFY(QDir(dir.path()).mkpath("scene.yaml"));
        QFile keep(dir.filePath("scene.yaml/keep.txt"));
        QVERIFY(keep.open(QIODevice::WriteOnly));
        keep.write("precious");
        keep.close();
        const SaveResult r = saveScene(throng::test::makeRandomScene(2, 2), dir.filePath("scene.yaml").toStdString());
        QVERIFY(!r.ok);
        QVERIFY(r.error.find("scene.yaml") != std::string::npos);
        QVERIFY(QFile::exists(dir.filePath("scene.yaml/keep.txt")));
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{});

        const SaveResult noDir = saveScene(Scene{}, dir.filePath("missing/dir/scene.yaml").toStdString());
        QVERIFY(!noDir.ok);
        QVERIFY(noDir.error.find("missing/dir") != std::string::npos);
    }

    // A wall stands 2.5 m high unless height says otherwise; only other heights are written.
    void wallHeightRoundTrips()
    {
        const LoadResult r = parseScene("throng: 1\nwalls:\n  - {points: [[0, 0], [5, 0]], height: 3.75}\n"
                                        "  - {points: [[0, 2], [5, 2]]}\n",
                                        "walls.yaml", "");
        QVERIFY2(r.ok(), r.diagnostics.empty() ? "" : r.diagnostics[0].format().c_str());
        QCOMPARE(r.scene.walls[0].heightM, 3.75f);
        QCOMPARE(r.scene.walls[1].heightM, 2.5f);
        const std::string text = sceneToYaml(r.scene);
        QVERIFY2(text.find("height: 3.75") != std::string::npos, text.c_str());
        QCOMPARE(text.find("height:"), text.rfind("height:"));  // the default one is left out
        Scene changed = r.scene;
        changed.walls[1].heightM = 0.4f;
        QTemporaryDir dir;
        checkRoundTrip(changed, dir.path());
    }

    void defaultsApplyWhenKeysAreOmitted()
    {
        const LoadResult r = parseScene("throng: 1\nagent_types:\n  - {name: w}\n  - {name: car, kind: vehicle}\n"
                                        "agents:\n  - {type: w, position: [1, 2]}\n  - {type: w, position: [3, 4, 5]}\n",
                                        "defaults.yaml", "");
        QVERIFY(r.ok());
        QCOMPARE(r.scene.settings.fps, 24.0f);
        QCOMPARE(r.scene.agentTypes[0].radiusM, 0.3f);
        QCOMPARE(r.scene.agentTypes[1].mass, 1200.0f);  // vehicles get car-sized defaults
        QCOMPARE(r.scene.agents[0].position, glm::vec3(1, 0, 2));  // [x, z] stands on the ground
        QCOMPARE(r.scene.agents[1].position, glm::vec3(3, 4, 5));
        QCOMPARE(r.scene.agents[0].id, 1u);  // ids are assigned when omitted
        QCOMPARE(r.scene.agents[1].id, 2u);
    }

    void idsNotGivenFollowTheHighestGiven()
    {
        // Placed agents, then vehicles, then heroes take the ids after the highest given
        // anywhere (a vehicle's 40 here), in file order; a leader may be any of them.
        const LoadResult r = parseScene("throng: 1\nagent_types:\n  - {name: w}\n  - {name: car, kind: vehicle}\n"
                                        "lanes:\n  - {name: main, points: [[0, 0], [50, 0]]}\n"
                                        "agents:\n  - {id: 7, type: w, position: [0, 0]}\n"
                                        "  - {type: w, position: [1, 0], leader: 40}\n"
                                        "  - {type: w, position: [2, 0]}\n"
                                        "vehicles:\n  - {type: car, lane: main}\n  - {id: 40, type: car, lane: main}\n"
                                        "heroes:\n  - {name: h, type: w, keyframes: [{time: 0, position: [0, 5]}]}\n",
                                        "ids.yaml", "");
        QVERIFY2(r.ok(), r.diagnostics.empty() ? "" : r.diagnostics.front().format().c_str());
        QCOMPARE(r.scene.agents[0].id, 7u);
        QCOMPARE(r.scene.agents[1].id, 41u);
        QCOMPARE(r.scene.agents[2].id, 42u);
        QCOMPARE(r.scene.vehicles[0].id, 43u);
        QCOMPARE(r.scene.vehicles[1].id, 40u);
        QCOMPARE(r.scene.heroes[0].id, 44u);
        QCOMPARE(r.scene.agents[1].leader, 40u);
    }
};

THRONG_REGISTER_TEST(TestSceneRoundTrip)
#include "TestSceneRoundTrip.moc"
