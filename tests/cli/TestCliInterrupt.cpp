// Ctrl-C and SIGTERM stop throng-cli cleanly, as a user stops a long run: sent to the real
// program while it simulates, while it writes an export and while a wedge runs, each stops
// within seconds with 128 + the signal, says what it did not write, and leaves no partial
// or staging file; outputs finished before the signal stay whole.
#include "TestRegistry.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <signal.h>
#include <sys/types.h>

namespace {

// A crowd of `count` walkers in a 100 m square, walking to an exit far to the east.
QString writeFarCrowd(const QString& path, int count)
{
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        qFatal("cannot write %s", qPrintable(path));
    f.write(QString("throng: 1\n"
                    "settings: {fps: 24, duration: 10, seed: 5}\n"
                    "agent_types: [{name: walker, radius: 0.25, max_speed: 1.3}]\n"
                    "goals: [{name: exit, position: [400, 0], radius: 2, exit: true}]\n"
                    "groups: [{name: crowd, type: walker, count: %1, rect: {min: [-50, -50], max: [50, 50]}, "
                    "goal: exit}]\n")
                .arg(count)
                .toUtf8());
    return path;
}

// Starts `throng-cli run` on a crowd of `walkers` (in `tmp`) for `frames` frames, each
// output (flag, file name) into the folder tmp/out, which it makes. Returns the folder.
QString startRun(QProcess& p, const QTemporaryDir& tmp, int walkers, int frames,
                 const QList<QPair<QString, QString>>& outputs)
{
    const QString scene = writeFarCrowd(tmp.filePath("crowd.yaml"), walkers);
    const QString out = tmp.filePath("out");
    if (!QDir().mkpath(out))
        qFatal("cannot make %s", qPrintable(out));
    QStringList args{"run", scene, "--frames", QString::number(frames)};
    for (const auto& [flag, name] : outputs)
        args << flag << out + "/" + name;
    p.start(QStringLiteral(THRONG_CLI_PATH), args);
    return out;
}

// Reads `p`'s standard error until it holds `marker` (true), the process ends or 60 s pass.
bool waitForStderr(QProcess& p, QString& err, const QString& marker)
{
    QElapsedTimer clock;
    clock.start();
    while (!err.contains(marker) && clock.elapsed() < 60000 && p.state() != QProcess::NotRunning) {
        p.waitForReadyRead(200);
        err += QString::fromUtf8(p.readAllStandardError());
    }
    return err.contains(marker);
}

// The exit code of `p` once it ends (within 60 s), -1 if it crashed or did not end.
int endOf(QProcess& p, QString& err)
{
    if (!p.waitForFinished(60000)) {
        p.kill();
        p.waitForFinished();
        return -1;
    }
    err += QString::fromUtf8(p.readAllStandardError());
    return p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
}

// The pids of `pid`'s children.
QList<qint64> childPids(qint64 pid)
{
    QFile f(QString("/proc/%1/task/%1/children").arg(pid));
    QList<qint64> out;
    if (f.open(QIODevice::ReadOnly))
        for (const QByteArray& word : f.readAll().simplified().split(' '))
            if (!word.isEmpty())
                out.push_back(word.toLongLong());
    return out;
}

// Whether `pid` has a handler of its own for `signal` (its SigCgt mask in /proc).
bool hasHandlerFor(qint64 pid, int signal)
{
    QFile f(QString("/proc/%1/status").arg(pid));
    if (!f.open(QIODevice::ReadOnly))
        return false;
    for (const QByteArray& line : f.readAll().split('\n'))
        if (line.startsWith("SigCgt:"))
            return (line.mid(7).trimmed().toULongLong(nullptr, 16) >> (signal - 1)) & 1u;
    return false;
}

QStringList entriesIn(const QString& dir)
{
    return QDir(dir).entryList(QDir::AllEntries | QDir::NoDotAndDotDot | QDir::Hidden, QDir::Name);
}

}  // namespace

class TestCliInterrupt : public QObject {
    Q_OBJECT
private slots:
    // Ctrl-C while it simulates: nothing of the run's outputs is written.
    void ctrlCWhileSimulatingWritesNothing()
    {
        QTemporaryDir tmp;
        QProcess p;
        const QString out =
            startRun(p, tmp, 2000, 100000, {{"--export", "a.glb"}, {"--export", "b.csv"}, {"--stats", "s.json"}});
        QString err;
        // Its progress says it is stepping (two thousand walkers for 100,000 frames: hours).
        QVERIFY2(waitForStderr(p, err, "simulating: 0%"), qPrintable(err));
        QElapsedTimer clock;
        clock.start();
        QCOMPARE(::kill(pid_t(p.processId()), SIGINT), 0);
        QCOMPARE(endOf(p, err), 128 + SIGINT);
        QVERIFY2(clock.elapsed() < 10000, qPrintable(QString::number(clock.elapsed())));
        QVERIFY2(err.contains(QRegularExpression("stopped by SIGINT \\(Ctrl-C\\) at frame [0-9]+ of 100000; nothing "
                                                 "was written")),
                 qPrintable(err));
        QCOMPARE(entriesIn(out), QStringList());
    }

    // SIGTERM while it writes its second export: the first stays whole, the second and the
    // stats are not written, and no staging file is left.
    void sigtermWhileExportingKeepsOnlyWhatWasDone()
    {
        QTemporaryDir tmp;
        QProcess p;
        // 5,000 walkers for 120 frames: an export with progress (half a million agent-frames).
        const QString out =
            startRun(p, tmp, 5000, 120, {{"--export", "a.csv"}, {"--export", "b.glb"}, {"--stats", "s.json"}});
        QString err;
        QVERIFY2(waitForStderr(p, err, "exporting " + out + "/b.glb: 0%"), qPrintable(err));
        QCOMPARE(::kill(pid_t(p.processId()), SIGTERM), 0);
        QCOMPARE(endOf(p, err), 128 + SIGTERM);
        QVERIFY2(err.contains("stopped by SIGTERM; " + out + "/b.glb and the outputs after it were not written"),
                 qPrintable(err));
        QCOMPARE(entriesIn(out), QStringList{"a.csv"});
        // The first export is whole: a header and a row per walker and frame.
        QFile csv(out + "/a.csv");
        QVERIFY(csv.open(QIODevice::ReadOnly));
        QCOMPARE(csv.readAll().count('\n'), 1 + 5000 * 120);
    }

    // SIGTERM to a wedge: the variant running stops cleanly, no other starts, nothing is
    // collected.
    void sigtermStopsAWedgeAndItsVariants()
    {
        QTemporaryDir tmp;
        const QString scene = writeFarCrowd(tmp.filePath("crowd.yaml"), 2000);
        const QString dir = tmp.filePath("wedge");
        QProcess p;
        p.start(QStringLiteral(THRONG_CLI_PATH),
                {"wedge", scene, "--seeds", "1..3", "--frames", "100000", "--out", dir, "--jobs", "1"});
        QVERIFY(p.waitForStarted());
        // Wait for the first variant to be running with its own handler in place.
        QElapsedTimer clock;
        clock.start();
        qint64 variant = 0;
        while (clock.elapsed() < 60000 && variant == 0) {
            for (const qint64 child : childPids(p.processId()))
                if (hasHandlerFor(child, SIGTERM))
                    variant = child;
            QTest::qWait(50);
        }
        QVERIFY(variant != 0);
        QCOMPARE(::kill(pid_t(p.processId()), SIGTERM), 0);
        QString err;
        QCOMPARE(endOf(p, err), 128 + SIGTERM);
        QVERIFY2(err.contains("stopped by SIGTERM; 1 of 3 variants ended"), qPrintable(err));
        // The variant stopped itself (its log says so) and was waited for (its status).
        QFile log(dir + "/v000/run.log");
        QVERIFY(log.open(QIODevice::ReadOnly));
        QVERIFY2(log.readAll().contains("stopped by SIGTERM at frame"), "the variant did not stop itself");
        QFile status(dir + "/v000/status");
        QVERIFY(status.open(QIODevice::ReadOnly));
        QCOMPARE(status.readAll().trimmed(), QByteArray::number(128 + SIGTERM));
        QVERIFY(!QFile::exists(dir + "/v000/stats.json"));
        QCOMPARE(entriesIn(dir + "/v001"), QStringList());
        QCOMPARE(entriesIn(dir + "/v002"), QStringList());
        QVERIFY(!QFile::exists(dir + "/wedge.csv"));
        QVERIFY(!QDir("/proc/" + QString::number(variant)).exists());
    }
};

THRONG_REGISTER_TEST(TestCliInterrupt)
#include "TestCliInterrupt.moc"
