// Exports of a scene at map coordinates (issue 23, finding 5): the World runs relative to
// the scene's centre, and every file a pipeline reads is in the scene's own coordinates,
// the origin added back once, in double: the trajectory CSV, the per-agent text cache and
// the glTF (a node at the origin carrying the agents' roots). The same walk near (0, 0)
// is the reference, to a micrometre.
#include "GltfReadBack.h"
#include "TestRegistry.h"

#include "export/AgentTextCache.h"
#include "export/GltfExporter.h"
#include "export/TrajectoryCsv.h"
#include "simcore/io/SceneIO.h"
#include "simcore/world/World.h"

#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <cstdio>
#include <string>

using namespace throng;

namespace {

constexpr double kEast = 680000.0, kNorth = 5400000.0;  // a UTM-like easting and northing

// Three walkers crossing a 40 m yard towards a goal, offset by (dx, dz).
sim::Scene yard(double dx, double dz)
{
    auto p = [&](double x, double z) {
        char buf[96];
        std::snprintf(buf, sizeof buf, "[%.3f, %.3f]", dx + x, dz + z);
        return std::string(buf);
    };
    auto p3 = [&](double x, double z) {
        char buf[96];
        std::snprintf(buf, sizeof buf, "[%.3f, 0, %.3f]", dx + x, dz + z);
        return std::string(buf);
    };
    const std::string yaml = "throng: 1\nsettings: {fps: 30, bounds: {min: " + p(-20, -20) + ", max: " + p(20, 20) +
                             "}}\nagent_types:\n  - {name: walker, radius: 0.3, max_speed: 1.3}\n"
                             "goals:\n  - {name: bench, position: " + p(12, 3) + ", radius: 1}\n"
                             "agents:\n"
                             "  - {id: 1, type: walker, position: " + p3(-10, 0) + ", goal: bench}\n"
                             "  - {id: 2, type: walker, position: " + p3(-10, 4) + ", goal: bench}\n"
                             "  - {id: 3, type: walker, position: " + p3(0, -8) + ", goal: bench}\n";
    const sim::LoadResult r = sim::parseScene(yaml, "yard.yaml", ".");
    if (!r.ok())
        qFatal("%s", r.diagnostics[0].format().c_str());
    return r.scene;
}

sim::FrameCache record(const sim::Scene& scene, int frames)
{
    sim::World world(scene);
    sim::FrameCache cache;
    world.startRecording(cache);
    std::vector<sim::AgentFrame> frame;
    for (int f = 1; f < frames; ++f) {
        world.step();
        world.snapshot(frame);
        cache.append(frame);
    }
    return cache;
}

QStringList lines(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    QStringList out = QString::fromUtf8(file.readAll()).split('\n');
    if (!out.isEmpty() && out.last().isEmpty())
        out.removeLast();
    return out;
}

}  // namespace

class TestFarSceneExport : public QObject {
    Q_OBJECT
private slots:
    void csvAndTextCacheAreInTheScenesCoordinates()
    {
        const sim::FrameCache nearCache = record(yard(0, 0), 150), farCache = record(yard(kEast, kNorth), 150);
        QCOMPARE(farCache.origin(), glm::dvec3(kEast, 0.0, kNorth));
        QTemporaryDir dir;
        QVERIFY(exporting::writeTrajectoryCsv(nearCache, dir.filePath("near.csv").toStdString()).ok());
        QVERIFY(exporting::writeTrajectoryCsv(farCache, dir.filePath("far.csv").toStdString()).ok());
        const QStringList nearRows = lines(dir.filePath("near.csv")), farRows = lines(dir.filePath("far.csv"));
        QCOMPARE(farRows.size(), 1 + 3 * 150);
        QCOMPARE(farRows.size(), nearRows.size());
        double worst = 0.0, walked = 0.0;
        for (int k = 1; k < farRows.size(); ++k) {
            const QStringList a = nearRows[k].split(','), b = farRows[k].split(',');
            QCOMPARE(b[0], a[0]);
            QCOMPARE(b[1], a[1]);
            worst = std::max({worst, std::fabs(b[2].toDouble() - kEast - a[2].toDouble()),
                              std::fabs(b[3].toDouble() - a[3].toDouble()),
                              std::fabs(b[4].toDouble() - kNorth - a[4].toDouble())});
            walked = std::max(walked, std::fabs(b[2].toDouble() - kEast - (-10.0)));
            QCOMPARE(b.mid(5), a.mid(5));  // heading, speed, clip, phase: as at the origin
        }
        QVERIFY2(worst < 1e-6, qPrintable(QString::number(worst)));
        QVERIFY2(walked > 5.0, "the far walkers walk (the old code froze them)");

        QVERIFY(exporting::writeAgentTextCache(farCache, dir.filePath("cache").toStdString()).ok());
        const QStringList text = lines(dir.filePath("cache/agent_1.txt"));
        QCOMPARE(text.size(), 150);
        for (int f = 0; f < text.size(); ++f) {
            const QStringList v = text[f].split(' ');
            const sim::AgentFrame& a = nearCache.at(std::size_t(f), 0);
            QVERIFY(std::fabs(v[0].toDouble() - kEast - a.position.x) < 1e-6);
            QVERIFY(std::fabs(v[2].toDouble() - kNorth - a.position.z) < 1e-6);
        }
    }

    void gltfRootsHangFromTheSceneOrigin()
    {
        const sim::Scene nearScene = yard(0, 0), farScene = yard(kEast, kNorth);
        const sim::FrameCache nearCache = record(nearScene, 60), farCache = record(farScene, 60);
        QTemporaryDir dir;
        exporting::GltfOptions options;
        options.mode = exporting::GltfMode::Compact;
        options.path = dir.filePath("near.glb").toStdString();
        QVERIFY(exporting::exportGltf(nearScene, nearCache, options).ok());
        options.path = dir.filePath("far.glb").toStdString();
        QVERIFY(exporting::exportGltf(farScene, farCache, options).ok());
        tinygltf::Model nearModel, farModel;
        std::string error;
        QVERIFY2(test::loadGltf(dir.filePath("near.glb").toStdString(), nearModel, error), error.c_str());
        QVERIFY2(test::loadGltf(dir.filePath("far.glb").toStdString(), farModel, error), error.c_str());
        QCOMPARE(test::nodeNamed(nearModel, "scene_origin"), -1);
        const int origin = test::nodeNamed(farModel, "scene_origin");
        QVERIFY(origin >= 0);
        QCOMPARE(farModel.nodes[std::size_t(origin)].translation, (std::vector<double>{kEast, 0.0, kNorth}));
        for (const char* name : {"agent_1_walker", "agent_2_walker", "agent_3_walker"}) {
            const int nearNode = test::nodeNamed(nearModel, name), farNode = test::nodeNamed(farModel, name);
            QVERIFY(nearNode >= 0 && farNode >= 0);
            const auto& children = farModel.nodes[std::size_t(origin)].children;
            QVERIFY(std::find(children.begin(), children.end(), farNode) != children.end());
            for (float t : {0.0f, 0.9f, 1.9f})
                QCOMPARE(test::evaluateChannel(farModel, farNode, "translation", t),
                         test::evaluateChannel(nearModel, nearNode, "translation", t));
        }
    }
};

THRONG_REGISTER_TEST(TestFarSceneExport)
#include "TestFarSceneExport.moc"
