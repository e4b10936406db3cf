// The table of export formats that the CLI and the editor offer: suffixes name one format
// each, a path finds its format, and every row's writer writes what that format's reader
// accepts, or, cancelled, nothing at all; and the skinned-crowd writers (glTF, USD, FBX)
// refuse bad key tolerances before they start.
#include "CrowdFixture.h"
#include "GltfReadBack.h"
#include "TestRegistry.h"

#include "export/ExportFormats.h"
#include "export/FbxExporter.h"
#include "export/GltfExporter.h"
#include "export/UsdExporter.h"

#include <QDir>
#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <assimp/Importer.hpp>
#include <assimp/scene.h>

#include <cmath>
#include <functional>
#include <limits>
#include <set>

using namespace throng;
using throng::test::CrowdFixture;

namespace {

QStringList entries(const QString& dir)
{
    QStringList names = QDir(dir).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot);
    names.sort();
    return names;
}

QStringList readLines(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    return QString::fromUtf8(file.readAll()).split('\n', Qt::SkipEmptyParts);
}

// Where a row writes in `dir`: a file with its first suffix, or a directory as the CLI names it.
QString targetIn(const QTemporaryDir& dir, const exporting::ExportFormat& format)
{
    return format.writesDirectory ? dir.filePath("out") + '/'
                                  : dir.filePath("out" + QString::fromStdString(format.suffixes.front()));
}

}  // namespace

class TestExportFormats : public QObject {
    Q_OBJECT
private slots:
    void rowsAreCompleteAndSuffixesUnique()
    {
        std::set<std::string> keys, suffixes;
        int directories = 0;
        for (const exporting::ExportFormat& f : exporting::exportFormats()) {
            QVERIFY2(keys.insert(f.key).second, f.key.c_str());
            QVERIFY2(!f.label.empty() && f.write, f.key.c_str());
            QVERIFY2(f.writesDirectory == f.suffixes.empty(), f.key.c_str());
            directories += f.writesDirectory;
            for (const std::string& s : f.suffixes) {
                QVERIFY2(s.size() > 1 && s[0] == '.', s.c_str());
                QVERIFY2(QString::fromStdString(s) == QString::fromStdString(s).toLower(), s.c_str());
                QVERIFY2(suffixes.insert(s).second, ("suffix in two rows: " + s).c_str());
            }
            QCOMPARE(exporting::formatByKey(f.key), &f);
        }
        // A trailing '/' names the first directory format (the text cache); the Maya cache,
        // a second one, is chosen by its key.
        QCOMPARE(directories, 2);
        QCOMPARE(exporting::formatForPath("x/"), exporting::formatByKey("text-cache"));
    }

    void formatForPathGoesBySuffix()
    {
        const exporting::ExportFormat* gltf = exporting::formatByKey("gltf");
        const exporting::ExportFormat* csv = exporting::formatByKey("csv");
        const exporting::ExportFormat* cache = exporting::formatByKey("text-cache");
        QVERIFY(gltf && csv && cache);
        QCOMPARE(exporting::formatForPath("shot.glb"), gltf);
        QCOMPARE(exporting::formatForPath("out/shot.gltf"), gltf);
        QCOMPARE(exporting::formatForPath("SHOT.GLB"), gltf);
        QCOMPARE(exporting::formatForPath("/tmp/run.1.csv"), csv);
        QCOMPARE(exporting::formatForPath("caches/shot1/"), cache);
        QCOMPARE(exporting::formatForPath("out.xyz"), nullptr);
        QCOMPARE(exporting::formatForPath("out"), nullptr);
        QCOMPARE(exporting::formatForPath(""), nullptr);
        QCOMPARE(exporting::formatByKey("abc"), nullptr);
        QCOMPARE(exporting::formatForPath("crowd.FBX"), exporting::formatByKey("fbx"));
        QCOMPARE(exporting::formatForPath("walkers.TXT"), exporting::formatByKey("pedpy"));
        QCOMPARE(exporting::formatForPath("shot.USDA"), exporting::formatByKey("usd"));
        QCOMPARE(exporting::knownPathForms(), std::string(".glb, .gltf, .usda, .fbx, .csv, .txt, DIR/"));
        // Only a .gltf's JSON is indented: a .glb is binary, a CSV has no such choice.
        QVERIFY(exporting::indentsText(*gltf, "out/shot.gltf") && exporting::indentsText(*gltf, "SHOT.GLTF"));
        QVERIFY(!exporting::indentsText(*gltf, "shot.glb") && !exporting::indentsText(*csv, "run.csv"));
    }

    // Each row writes the fixture's 3 agents x 49 frames; a row without a check here fails,
    // so a new format brings its reader along.
    void everyWriterWritesWhatItsReaderAccepts()
    {
        const CrowdFixture fx = CrowdFixture::make();
        for (const exporting::ExportFormat& f : exporting::exportFormats()) {
            QTemporaryDir dir;
            exporting::ExportRequest request;
            request.path = targetIn(dir, f).toStdString();
            const exporting::ExportResult result = f.write(fx.scene, fx.cache, request, {});
            QVERIFY2(result.ok(), result.error.c_str());
            QVERIFY2(!result.writtenPaths.empty(), f.key.c_str());
            for (const std::string& p : result.writtenPaths)
                QVERIFY2(QFile::exists(QString::fromStdString(p)), p.c_str());
            if (f.key == "gltf") {
                tinygltf::Model model;
                std::string error;
                QVERIFY2(test::loadGltf(request.path, model, error), error.c_str());
                QCOMPARE(model.animations.size(), std::size_t(1));
                for (const char* node : {"agent_7_walker", "agent_42_runner", "agent_1000_walker"})
                    QVERIFY2(test::nodeNamed(model, node) >= 0, node);
            } else if (f.key == "usd") {
                // A UsdSkel stage: a SkelRoot per agent (tests/export/TestUsdExport reads it with tinyusdz).
                const QStringList lines = readLines(QString::fromStdString(request.path));
                QCOMPARE(lines.first(), QStringLiteral("#usda 1.0"));
                QVERIFY(lines.contains("    endTimeCode = 48"));
                for (const char* agent : {"agent_7_walker", "agent_42_runner", "agent_1000_walker"})
                    QVERIFY2(lines.contains(QString("        def SkelRoot \"%1\" (").arg(agent)), agent);
            } else if (f.key == "fbx") {
                // assimp reads it back: an agent node each, one animation (tests/export/TestFbxExport).
                Assimp::Importer importer;
                const aiScene* scene = importer.ReadFile(request.path, 0);
                QVERIFY2(scene, importer.GetErrorString());
                QCOMPARE(scene->mNumAnimations, 1u);
                for (const char* agent : {"agent_7_walker", "agent_42_runner", "agent_1000_walker"})
                    QVERIFY2(scene->mRootNode->FindNode(agent), agent);
            } else if (f.key == "csv") {
                const QStringList lines = readLines(QString::fromStdString(request.path));
                QCOMPARE(lines.size(), 1 + 3 * int(CrowdFixture::kFrames));
                QCOMPARE(lines.first(), QStringLiteral("frame,agent,x,y,z,heading,speed,clip,phase"));
            } else if (f.key == "pedpy") {
                // Three walkers, no vehicle: a row per walker per frame after the comments,
                // "id frame x y z" with y = -z; the set beside it.
                const QStringList lines = readLines(QString::fromStdString(request.path));
                QVERIFY(lines.contains("# framerate: 24"));
                const QStringList rows = lines.filter(QRegularExpression("^[0-9]"));
                QCOMPARE(rows.size(), 3 * int(CrowdFixture::kFrames));
                const QStringList first = rows.first().split(' ');
                QCOMPARE(first.size(), 5);
                const sim::AgentFrame& a = fx.cache.at(0, 0);
                QCOMPARE(first[0].toUInt(), fx.cache.agents()[0].id);
                QCOMPARE(first[1], QString("0"));
                QCOMPARE(first[2].toFloat(), a.position.x);
                QCOMPARE(first[3].toFloat(), -a.position.z);
                QCOMPARE(first[4].toFloat(), a.position.y);
                QCOMPARE(result.writtenPaths.size(), std::size_t(2));
                QVERIFY(readLines(dir.filePath("out.wkt")).first().startsWith("GEOMETRYCOLLECTION (POLYGON (("));
            } else if (f.key == "maya-cache") {
                // The text cache's files with rotY for rigs facing +Z (heading + 90), and the
                // manifest a script reads: the rate, the frames, each agent's file.
                const QString out = dir.filePath("out");
                QCOMPARE(entries(out),
                         (QStringList{"agent_1000.txt", "agent_42.txt", "agent_7.txt", "throng_cache.txt"}));
                const QStringList manifest = readLines(QDir(out).filePath("throng_cache.txt"));
                QVERIFY(manifest.contains("fps 24") && manifest.contains("frames 49") && manifest.contains("forward +z"));
                QVERIFY(manifest.contains("agent 42 agent_42.txt 0 49"));
                const QStringList first = readLines(QDir(out).filePath("agent_42.txt")).first().split(' ');
                const double heading = double(fx.cache.at(0, 1).headingRad) * 180.0 / 3.14159265358979;
                QVERIFY2(std::abs(first[3].toDouble() - (heading + 90.0)) < 1e-3, qPrintable(first.join(' ')));
                request.mayaForward = exporting::ForwardAxis::PlusX;
                QTemporaryDir plain;
                request.path = (plain.filePath("out") + '/').toStdString();
                QVERIFY(f.write(fx.scene, fx.cache, request, {}).ok());
                const QStringList asX = readLines(QDir(plain.filePath("out")).filePath("agent_42.txt")).first().split(' ');
                QVERIFY2(std::abs(asX[3].toDouble() - heading) < 1e-3, qPrintable(asX.join(' ')));
                QVERIFY(readLines(QDir(plain.filePath("out")).filePath("throng_cache.txt")).contains("forward +x"));
            } else if (f.key == "text-cache") {
                const QString out = dir.filePath("out");
                QCOMPARE(entries(out), (QStringList{"agent_1000.txt", "agent_42.txt", "agent_7.txt"}));
                for (const QString& file : entries(out))
                    QCOMPARE(readLines(QDir(out).filePath(file)).size(), int(CrowdFixture::kFrames));
                QCOMPARE(entries(dir.path()), QStringList{"out"});  // no staging directory left beside it
            } else {
                QFAIL(("no reader check for format '" + f.key + "': add one here").c_str());
            }
        }
    }

    // The glTF row reads the request's choices: .gltf writes its .bin beside it, indented.
    void gltfRowHonoursTheRequest()
    {
        const CrowdFixture fx = CrowdFixture::make();
        QTemporaryDir dir;
        exporting::ExportRequest request;
        request.path = dir.filePath("shot.gltf").toStdString();
        request.indentedText = true;
        request.jointBake = exporting::JointBake::Compact;
        const exporting::ExportResult result = exporting::formatForPath(request.path)->write(fx.scene, fx.cache, request, {});
        QVERIFY2(result.ok(), result.error.c_str());
        QCOMPARE(entries(dir.path()), (QStringList{"shot.bin", "shot.gltf"}));
        QFile json(dir.filePath("shot.gltf"));
        QVERIFY(json.open(QIODevice::ReadOnly));
        const QByteArray text = json.readAll();
        QVERIFY(text.contains("\n  "));
        QVERIFY(text.contains("compact"));
    }

    void cancelledWriterLeavesNothing()
    {
        const CrowdFixture fx = CrowdFixture::make();
        for (const exporting::ExportFormat& f : exporting::exportFormats()) {
            QTemporaryDir dir;
            exporting::ExportRequest request;
            request.path = targetIn(dir, f).toStdString();
            int calls = 0;
            const exporting::ExportResult result =
                f.write(fx.scene, fx.cache, request, [&](float) { return ++calls < 2; });
            QVERIFY2(result.cancelled, f.key.c_str());
            QVERIFY2(!result.ok() && result.writtenPaths.empty(), f.key.c_str());
            QVERIFY2(entries(dir.path()).isEmpty(), qPrintable(f.key.c_str() + (": " + entries(dir.path()).join(' '))));
        }
    }

    // Every skinned-crowd writer refuses a key tolerance below 0 or not a number, with a
    // message that names the file, before it asks for progress or writes anything.
    void badToleranceIsRefused_data()
    {
        QTest::addColumn<QString>("format");
        QTest::addColumn<int>("which");  // position, rotation, root rotation
        QTest::addColumn<float>("value");
        const float nan = std::numeric_limits<float>::quiet_NaN();
        QTest::newRow("gltf position -0.1") << "gltf" << 0 << -0.1f;
        QTest::newRow("gltf rotation NaN") << "gltf" << 1 << nan;
        QTest::newRow("gltf root rotation -1") << "gltf" << 2 << -1.0f;
        QTest::newRow("usd position NaN") << "usd" << 0 << nan;
        QTest::newRow("usd rotation -2") << "usd" << 1 << -2.0f;
        QTest::newRow("usd root rotation NaN") << "usd" << 2 << nan;
        QTest::newRow("fbx position -0.001") << "fbx" << 0 << -0.001f;
        QTest::newRow("fbx position NaN") << "fbx" << 0 << nan;
    }
    void badToleranceIsRefused()
    {
        QFETCH(QString, format);
        QFETCH(int, which);
        QFETCH(float, value);
        const CrowdFixture fx = CrowdFixture::make();
        QTemporaryDir dir;
        int progressCalls = 0;
        const exporting::ProgressFn progress = [&](float) { return ++progressCalls > 0; };
        auto set = [&](auto& options) {
            float* tolerances[] = {&options.positionToleranceM, nullptr, nullptr};
            if constexpr (requires { options.rotationToleranceDeg; }) {
                tolerances[1] = &options.rotationToleranceDeg;
                tolerances[2] = &options.rootRotationToleranceDeg;
            }
            QVERIFY(tolerances[which]);
            *tolerances[which] = value;
        };
        exporting::ExportResult result;
        std::string path;
        if (format == "gltf") {
            exporting::GltfOptions options;
            options.path = path = dir.filePath("shot.glb").toStdString();
            set(options);
            result = exporting::exportGltf(fx.scene, fx.cache, options, progress);
        } else if (format == "usd") {
            exporting::UsdOptions options;
            options.path = path = dir.filePath("shot.usda").toStdString();
            set(options);
            result = exporting::exportUsd(fx.scene, fx.cache, options, progress);
        } else {
            exporting::FbxOptions options;
            options.path = path = dir.filePath("shot.fbx").toStdString();
            set(options);
            result = exporting::exportFbx(fx.scene, fx.cache, options, progress);
        }
        QVERIFY(!result.ok() && !result.cancelled);
        QCOMPARE(QString::fromStdString(result.error),
                 QString::fromStdString("cannot export '" + path + "': key tolerances must be >= 0"));
        QCOMPARE(progressCalls, 0);
        QVERIFY(result.writtenPaths.empty());
        QVERIFY2(entries(dir.path()).isEmpty(), qPrintable(entries(dir.path()).join(' ')));
    }
};

THRONG_REGISTER_TEST(TestExportFormats)
#include "TestExportFormats.moc"
