// `throng-cli run --maya-cache DIR` (issue 28's Maya hand-off): the per-agent files and
// the manifest read back and agree, line for line, with the trajectories CSV of the same
// run: positions and speeds equal, rotY the CSV's heading plus 90 degrees for rigs that
// face +Z (the default) and equal to it with --maya-forward x, each agent's file ending
// where it left; the manifest gives the frame rate, the frame count and each agent's first
// frame and frame count. A bad --maya-forward and an unwritable directory fail with a
// message; the MEL script that reads the cache ships beside the scenes.
#include "CliRunner.h"
#include "TestRegistry.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <map>

using throng::test::runCli;

namespace {

// 12 walkers head for an exit 8 m east and leave through it during the run.
const char* kLeavingScene = R"(throng: 1
settings: {fps: 10, duration: 12, seed: 4}
agent_types: [{name: walker, max_speed: 1.5, max_force: 6}]
goals: [{name: exit, position: [8, 0], radius: 1.5, exit: true}]
groups: [{name: g, type: walker, count: 12, rect: {min: [-4, -3], max: [0, 3]}, goal: exit}]
)";

QStringList linesOf(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    QStringList lines = QString::fromUtf8(f.readAll()).split('\n');
    if (!lines.isEmpty() && lines.last().isEmpty())
        lines.removeLast();
    return lines;
}

struct CsvRow {
    double x, y, z, heading, speed;
};

// agent id -> frame -> row, from the trajectories CSV.
std::map<unsigned, std::map<int, CsvRow>> readCsv(const QString& path)
{
    std::map<unsigned, std::map<int, CsvRow>> rows;
    const QStringList lines = linesOf(path);
    for (int k = 1; k < lines.size(); ++k) {
        const QStringList c = lines[k].split(',');
        rows[c[1].toUInt()][c[0].toInt()] = {c[2].toDouble(), c[3].toDouble(), c[4].toDouble(), c[5].toDouble(),
                                              c[6].toDouble()};
    }
    return rows;
}

}  // namespace

class TestCliMayaCache : public QObject {
    Q_OBJECT
private slots:
    void theCacheAgreesWithTheTrajectories()
    {
        for (const char* forward : {"", "z", "x"}) {
            QTemporaryDir tmp;
            const std::string scene = throng::test::writeText(tmp.filePath("s.yaml"), kLeavingScene).toStdString();
            const QString dir = tmp.filePath("maya"), csv = tmp.filePath("t.csv");
            std::vector<std::string> args{"run", scene, "--maya-cache", dir.toStdString(), "--trajectories",
                                          csv.toStdString(), "--quiet"};
            if (*forward) {
                args.push_back("--maya-forward");
                args.push_back(forward);
            }
            const auto r = runCli(args);
            QVERIFY2(r.status == 0, r.err.c_str());
            QVERIFY2(r.out.find("maya-cache: " + dir.toStdString()) != std::string::npos, r.out.c_str());
            const double rotYOffset = std::string(forward) == "x" ? 0.0 : 90.0;

            // The manifest.
            const QStringList manifest = linesOf(QDir(dir).filePath("throng_cache.txt"));
            QVERIFY(manifest.contains("fps 10"));
            QVERIFY(manifest.contains("frames 120"));
            QVERIFY(manifest.contains(rotYOffset == 0.0 ? "forward +x" : "forward +z"));
            QVERIFY(manifest.contains("unit m") && manifest.contains("up +y"));
            QVERIFY(manifest.contains("agents 12"));
            const QStringList agents = manifest.filter(QRegularExpression("^agent "));
            QCOMPARE(agents.size(), 12);

            const auto rows = readCsv(csv);
            QCOMPARE(rows.size(), std::size_t(12));
            int left = 0, lines = 0;
            for (const QString& a : agents) {
                const QStringList f = a.split(' ');  // agent <id> <file> <first> <frames>
                QCOMPARE(f.size(), 5);
                const unsigned id = f[1].toUInt();
                QCOMPARE(f[2], QString("agent_%1.txt").arg(id));
                QCOMPARE(f[3], QString("0"));
                const std::map<int, CsvRow>& mine = rows.at(id);
                const QStringList file = linesOf(QDir(dir).filePath(f[2]));
                // Its lines are its CSV rows: until it left, where the CSV's rows end too.
                QCOMPARE(file.size(), int(mine.size()));
                QCOMPARE(f[4].toInt(), file.size());
                left += file.size() < 120 ? 1 : 0;
                for (int k = 0; k < file.size(); ++k, ++lines) {
                    const QStringList v = file[k].split(' ');  // x y z rotY speed clip
                    QCOMPARE(v.size(), 6);
                    const CsvRow& c = mine.at(k);
                    QCOMPARE(v[0].toDouble(), c.x);
                    QCOMPARE(v[1].toDouble(), c.y);
                    QCOMPARE(v[2].toDouble(), c.z);
                    QVERIFY2(std::abs(v[3].toDouble() - (c.heading + rotYOffset)) < 1e-3,
                             qPrintable(file[k] + " against heading " + QString::number(c.heading)));
                    QCOMPARE(v[4].toDouble(), c.speed);
                }
            }
            QVERIFY2(left == 12, qPrintable(QString::number(left)));  // all out through the exit before 12 s
            QVERIFY(lines > 12 * 40);
            QCOMPARE(QDir(tmp.path()).entryList(QDir::Dirs | QDir::NoDotAndDotDot), QStringList{"maya"});
        }
    }

    void badChoicesAndPathsFailWithAMessage()
    {
        QTemporaryDir tmp;
        const std::string scene = throng::test::writeText(tmp.filePath("s.yaml"), kLeavingScene).toStdString();
        auto r = runCli({"run", scene, "--maya-cache", tmp.filePath("m").toStdString(), "--maya-forward", "y"});
        QCOMPARE(r.status, 2);
        QVERIFY2(r.err.find("--maya-forward is z or x, got 'y'") != std::string::npos, r.err.c_str());
        r = runCli({"check", scene, "--maya-forward", "x"});
        QCOMPARE(r.status, 2);
        QVERIFY2(r.err.find("belong to 'run'") != std::string::npos, r.err.c_str());
        // A file where the directory should be.
        const QString blocked = throng::test::writeText(tmp.filePath("blocked"), "not a directory\n");
        r = runCli({"run", scene, "--frames", "5", "--maya-cache", blocked.toStdString(), "--quiet"});
        QCOMPARE(r.status, 1);
        QVERIFY2(r.err.find(blocked.toStdString()) != std::string::npos, r.err.c_str());
        const auto help = runCli({"--help"});
        QVERIFY(help.out.find("--maya-cache DIR") != std::string::npos);
        QVERIFY(help.out.find("--maya-forward z|x") != std::string::npos);
    }

    // The script a Maya user sources reads the manifest this writes, and offers both ways in.
    void theMelScriptShipsWithTheCache()
    {
        const QStringList mel = linesOf(QStringLiteral(THRONG_SOURCE_DIR "/resources/maya/throngCrowd.mel"));
        QVERIFY(!mel.isEmpty());
        const QString text = mel.join('\n');
        for (const char* needed : {"global proc string throngCrowdLocators(string $dir, int $start)",
                                   "global proc string throngCrowdInstances(string $dir, int $start, string $model)",
                                   "/throng_cache.txt", "\"agent\"", "\"fps\"", "\"frames\"", "rotateY", "visibility"})
            QVERIFY2(text.contains(needed), needed);
        // Braces and parentheses balance: a script cut short would not source.
        QCOMPARE(text.count('{'), text.count('}'));
        QCOMPARE(text.count('('), text.count(')'));
    }
};

THRONG_REGISTER_TEST(TestCliMayaCache)
#include "TestCliMayaCache.moc"
