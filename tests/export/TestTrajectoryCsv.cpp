// The trajectory CSV and the per-agent text cache hold every recorded frame with the
// values a pipeline script reads back, and never leave a partial file behind.
#include "CrowdFixture.h"
#include "TestRegistry.h"

#include "export/AgentTextCache.h"
#include "export/TrajectoryCsv.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

using namespace throng;
using throng::test::CrowdFixture;

class TestTrajectoryCsv : public QObject {
    Q_OBJECT

    static QStringList readLines(const QString& path)
    {
        QFile file(path);
        if (!file.open(QIODevice::ReadOnly))
            return {};
        QStringList lines = QString::fromUtf8(file.readAll()).split('\n');
        if (!lines.isEmpty() && lines.last().isEmpty())
            lines.removeLast();  // the file ends with a newline
        return lines;
    }

    static float field(const QString& line, int column) { return line.split(',').at(column).toFloat(); }

    static QStringList entries(const QString& dir)
    {
        return QDir(dir).entryList(QDir::AllEntries | QDir::Hidden | QDir::NoDotAndDotDot);
    }

private slots:
    void headerAndOneRowPerAgentPerFrame()
    {
        const CrowdFixture fx = CrowdFixture::make();
        QTemporaryDir dir;
        const QString path = dir.filePath("run.csv");
        const exporting::ExportResult result = exporting::writeTrajectoryCsv(fx.cache, path.toStdString());
        QVERIFY2(result.ok(), result.error.c_str());
        QCOMPARE(result.writtenPaths, std::vector<std::string>{path.toStdString()});
        const QStringList lines = readLines(path);
        QCOMPARE(lines.size(), 1 + 3 * int(CrowdFixture::kFrames));
        QCOMPARE(lines.first(), QStringLiteral("frame,agent,x,y,z,heading,speed,clip,phase"));
        for (const QString& line : lines)
            QCOMPARE(line.count(','), 8);
        QCOMPARE(entries(dir.path()), QStringList{"run.csv"});  // no temporary file left over
    }

    // Row k is frame k / agents, agents by AgentId in the cache's dense order.
    void rowsAreFrameMajorWithAgentIds()
    {
        const CrowdFixture fx = CrowdFixture::make();
        QTemporaryDir dir;
        const QString path = dir.filePath("run.csv");
        QVERIFY(exporting::writeTrajectoryCsv(fx.cache, path.toStdString()).ok());
        const QStringList lines = readLines(path);
        const QStringList ids{"7", "42", "1000"};
        for (int k = 1; k < lines.size(); ++k) {
            const QStringList f = lines[k].split(',');
            QCOMPARE(f[0].toInt(), (k - 1) / 3);
            QCOMPARE(f[1], ids[(k - 1) % 3]);
        }
    }

    // Agent 42 runs north (-z) at 3 m/s from (5, 0.5, 2): one second in, it is at
    // (5, 0.5, -1), facing 90 degrees, running.
    void knownAgentAtKnownFrame()
    {
        const CrowdFixture fx = CrowdFixture::make();
        QTemporaryDir dir;
        const QString path = dir.filePath("run.csv");
        QVERIFY(exporting::writeTrajectoryCsv(fx.cache, path.toStdString()).ok());
        const QString row = readLines(path).at(1 + 24 * 3 + 1);
        QVERIFY2(row.startsWith("24,42,"), qPrintable(row));
        QCOMPARE(field(row, 2), 5.0f);
        QCOMPARE(field(row, 3), 0.5f);
        QVERIFY2(std::abs(field(row, 4) - -1.0f) < 1e-5f, qPrintable(row));
        QVERIFY2(std::abs(field(row, 5) - 90.0f) < 1e-4f, qPrintable(row));
        QCOMPARE(field(row, 6), 3.0f);
        QCOMPARE(row.split(',').at(7), QStringLiteral("run"));
        // Shortest round-trip text: what is read back is the recorded float, bit for bit.
        const sim::AgentFrame& a = fx.cache.at(24, 1);
        QCOMPARE(field(row, 4), a.position.z);
        QCOMPARE(field(row, 8), a.phase);
    }

    // Agent 1000 walks towards +x+z (south-east): heading -45 degrees; agent 7 faces +x: 0.
    void headingIsDegreesCounterClockwiseFromAbove()
    {
        const CrowdFixture fx = CrowdFixture::make();
        QTemporaryDir dir;
        const QString path = dir.filePath("run.csv");
        QVERIFY(exporting::writeTrajectoryCsv(fx.cache, path.toStdString()).ok());
        const QStringList lines = readLines(path);
        QCOMPARE(field(lines[1 + 10 * 3 + 0], 5), 0.0f);
        QVERIFY(std::abs(field(lines[1 + 10 * 3 + 2], 5) - -45.0f) < 1e-4f);
        QCOMPARE(field(lines[1 + 10 * 3 + 2], 4), fx.cache.at(10, 2).position.z);
    }

    void replacesAnExistingFileWhole()
    {
        const CrowdFixture fx = CrowdFixture::make();
        QTemporaryDir dir;
        const QString path = dir.filePath("run.csv");
        QFile old(path);
        QVERIFY(old.open(QIODevice::WriteOnly));
        old.write(QByteArray(1 << 20, 'x'));  // longer than the new table
        old.close();
        QVERIFY(exporting::writeTrajectoryCsv(fx.cache, path.toStdString()).ok());
        const QStringList lines = readLines(path);
        QCOMPARE(lines.size(), 1 + 3 * int(CrowdFixture::kFrames));
        QVERIFY(!lines.last().contains('x'));
        QCOMPARE(entries(dir.path()), QStringList{"run.csv"});
    }

    void cancelLeavesNoFile()
    {
        const CrowdFixture fx = CrowdFixture::make();
        QTemporaryDir dir;
        const QString path = dir.filePath("run.csv");
        int calls = 0;
        const exporting::ExportResult result =
            exporting::writeTrajectoryCsv(fx.cache, path.toStdString(), [&](float) { return ++calls < 10; });
        QVERIFY(!result.ok());
        QVERIFY(result.cancelled);
        QCOMPARE(calls, 10);
        QVERIFY(result.writtenPaths.empty());
        QCOMPARE(entries(dir.path()), QStringList{});
    }

    // The parent is a regular file: no user (root included) can create anything under it.
    void unwritablePathGivesErrorNamingIt()
    {
        const CrowdFixture fx = CrowdFixture::make();
        QTemporaryDir dir;
        QFile blocker(dir.filePath("plain-file"));
        QVERIFY(blocker.open(QIODevice::WriteOnly));
        blocker.close();
        const std::string csv = dir.filePath("plain-file/run.csv").toStdString();
        const exporting::ExportResult result = exporting::writeTrajectoryCsv(fx.cache, csv);
        QVERIFY(!result.ok());
        QVERIFY2(result.error.find(csv) != std::string::npos, result.error.c_str());
        const std::string cacheDir = dir.filePath("plain-file/cache").toStdString();
        const exporting::ExportResult cache = exporting::writeAgentTextCache(fx.cache, cacheDir);
        QVERIFY(!cache.ok());
        QVERIFY2(cache.error.find(cacheDir) != std::string::npos, cache.error.c_str());
        QCOMPARE(entries(dir.path()), QStringList{"plain-file"});
    }

    // One `x y z rotYdeg speed` line per frame in agent_<id>.txt, named by AgentId.
    void agentTextCacheHasOneFilePerAgent()
    {
        const CrowdFixture fx = CrowdFixture::make();
        QTemporaryDir dir;
        const QString cacheDir = dir.filePath("cache/shot1");
        const exporting::ExportResult result = exporting::writeAgentTextCache(fx.cache, cacheDir.toStdString());
        QVERIFY2(result.ok(), result.error.c_str());
        QCOMPARE(result.writtenPaths.size(), std::size_t(3));
        QStringList files = entries(cacheDir);
        files.sort();
        QCOMPARE(files, (QStringList{"agent_1000.txt", "agent_42.txt", "agent_7.txt"}));
        for (const QString& f : files)
            QCOMPARE(readLines(QDir(cacheDir).filePath(f)).size(), int(CrowdFixture::kFrames));

        const QStringList values = readLines(QDir(cacheDir).filePath("agent_42.txt")).at(24).split(' ');
        QCOMPARE(values.size(), 6);
        QCOMPARE(values[0].toFloat(), 5.0f);
        QCOMPARE(values[1].toFloat(), 0.5f);
        QVERIFY(std::abs(values[2].toFloat() - -1.0f) < 1e-5f);
        QVERIFY(std::abs(values[3].toFloat() - 90.0f) < 1e-4f);
        QCOMPARE(values[4].toFloat(), 3.0f);
        QCOMPARE(values[5], QString("run"));  // the runner runs, as the CSV says
        const QStringList last = readLines(QDir(cacheDir).filePath("agent_7.txt")).last().split(' ');
        QCOMPARE(last[0].toFloat(), fx.cache.at(CrowdFixture::kFrames - 1, 0).position.x);
        QVERIFY(std::abs(last[0].toFloat() - 2.4f) < 1e-5f);  // 1.2 m/s for 2 s
    }

    void agentTextCacheCancelLeavesNothing()
    {
        const CrowdFixture fx = CrowdFixture::make();
        QTemporaryDir dir;
        const QString cacheDir = dir.filePath("cache");
        int calls = 0;
        const exporting::ExportResult result = exporting::writeAgentTextCache(
            fx.cache, cacheDir.toStdString(), [&](float) { return ++calls < 3; });  // after two files
        QVERIFY(result.cancelled);
        QVERIFY(!QFileInfo::exists(cacheDir));  // it created the directory, so it removed it

        QVERIFY(QDir(dir.path()).mkdir("existing"));
        calls = 0;
        const QString existing = dir.filePath("existing");
        QVERIFY(exporting::writeAgentTextCache(fx.cache, existing.toStdString(), [&](float) { return ++calls < 4; })
                    .cancelled);
        QCOMPARE(entries(existing), QStringList{});
    }
};

THRONG_REGISTER_TEST(TestTrajectoryCsv)
#include "TestTrajectoryCsv.moc"
