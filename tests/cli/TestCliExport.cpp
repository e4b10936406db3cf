// `throng-cli run --export` picks the format by the path's suffix from the export
// formats' table: the CSV through --export is --trajectories' file, one run writes every
// output asked for, an unknown suffix stops before the run, and `DIR/` is the text cache.
#include "CliRunner.h"
#include "TestRegistry.h"

#include "export/ExportFormats.h"

#include <QDir>
#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>

using throng::test::runCli;

namespace {

const char* kScene = R"(throng: 1
settings: {fps: 10, duration: 3, seed: 4}
agent_types: [{name: walker, max_speed: 1.5, max_force: 6}]
goals: [{name: exit, position: [8, 0], radius: 1}]
groups: [{name: g, type: walker, count: 12, rect: {min: [-6, -5], max: [0, 5]}, goal: exit}]
)";

QByteArray readAll(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

QStringList entries(const QString& dir)
{
    QStringList names = QDir(dir).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot);
    names.sort();
    return names;
}

}  // namespace

class TestCliExport : public QObject {
    Q_OBJECT
private slots:
    // The scene's layout layer edits what the exports write, not the run: the CSV's rows of
    // the deleted agent are gone and the moved ones' x is 5 m further on; the stats are the
    // run's, byte for byte; an operation that selects nobody is named on stderr.
    void theLayoutLayerEditsTheExportsNotTheRun()
    {
        QTemporaryDir tmp;
        const std::string plain = throng::test::writeText(tmp.filePath("plain.yaml"), kScene).toStdString();
        const std::string layered = std::string(kScene) + "layout:\n"
                                                          "  - {op: delete, agents: {ids: [1]}}\n"
                                                          "  - {op: translate, agents: {groups: [g]}, offset: [5, 0]}\n"
                                                          "  - {op: delete, agents: {ids: [77]}}\n";
        const std::string laid = throng::test::writeText(tmp.filePath("laid.yaml"), layered.c_str()).toStdString();
        const QString csvPlain = tmp.filePath("plain.csv"), csvLaid = tmp.filePath("laid.csv");
        const QString statsPlain = tmp.filePath("plain.json"), statsLaid = tmp.filePath("laid.json");
        auto r = runCli({"run", plain, "--frames", "15", "--trajectories", csvPlain.toStdString(), "--stats",
                         statsPlain.toStdString(), "--quiet"});
        QCOMPARE(r.status, 0);
        r = runCli({"run", laid, "--frames", "15", "--trajectories", csvLaid.toStdString(), "--stats",
                    statsLaid.toStdString(), "--quiet"});
        QCOMPARE(r.status, 0);
        QVERIFY2(r.err.find("warning: layout operation 3 (delete): 1 agent is not in the recording (id 77)") !=
                     std::string::npos,
                 r.err.c_str());
        QVERIFY2(r.err.find("warning: layout operation 1") == std::string::npos, r.err.c_str());
        QVERIFY2(r.err.find("the layout layer makes") == std::string::npos, r.err.c_str());  // all moved as one
        // The stats are the simulation's whatever the layer does, but for the seconds it took.
        auto withoutTimes = [](QByteArray json) {
            QStringList lines = QString::fromUtf8(json).split('\n');
            lines.erase(std::remove_if(lines.begin(), lines.end(), [](const QString& l) {
                            return l.contains("seconds") || l.contains("steps_per_second") || l.contains("per_second");
                        }),
                        lines.end());
            return lines;
        };
        QCOMPARE(withoutTimes(readAll(statsLaid)), withoutTimes(readAll(statsPlain)));
        const QStringList before = QString::fromUtf8(readAll(csvPlain)).trimmed().split('\n');
        const QStringList after = QString::fromUtf8(readAll(csvLaid)).trimmed().split('\n');
        QCOMPARE(before.size(), 1 + 15 * 12);
        QCOMPARE(after.size(), 1 + 15 * 11);  // agent 1 deleted
        int compared = 0;
        for (const QString& row : after.mid(1)) {
            const QStringList f = row.split(',');
            QVERIFY(f[1] != "1");
            const QRegularExpression sameRow("^" + f[0] + "," + f[1] + ",");
            const QStringList original = before.filter(sameRow).first().split(',');
            QVERIFY2(std::abs(f[2].toDouble() - original[2].toDouble() - 5.0) < 1e-4, qPrintable(row));
            QCOMPARE(f[4], original[4]);
            ++compared;
        }
        QCOMPARE(compared, 15 * 11);

        // Squeezed to a tenth of its spread, the group's bodies overlap: the check says so.
        const std::string squeezed = std::string(kScene) + "layout:\n"
                                                           "  - {op: expand, agents: {groups: [g]}, factor: 0.1}\n";
        const std::string tight = throng::test::writeText(tmp.filePath("tight.yaml"), squeezed.c_str()).toStdString();
        r = runCli({"run", tight, "--frames", "15", "--trajectories", tmp.filePath("tight.csv").toStdString(),
                    "--quiet"});
        QCOMPARE(r.status, 0);
        QVERIFY2(r.err.find("warning: the layout layer makes ") != std::string::npos &&
                     r.err.find(" overlaps and 0 wall crossings on 15 frames (first: frame 0, agent ") !=
                         std::string::npos,
                 r.err.c_str());
    }

    void exportCsvIsTheTrajectoriesFile()
    {
        QTemporaryDir tmp;
        const std::string scene = throng::test::writeText(tmp.filePath("s.yaml"), kScene).toStdString();
        const QString trajectories = tmp.filePath("trajectories.csv"), exported = tmp.filePath("exported.csv");
        auto r = runCli({"run", scene, "--frames", "15", "--seed", "11", "--trajectories", trajectories.toStdString(),
                         "--quiet"});
        QCOMPARE(r.status, 0);
        QVERIFY2(r.out.find("trajectories: " + trajectories.toStdString()) != std::string::npos, r.out.c_str());
        r = runCli({"run", scene, "--frames", "15", "--seed", "11", "--export", exported.toStdString(), "--quiet"});
        QCOMPARE(r.status, 0);
        QVERIFY2(r.out.find("export: " + exported.toStdString()) != std::string::npos, r.out.c_str());
        const QByteArray bytes = readAll(trajectories);
        QVERIFY(bytes.startsWith("frame,agent,x,y,z,heading,speed,clip,phase\n"));
        QCOMPARE(bytes.count('\n'), 1 + 15 * 12);
        QCOMPARE(readAll(exported), bytes);
    }

    void everyOutputOfOneRunIsWritten()
    {
        QTemporaryDir tmp;
        const std::string scene = throng::test::writeText(tmp.filePath("s.yaml"), kScene).toStdString();
        const QString glb = tmp.filePath("crowd.glb"), csv = tmp.filePath("crowd.csv"), more = tmp.filePath("t.csv");
        const auto r = runCli({"run", scene, "--frames", "10", "--export", glb.toStdString(), "--export",
                               csv.toStdString(), "--trajectories", more.toStdString(), "--quiet"});
        QCOMPARE(r.status, 0);
        QCOMPARE(readAll(glb).left(4), QByteArray("glTF"));
        QCOMPARE(readAll(csv).count('\n'), 1 + 10 * 12);
        QCOMPARE(readAll(more), readAll(csv));
    }

    void unknownSuffixStopsBeforeTheRun()
    {
        QTemporaryDir tmp;
        const std::string scene = throng::test::writeText(tmp.filePath("s.yaml"), kScene).toStdString();
        const std::string glb = tmp.filePath("crowd.glb").toStdString(), xyz = tmp.filePath("out.xyz").toStdString();
        const auto r = runCli({"run", scene, "--export", glb, "--export", xyz, "--stats",
                               tmp.filePath("s.json").toStdString()});
        QCOMPARE(r.status, 2);
        const std::string message = "throng-cli: --export " + xyz + ": unknown format '.xyz' (known: " +
                                    throng::exporting::knownPathForms() + ")";
        QVERIFY2(r.err.rfind(message, 0) == 0, r.err.c_str());
        QVERIFY(throng::exporting::knownPathForms().find(".glb, .gltf, .usda, .fbx, .csv") != std::string::npos);
        QVERIFY(r.out.empty());
        QCOMPARE(entries(tmp.path()), QStringList{"s.yaml"});
    }

    void sameOutputTwiceIsAUsageError()
    {
        const auto r = runCli({"run", "s.yaml", "--export", "a.csv", "--trajectories", "a.csv"});
        QCOMPARE(r.status, 2);
        QVERIFY2(r.err.find("--trajectories a.csv: already an output of this run") != std::string::npos, r.err.c_str());
    }

    // --export-lod picks the built-in bodies' detail: the far file's geometry is a
    // fraction of the near one's (the same run, the same man); a level not named is a
    // usage error before any run.
    void levelOfDetailChoosesTheBodies()
    {
        QTemporaryDir tmp;
        const std::string scene = throng::test::writeText(tmp.filePath("s.yaml"), kScene).toStdString();
        const QString nearGlb = tmp.filePath("near.glb"), farGlb = tmp.filePath("far.glb");
        auto r = runCli({"run", scene, "--frames", "4", "--export", nearGlb.toStdString(), "--quiet"});
        QCOMPARE(r.status, 0);
        r = runCli({"run", scene, "--frames", "4", "--export", farGlb.toStdString(), "--export-lod", "far", "--quiet"});
        QCOMPARE(r.status, 0);
        const QByteArray nearBytes = readAll(nearGlb), farBytes = readAll(farGlb);
        QCOMPARE(farBytes.left(4), QByteArray("glTF"));
        // The man near: about 4,150 vertices of 44 bytes; far: about 680.
        QVERIFY2(nearBytes.size() - farBytes.size() > 120000,
                 qPrintable(QString("%1 / %2 bytes").arg(nearBytes.size()).arg(farBytes.size())));
        r = runCli({"run", scene, "--export", nearGlb.toStdString(), "--export-lod", "huge"});
        QCOMPARE(r.status, 2);
        QVERIFY2(r.err.find("--export-lod is near, mid or far, got 'huge'") != std::string::npos, r.err.c_str());
        r = runCli({"check", scene, "--export-lod", "far"});
        QCOMPARE(r.status, 2);
        QVERIFY2(r.err.find("belong to 'run'") != std::string::npos, r.err.c_str());
    }

    // --no-set: the glTF of the crowd alone. kScene has bounds but no set beyond the ground.
    void noSetLeavesTheSetOut()
    {
        QTemporaryDir tmp;
        const std::string scene = throng::test::writeText(tmp.filePath("s.yaml"), kScene).toStdString();
        const QString with = tmp.filePath("with.glb"), without = tmp.filePath("without.glb");
        auto r = runCli({"run", scene, "--frames", "4", "--export", with.toStdString(), "--quiet"});
        QCOMPARE(r.status, 0);
        r = runCli({"run", scene, "--frames", "4", "--export", without.toStdString(), "--no-set", "--quiet"});
        QCOMPARE(r.status, 0);
        QVERIFY(readAll(with).contains("\"set_ground\""));
        QVERIFY(!readAll(without).contains("\"set_"));
        r = runCli({"check", scene, "--no-set"});
        QCOMPARE(r.status, 2);
        QVERIFY2(r.err.find("belong to 'run'") != std::string::npos, r.err.c_str());
    }

    // An export of half a million agent-frames and more shows its progress on stderr, as
    // the run does (a line every 10 % when stderr is no terminal); --quiet silences it.
    void aLongExportShowsItsProgress()
    {
        QTemporaryDir tmp;
        const std::string scene = THRONG_SOURCE_DIR "/resources/scenes/crossroads.yaml";
        const QString csv = tmp.filePath("long.csv");
        auto r = runCli({"run", scene, "--frames", "2400", "--export", csv.toStdString()});
        QCOMPARE(r.status, 0);
        for (const char* percent : {": 0%", ": 50%", ": 100%"})
            QVERIFY2(r.err.find("exporting " + csv.toStdString() + percent) != std::string::npos, r.err.c_str());
        r = runCli({"run", scene, "--frames", "2400", "--export", csv.toStdString(), "--quiet"});
        QCOMPARE(r.status, 0);
        QVERIFY2(r.err.find("exporting") == std::string::npos, r.err.c_str());
    }

    void exportBelongsToRun()
    {
        const auto r = runCli({"check", "s.yaml", "--export", "a.glb"});
        QCOMPARE(r.status, 2);
        QVERIFY2(r.err.find("belong to 'run'") != std::string::npos, r.err.c_str());
    }

    // A path ending in '/' is the text cache: one agent_<id>.txt per agent, a line per frame.
    void textCacheIsOneFilePerAgent()
    {
        QTemporaryDir tmp;
        const std::string scene = throng::test::writeText(tmp.filePath("s.yaml"), kScene).toStdString();
        const QString dir = tmp.filePath("cache/shot1");
        const auto r = runCli({"run", scene, "--frames", "8", "--export", dir.toStdString() + "/", "--quiet"});
        QCOMPARE(r.status, 0);
        QVERIFY2(r.out.find("export: " + dir.toStdString() + "/ (12 files)") != std::string::npos, r.out.c_str());
        const QStringList files = entries(dir);
        QCOMPARE(files.size(), 12);
        for (const QString& f : files) {
            QVERIFY2(f.startsWith("agent_") && f.endsWith(".txt"), qPrintable(f));
            QCOMPARE(readAll(QDir(dir).filePath(f)).count('\n'), 8);
        }
        QCOMPARE(entries(tmp.filePath("cache")), QStringList{"shot1"});  // no staging directory left
    }

    void usageListsEveryFormatOfTheTable()
    {
        const auto r = runCli({"--help"});
        QCOMPARE(r.status, 0);
        for (const throng::exporting::ExportFormat& f : throng::exporting::exportFormats()) {
            QVERIFY2(r.out.find(throng::exporting::pathForms(f)) != std::string::npos, f.key.c_str());
            QVERIFY2(r.out.find(f.label) != std::string::npos, f.key.c_str());
        }
    }
};

THRONG_REGISTER_TEST(TestCliExport)
#include "TestCliExport.moc"
