// Wedges (issue 28), run as a user runs them, with the real throng-cli: `run --set` changes
// a scene value as if the file said so (and refuses a key the format lacks, naming it);
// `wedge` runs every combination of the values for every seed in parallel processes, each
// variant's figures in its own folder, and `wedge collect` gathers them into a CSV, a JSON
// table and a plot, where a failed variant's row says why and the others are kept; a bad
// --set or --seeds stops before anything runs, and a folder that holds a wedge is never
// overwritten. With --slurm the same wedge goes to a real single-node Slurm the test
// starts (local-slurm.sh) as one array job, and gives the same figures.
#include "CliRunner.h"
#include "TestRegistry.h"

#include "WedgePlan.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QProcessEnvironment>
#include <QTemporaryDir>
#include <QTest>

#include <unistd.h>

using throng::test::runCli;

namespace {

// 10 walkers in a room walk to an exit 10 m east, all at their type's top speed.
const char* kRoom = R"(throng: 1
settings: {fps: 10, duration: 20, seed: 3}
agent_types: [{name: walker, radius: 0.25, max_speed: 1.3, variation: {speed: [1, 1]}}]
goals: [{name: exit, position: [10, 0], radius: 1.5, exit: true}]
groups: [{name: crowd, type: walker, count: 10, rect: {min: [-3, -3], max: [0, 3]}, goal: exit}]
)";

struct ProcessRun {
    int status = -1;
    QString out, err;
};

ProcessRun cli(const QStringList& args, const QString& slurmConf = {})
{
    QProcess p;
    if (!slurmConf.isEmpty()) {
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("SLURM_CONF", slurmConf);
        p.setProcessEnvironment(env);
    }
    p.start(QStringLiteral(THRONG_CLI_PATH), args);
    p.waitForFinished(300000);
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, QString::fromUtf8(p.readAllStandardOutput()),
            QString::fromUtf8(p.readAllStandardError())};
}

QStringList linesIn(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    QStringList out = QString::fromUtf8(f.readAll()).split('\n');
    if (!out.isEmpty() && out.last().isEmpty())
        out.removeLast();
    return out;
}

}  // namespace

class TestCliWedge : public QObject {
    Q_OBJECT
private slots:
    void setChangesAValueAsTheFileWould()
    {
        QTemporaryDir tmp;
        const QString scene = throng::test::writeText(tmp.filePath("room.yaml"), kRoom);
        const QString stats = tmp.filePath("s.json");
        auto r = runCli({"run", scene.toStdString(), "--set", "groups.crowd.count=4", "--set",
                         "agent_types.walker.max_speed=0.3", "--stats", stats.toStdString(), "--quiet"});
        QVERIFY2(r.status == 0, r.err.c_str());
        QFile f(stats);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QJsonObject o = QJsonDocument::fromJson(f.readAll()).object();
        QCOMPARE(o["agents"].toInt(), 4);
        // At 0.3 m/s nobody covers the 8.5 m and more to the exit in 20 s.
        QCOMPARE(o["agents_out"].toInt(), 0);
        // A key the format lacks, a list item that is not there, and a value it refuses.
        r = runCli({"run", scene.toStdString(), "--set", "agent_types.walker.max_sped=2", "--quiet"});
        QCOMPARE(r.status, 1);
        QVERIFY2(r.err.find("--set agent_types.walker.max_sped: error: the scene format has no key 'max_sped'") !=
                     std::string::npos,
                 r.err.c_str());
        r = runCli({"run", scene.toStdString(), "--set", "groups.mob.count=4", "--quiet"});
        QCOMPARE(r.status, 1);
        QVERIFY2(r.err.find("the list at 'groups' has no item named 'mob'") != std::string::npos, r.err.c_str());
        r = runCli({"run", scene.toStdString(), "--set", "groups.crowd.count=-4", "--quiet"});
        QCOMPARE(r.status, 1);
        QVERIFY2(r.err.find("(with --set)") != std::string::npos && r.err.find("count") != std::string::npos,
                 r.err.c_str());
        r = runCli({"run", scene.toStdString(), "--set", "noequals"});
        QCOMPARE(r.status, 2);
        QVERIFY2(r.err.find("not KEY=VALUE") != std::string::npos, r.err.c_str());
    }

    void variantsExpandEveryCombinationForEverySeed()
    {
        std::string error;
        const auto speed = throng::cli::parseAxis("agent_types.walker.max_speed=1,1.5", error);
        const auto spread = throng::cli::parseAxis("agent_types.walker.variation.speed=[0.9, 1.1],[1, 1]", error);
        QVERIFY2(speed && spread, error.c_str());
        QCOMPARE(spread->values, (std::vector<std::string>{"[0.9, 1.1]", "[1, 1]"}));
        const auto seeds = throng::cli::parseSeeds("4..6", error);
        QVERIFY(seeds && *seeds == (std::vector<std::uint64_t>{4, 5, 6}));
        const auto variants = throng::cli::expandVariants({*speed, *spread}, *seeds);
        QCOMPARE(variants.size(), std::size_t(2 * 2 * 3));
        QCOMPARE(variants[0].folder, std::string("v000"));
        QCOMPARE(variants[11].folder, std::string("v011"));
        QCOMPARE(variants[3].overrides[0].value, std::string("1"));
        QCOMPARE(variants[3].overrides[1].value, std::string("[1, 1]"));
        QCOMPARE(*variants[3].seed, std::uint64_t(4));
        QVERIFY(!throng::cli::parseSeeds("6..4", error));
        QVERIFY(!throng::cli::parseAxis("=1,2", error));
        QVERIFY(!throng::cli::parseAxis("a.b=1,,2", error));
        // The plan reads back as it was written.
        throng::cli::WedgePlan plan{"/x/room.yaml", {*speed, *spread}, *seeds, variants};
        const auto back = throng::cli::planFromYaml(throng::cli::planToYaml(plan), error);
        QVERIFY2(back, error.c_str());
        QCOMPARE(back->variants.size(), variants.size());
        QCOMPARE(back->variants[7].overrides, variants[7].overrides);
        QCOMPARE(back->variants[7].seed, variants[7].seed);
    }

    // Two speeds x two seeds, two variants at a time.
    void aWedgeRunsEveryVariantAndCollectsThem()
    {
        QTemporaryDir tmp;
        const QString scene = throng::test::writeText(tmp.filePath("room.yaml"), kRoom);
        const QString dir = tmp.filePath("wedge");
        const ProcessRun r = cli({"wedge", scene, "--set", "agent_types.walker.max_speed=0.4,1.3", "--seeds", "1..2", "--out",
                           dir, "--jobs", "2"});
        QVERIFY2(r.status == 0, qPrintable(r.err + r.out));
        QVERIFY2(r.err.contains("wedge: 4 of 4 variants done"), qPrintable(r.err));
        QVERIFY2(r.out.contains("wedge: 4 of 4 variants ran"), qPrintable(r.out));
        const QStringList csv = linesIn(QDir(dir).filePath("wedge.csv"));
        QCOMPARE(csv.size(), 1 + 4);
        const QStringList header = csv[0].split(',');
        QCOMPARE(header.mid(0, 5), (QStringList{"variant", "seed", "agent_types.walker.max_speed", "status", "reason"}));
        const int out = header.indexOf("agents_out"), seedColumn = header.indexOf("seed");
        QVERIFY(out > 0);
        // Each row is its variant's own stats.json, and its seed and speed are what it ran with.
        for (int k = 1; k <= 4; ++k) {
            const QStringList row = csv[k].split(',');
            QCOMPARE(row[0], QString("v%1").arg(k - 1, 3, 10, QChar('0')));
            QCOMPARE(row[seedColumn], QString::number(k % 2 == 1 ? 1 : 2));
            QCOMPARE(row[2], QString(k <= 2 ? "0.4" : "1.3"));
            QCOMPARE(row[3], QString("ok"));
            QFile stats(QDir(dir).filePath(row[0] + "/stats.json"));
            QVERIFY(stats.open(QIODevice::ReadOnly));
            const QJsonObject o = QJsonDocument::fromJson(stats.readAll()).object();
            QCOMPARE(row[out].toInt(), o["agents_out"].toInt());
            QCOMPARE(o["seed"].toInt(), row[seedColumn].toInt());
        }
        // 1.3 m/s gets all ten out in 20 s; at 0.4 m/s the 8.5 m and more to the exit take
        // over 21 s.
        QCOMPARE(csv[3].split(',')[out].toInt(), 10);
        QCOMPARE(csv[1].split(',')[out].toInt(), 0);
        // The JSON table and the plot.
        QFile json(QDir(dir).filePath("wedge.json"));
        QVERIFY(json.open(QIODevice::ReadOnly));
        const QJsonArray variants = QJsonDocument::fromJson(json.readAll()).object()["variants"].toArray();
        QCOMPARE(variants.size(), 4);
        QCOMPARE(variants[2].toObject()["set"].toObject()["agent_types.walker.max_speed"].toString(), QString("1.3"));
        QCOMPARE(variants[2].toObject()["stats"].toObject()["agents_out"].toInt(), 10);
        QVERIFY(QFile(QDir(dir).filePath("wedge.png")).size() > 1000);

        // A variant that fails: its row says why, the others are kept. (Its stats are taken
        // away and its status rewritten, as a run killed on a farm would leave them.)
        QFile::remove(QDir(dir).filePath("v001/stats.json"));
        QFile status(QDir(dir).filePath("v001/status"));
        QVERIFY(status.open(QIODevice::WriteOnly));
        status.write("1\n");
        status.close();
        QFile log(QDir(dir).filePath("v001/run.log"));
        QVERIFY(log.open(QIODevice::WriteOnly));
        log.write("throng-cli: out of memory\n");
        log.close();
        const ProcessRun collect = cli({"wedge", "collect", dir, "--metric", "agents_out"});
        QCOMPARE(collect.status, 1);
        QVERIFY2(collect.out.contains("3 of 4 variants ran; failed: v001 (throng-cli: out of memory)"),
                 qPrintable(collect.out));
        const QStringList again = linesIn(QDir(dir).filePath("wedge.csv"));
        QCOMPARE(again[2].split(',')[3], QString("failed"));
        QCOMPARE(again[2].split(',')[4], QString("throng-cli: out of memory"));
        QCOMPARE(again[3], csv[3]);
        QCOMPARE(again[1], csv[1]);

        // The folder holds a wedge now: a second one there is refused, and nothing changes.
        const ProcessRun twice = cli({"wedge", scene, "--seeds", "1..2", "--out", dir});
        QCOMPARE(twice.status, 1);
        QVERIFY2(twice.err.contains("already holds a wedge"), qPrintable(twice.err));
    }

    // The wedge above as one Slurm array job on a node of this machine: every task ran, and
    // every variant's figures are those of the same variant run here.
    void aWedgeRunsAsASlurmArrayJob()
    {
        QTemporaryDir tmp;
        const QString script = QStringLiteral(THRONG_SOURCE_DIR "/tests/cli/local-slurm.sh");
        const QString slurmDir = tmp.filePath("slurm");
        QDir().mkpath(slurmDir);
        const int port = 20000 + int(getpid() % 10000) * 2;
        QProcess start;
        start.start("bash", {script, "start", slurmDir, QString::number(port)});
        QVERIFY(start.waitForFinished(60000));
        const QString conf = QString::fromUtf8(start.readAllStandardOutput()).trimmed();
        struct Stop {
            QString script, dir;
            ~Stop() { QProcess::execute("bash", {script, "stop", dir}); }
        } stop{script, slurmDir};
        QVERIFY2(start.exitCode() == 0 && conf.endsWith("slurm.conf"),
                 qPrintable(QString::fromUtf8(start.readAllStandardError())));

        const QString scene = throng::test::writeText(tmp.filePath("room.yaml"), kRoom);
        const QString farm = tmp.filePath("farm"), here = tmp.filePath("here");
        const QStringList vary{"--set", "agent_types.walker.max_speed=0.4,1.3", "--seeds", "1..2"};
        const ProcessRun submitted = cli(QStringList{"wedge", scene, "--out", farm, "--slurm"} + vary, conf);
        QVERIFY2(submitted.status == 0, qPrintable(submitted.err + submitted.out));
        QVERIFY2(submitted.out.contains("submitted Slurm job") && submitted.out.contains("4 tasks"),
                 qPrintable(submitted.out));
        QVERIFY(linesIn(QDir(farm).filePath("wedge.sbatch")).contains("#SBATCH --array=0-3"));
        QTRY_VERIFY_WITH_TIMEOUT(QFile::exists(QDir(farm).filePath("v000/status")) &&
                                     QFile::exists(QDir(farm).filePath("v001/status")) &&
                                     QFile::exists(QDir(farm).filePath("v002/status")) &&
                                     QFile::exists(QDir(farm).filePath("v003/status")),
                                 120000);
        const ProcessRun collected = cli({"wedge", "collect", farm}, conf);
        QVERIFY2(collected.status == 0 && collected.out.contains("4 of 4 variants ran"), qPrintable(collected.out));
        QCOMPARE(cli(QStringList{"wedge", scene, "--out", here} + vary).status, 0);
        const QStringList fromFarm = linesIn(QDir(farm).filePath("wedge.csv")),
                          fromHere = linesIn(QDir(here).filePath("wedge.csv"));
        QCOMPARE(fromFarm.size(), 5);
        const QStringList header = fromFarm[0].split(',');
        QCOMPARE(header, fromHere[0].split(','));
        for (const char* figure : {"agents_out", "arrived", "overlapping_pairs", "peak_density_per_m2"}) {
            const int c = header.indexOf(figure);
            QVERIFY2(c > 0, figure);
            for (int k = 1; k <= 4; ++k)
                QCOMPARE(fromFarm[k].split(',')[c], fromHere[k].split(',')[c]);
        }
        QCOMPARE(fromFarm[3].split(',')[header.indexOf("agents_out")], QString("10"));
    }

    // One variant at a time, each on the run's own threads (every core): all run, with
    // --threads given (each on that many) and without it.
    void aWedgeOneVariantAtATimeRunsThemAll()
    {
        QTemporaryDir tmp;
        const QString scene = throng::test::writeText(tmp.filePath("room.yaml"), kRoom);
        for (const QStringList& threads : {QStringList{}, QStringList{"--threads", "2"}}) {
            const QString dir = tmp.filePath(threads.isEmpty() ? "w" : "w2");
            const ProcessRun r = cli(QStringList{"wedge", scene, "--seeds", "1..2", "--out", dir, "--jobs", "1",
                                                 "--metric", "agents_out"} + threads);
            QVERIFY2(r.status == 0, qPrintable(r.err + r.out));
            QVERIFY2(r.out.contains("wedge: 2 of 2 variants ran"), qPrintable(r.out));
            for (const char* v : {"v000", "v001"}) {
                QCOMPARE(linesIn(QDir(dir).filePath(QString(v) + "/status")), QStringList{"0"});
                QVERIFY(QFile::exists(QDir(dir).filePath(QString(v) + "/stats.json")));
            }
        }
    }

    void badWedgesStopBeforeAnythingRuns()
    {
        QTemporaryDir tmp;
        const QString scene = throng::test::writeText(tmp.filePath("room.yaml"), kRoom);
        const QString dir = tmp.filePath("w");
        ProcessRun r = cli({"wedge", scene, "--set", "agent_types.walker.max_speed=1,-1", "--out", dir});
        QCOMPARE(r.status, 1);
        QVERIFY2(r.err.contains("variant v001") && r.err.contains("max_speed"), qPrintable(r.err));
        QVERIFY(!QFile::exists(QDir(dir).filePath("wedge.yaml")));
        r = cli({"wedge", scene, "--set", "agent_types.walker.speedy=1,2", "--out", dir});
        QCOMPARE(r.status, 1);
        QVERIFY2(r.err.contains("no key 'speedy'"), qPrintable(r.err));
        r = cli({"wedge", scene, "--seeds", "9..3", "--out", dir});
        QCOMPARE(r.status, 2);
        QVERIFY2(r.err.contains("--seeds 9..3"), qPrintable(r.err));
        r = cli({"wedge", scene, "--out", dir});
        QCOMPARE(r.status, 2);
        QVERIFY2(r.err.contains("something to vary"), qPrintable(r.err));
        r = cli({"wedge", scene, "--seeds", "1..2"});
        QCOMPARE(r.status, 2);
        QVERIFY2(r.err.contains("needs --out"), qPrintable(r.err));
        r = cli({"wedge", "collect", tmp.filePath("nowhere")});
        QCOMPARE(r.status, 1);
        QVERIFY2(r.err.contains("no wedge here"), qPrintable(r.err));
        r = cli({"check", scene, "--seeds", "1..2"});
        QCOMPARE(r.status, 2);
        QVERIFY2(r.err.contains("belong to 'wedge'"), qPrintable(r.err));
        r = cli({"wedge", scene, "--seeds", "1..2", "--out", dir, "--slurm", "--jobs", "2"});
        QCOMPARE(r.status, 2);
        QVERIFY2(r.err.contains("Slurm runs the variants"), qPrintable(r.err));
    }
};

THRONG_REGISTER_TEST(TestCliWedge)
#include "TestCliWedge.moc"
