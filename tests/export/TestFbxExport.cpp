// The FBX export (issue 28), read back by two independent readers: assimp's own FBX
// importer (a different code path from the writer) and Blender's FBX importer
// (tests/tools/blender-fbx-check). Held against the trajectories CSV of the same recording:
// one skinned, animated character per agent, every root where the CSV has it on every
// frame (and scaled to nothing on the frames it is out of the shot), the shot's frame
// rate; the set with its lamps following the phase; --no-set leaves it out; bad paths fail
// with a message and leave nothing behind. (Without detail/FbxFraming's mending neither
// reader opens what Debian's assimp writes, and both drop every scale animation.)
#include "CourtFixture.h"
#include "ExternalReader.h"
#include "TestRegistry.h"

#include "export/FbxExporter.h"
#include "export/TrajectoryCsv.h"
#include "simcore/traffic/LightPhase.h"

#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

using namespace throng;

namespace {

// Vector keys at `time` (ticks): linear between neighbours, held beyond the ends.
glm::dvec3 keyAt(const aiVectorKey* keys, unsigned count, double time)
{
    auto v = [&](unsigned k) { return glm::dvec3(keys[k].mValue.x, keys[k].mValue.y, keys[k].mValue.z); };
    if (time <= keys[0].mTime)
        return v(0);
    for (unsigned k = 1; k < count; ++k)
        if (time <= keys[k].mTime)
            return v(k - 1) + (v(k) - v(k - 1)) * ((time - keys[k - 1].mTime) / (keys[k].mTime - keys[k - 1].mTime));
    return v(count - 1);
}

std::vector<const aiMesh*> meshesUnder(const aiScene* s, const aiNode* node)
{
    std::vector<const aiMesh*> meshes;
    for (unsigned m = 0; m < node->mNumMeshes; ++m)
        meshes.push_back(s->mMeshes[node->mMeshes[m]]);
    for (unsigned c = 0; c < node->mNumChildren; ++c)
        for (const aiMesh* mesh : meshesUnder(s, node->mChildren[c]))
            meshes.push_back(mesh);
    return meshes;
}

const aiNodeAnim* channelOf(const aiAnimation* a, const std::string& node)
{
    for (unsigned c = 0; c < a->mNumChannels; ++c)
        if (node == a->mChannels[c]->mNodeName.C_Str())
            return a->mChannels[c];
    return nullptr;
}

std::string exportCourt(const test::CourtShot& rec, const QTemporaryDir& dir, const QString& name, bool includeSet)
{
    exporting::FbxOptions options;
    options.path = dir.filePath(name).toStdString();
    options.lod = exporting::Lod::Far;
    options.includeSet = includeSet;
    const exporting::ExportResult result = exporting::exportFbx(rec.scene, rec.cache, options);
    if (!result.ok())
        qFatal("%s", result.error.c_str());
    return options.path;
}

}  // namespace

class TestFbxExport : public QObject {
    Q_OBJECT
private slots:
    void assimpReadsEveryAgentWhereTheCsvHasIt_data()
    {
        QTest::addColumn<double>("shift");
        QTest::newRow("at the origin") << 0.0;
        QTest::newRow("at 10^6 m") << 1.0e6;
    }
    void assimpReadsEveryAgentWhereTheCsvHasIt()
    {
        QFETCH(double, shift);
        QTemporaryDir dir;
        const test::CourtShot rec = test::recordCourt(shift);
        const std::string csv = dir.filePath("court.csv").toStdString();
        QVERIFY(exporting::writeTrajectoryCsv(rec.cache, csv).ok());
        const std::string path = exportCourt(rec, dir, "court.fbx", true);

        Assimp::Importer importer;
        const aiScene* s = importer.ReadFile(path, 0);
        QVERIFY2(s, importer.GetErrorString());
        QCOMPARE(s->mNumAnimations, 1u);
        const aiAnimation* anim = s->mAnimations[0];
        const double ticks = anim->mTicksPerSecond > 0 ? anim->mTicksPerSecond : 1.0;
        const aiNode* crowd = s->mRootNode->FindNode("Crowd");
        QVERIFY(crowd);
        const glm::dvec3 origin(crowd->mTransformation.a4, crowd->mTransformation.b4, crowd->mTransformation.c4);
        QCOMPARE(origin.x, rec.cache.origin().x);
        const auto rows = test::readTrajectoryRows(csv);
        int agents = 0, skinned = 0, gone = 0, compared = 0;
        double worst = 0.0;
        for (unsigned c = 0; c < crowd->mNumChildren; ++c) {
            const aiNode* agent = crowd->mChildren[c];
            const QString name = agent->mName.C_Str();
            if (!name.startsWith("agent_"))
                continue;
            ++agents;
            const int id = name.section('_', 1, 1).toInt();
            // The body: a mesh per part (FBX gives each a node of its own under it).
            const aiNode* body = agent->FindNode((name + "_body").toStdString().c_str());
            QVERIFY2(body, qPrintable(name));
            const std::vector<const aiMesh*> parts = meshesUnder(s, body);
            QVERIFY2(parts.size() >= 4, qPrintable(name));
            for (const aiMesh* mesh : parts)
                skinned += mesh->mNumBones > 0 ? 1 : 0;
            const aiNodeAnim* channel = channelOf(anim, agent->mName.C_Str());
            QVERIFY2(channel && channel->mNumPositionKeys > 1, qPrintable(name));
            const auto& frames = rows.at(id);
            bool left = false;
            for (std::size_t f = 0; f < rec.cache.frameCount(); ++f) {
                const double time = double(f) / 12.0 * ticks;
                const double scale = keyAt(channel->mScalingKeys, channel->mNumScalingKeys, time).x;
                const auto row = frames.find(int(f));
                if (row == frames.end()) {
                    QVERIFY2(scale < 1e-3,
                             qPrintable(QString("%1 frame %2 out, scale %3").arg(name).arg(f).arg(scale)));
                    left = true;
                    continue;
                }
                QVERIFY2(scale > 0.5, qPrintable(QString("%1 frame %2 in, scale %3").arg(name).arg(f).arg(scale)));
                const glm::dvec3 at = origin + keyAt(channel->mPositionKeys, channel->mNumPositionKeys, time);
                worst = std::max(worst, glm::length(at - row->second));
                ++compared;
            }
            gone += left ? 1 : 0;
        }
        QCOMPARE(agents, int(rec.cache.agentCount()));
        QVERIFY2(skinned >= agents * 4, qPrintable(QString("%1 skinned meshes").arg(skinned)));
        QVERIFY2(worst < 1e-3, qPrintable(QString("worst root %1 m from the CSV").arg(worst)));
        QVERIFY2(gone >= 4, qPrintable(QString("%1 agents left through the door").arg(gone)));
        // Each root faces where the CSV says on every frame it is there (FBX's Euler keys,
        // read back by assimp as quaternions about +Y).
        const auto headings = test::readTrajectoryHeadings(csv);
        double worstTurn = 0.0;
        int turns = 0;
        for (unsigned c = 0; c < crowd->mNumChildren; ++c) {
            const QString name = crowd->mChildren[c]->mName.C_Str();
            if (!name.startsWith("agent_"))
                continue;
            const aiNodeAnim* channel = channelOf(anim, crowd->mChildren[c]->mName.C_Str());
            const auto& byFrame = headings.at(name.section('_', 1, 1).toInt());
            for (unsigned k = 0; k < channel->mNumRotationKeys; ++k) {
                const aiQuaternion& q = channel->mRotationKeys[k].mValue;
                const int f = int(std::lround(channel->mRotationKeys[k].mTime / ticks * 12.0));
                const auto row = byFrame.find(f);
                if (row == byFrame.end())
                    continue;
                const double yaw = 2.0 * std::atan2(double(q.y), double(q.w));
                worstTurn = std::max(worstTurn, std::abs(std::remainder(yaw - row->second, 2.0 * 3.14159265358979)));
                ++turns;
            }
        }
        QVERIFY2(worstTurn < 2e-3, qPrintable(QString("worst heading %1 rad from the CSV").arg(worstTurn)));
        QVERIFY(turns > 700);
        QVERIFY(compared > 700);
        qInfo("assimp: %d agents, %d skinned meshes, %d agent-frames within %.2g m of the CSV, %d left the shot",
              agents, skinned, compared, worst, gone);

        // The set: its parts, and each lamp shown exactly on the frames its phase lights it.
        const aiNode* set = crowd->FindNode("set");
        QVERIFY(set);
        QVERIFY(set->FindNode("set_ground") && set->FindNode("set_walls") && set->FindNode("set_lanes"));
        const sim::TrafficLight& light = rec.scene.trafficLights[0];
        for (const auto& [colour, lamp] : {std::pair{"red", sim::LightPhase::Red},
                                           std::pair{"yellow", sim::LightPhase::Yellow},
                                           std::pair{"green", sim::LightPhase::Green}}) {
            const aiNodeAnim* channel = channelOf(anim, std::string("set_lamp_signal_") + colour);
            QVERIFY2(channel, colour);
            for (std::size_t f = 0; f < rec.cache.frameCount(); ++f) {
                const bool lit = sim::lightPhaseAt(light, double(f) / 12.0) == lamp;
                const double scale = keyAt(channel->mScalingKeys, channel->mNumScalingKeys, double(f) / 12.0 * ticks).x;
                QVERIFY2(lit ? scale > 0.999 : scale < 1e-3, qPrintable(QString("%1 frame %2").arg(colour).arg(f)));
            }
        }
    }

    void blenderImportsTheCrowd()
    {
        if (!QFile::exists(test::externalReaderPath("blender-fbx-check")))
            QFAIL("tests/tools/blender-fbx-check is missing");
        QTemporaryDir dir;
        const test::CourtShot rec = test::recordCourt(0.0);
        const std::string csv = dir.filePath("court.csv").toStdString();
        QVERIFY(exporting::writeTrajectoryCsv(rec.cache, csv).ok());
        const std::string path = exportCourt(rec, dir, "court.fbx", true);
        const QString json = dir.filePath("blender.json");
        const test::ExternalReaderRun run = test::runExternalReader(
            "blender-fbx-check", {"--frames", "0,30,60,118", "--json-out", json, QString::fromStdString(path)});
        if (run.exitCode == 2)
            QSKIP(qPrintable("Blender cannot run here: " + run.output.right(500)));
        QVERIFY2(run.started && run.exitCode == 0, qPrintable(run.output.right(3000)));
        QFile file(json);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QJsonObject b = QJsonDocument::fromJson(file.readAll()).object();
        const int agents = int(rec.cache.agentCount());
        QCOMPARE(b["agents"].toInt(), agents);
        QCOMPARE(b["armatures"].toInt(), agents);
        QVERIFY(b["skinnedMeshes"].toInt() >= 4 * agents);
        QCOMPARE(b["fps"].toDouble(), 12.0);
        QVERIFY(b["set"].toBool());
        QCOMPARE(b["lamps"].toInt(), 3);
        const auto rows = test::readTrajectoryRows(csv);
        const QJsonObject places = b["places"].toObject();
        int compared = 0, hidden = 0;
        double worst = 0.0;
        for (auto it = places.begin(); it != places.end(); ++it) {
            const int id = it.key().section('_', 1, 1).toInt();
            const QJsonObject byFrame = it.value().toObject();
            for (auto f = byFrame.begin(); f != byFrame.end(); ++f) {
                const QJsonArray p = f.value().toArray();
                const QString where = it.key() + " frame " + f.key();
                QCOMPARE(p.size(), 7);
                const double scale = p[3].toDouble();
                const auto row = rows.at(id).find(f.key().toInt());
                if (row == rows.at(id).end()) {  // out of the shot: scaled to nothing
                    QVERIFY2(scale < 1e-3, qPrintable(where + QString(": scale %1").arg(scale)));
                    ++hidden;
                    continue;
                }
                QVERIFY2(scale > 0.5, qPrintable(where + QString(": scale %1").arg(scale)));
                const glm::dvec3 root(p[0].toDouble(), p[1].toDouble(), p[2].toDouble());
                worst = std::max(worst, glm::length(root - row->second));
                // The skinned body stands on its root: its middle above the root, at hip height.
                const glm::dvec3 body(p[4].toDouble(), p[5].toDouble(), p[6].toDouble());
                const double apart = glm::length(glm::dvec2(body.x - root.x, body.z - root.z));
                QVERIFY2(apart < 0.3 && body.y > 0.5 && body.y < 1.4,
                         qPrintable(where + QString(": body's middle %1 m off the root, %2 m up")
                                                .arg(apart)
                                                .arg(body.y)));
                ++compared;
            }
        }
        QVERIFY(compared >= 2 * agents);
        QVERIFY2(hidden >= 4, qPrintable(QString("%1 agent-frames out of the shot").arg(hidden)));
        QVERIFY2(worst < 1e-3, qPrintable(QString("worst root %1 m from the CSV").arg(worst)));
        qInfo("Blender: %d agents, %d skinned meshes, %d places within %.2g m of the CSV, %d out of the shot", agents,
              b["skinnedMeshes"].toInt(), compared, worst, hidden);
    }

    void withoutTheSetOnlyTheCrowd()
    {
        QTemporaryDir dir;
        const test::CourtShot rec = test::recordCourt(0.0);
        const std::string path = exportCourt(rec, dir, "bare.fbx", false);
        Assimp::Importer importer;
        const aiScene* s = importer.ReadFile(path, 0);
        QVERIFY2(s, importer.GetErrorString());
        QVERIFY(!s->mRootNode->FindNode("set"));
        QVERIFY(s->mRootNode->FindNode("agent_1_walker"));
    }

    void badPathsFailWithAMessageAndLeaveNothing()
    {
        QTemporaryDir dir;
        const test::CourtShot rec = test::recordCourt(0.0);
        exporting::FbxOptions options;
        options.path = dir.filePath("crowd.obj").toStdString();
        exporting::ExportResult r = exporting::exportFbx(rec.scene, rec.cache, options);
        QVERIFY(!r.ok());
        QVERIFY2(r.error.find("crowd.obj") != std::string::npos && r.error.find(".fbx") != std::string::npos,
                 r.error.c_str());
        options.path = dir.filePath("no/such/dir/crowd.fbx").toStdString();
        r = exporting::exportFbx(rec.scene, rec.cache, options);
        QVERIFY(!r.ok());
        QVERIFY2(r.error.find("crowd.fbx") != std::string::npos, r.error.c_str());
        QCOMPARE(QDir(dir.path()).entryList(QDir::NoDotAndDotDot | QDir::AllEntries).size(), 0);
    }
};

THRONG_REGISTER_TEST(TestFbxExport)
#include "TestFbxExport.moc"
