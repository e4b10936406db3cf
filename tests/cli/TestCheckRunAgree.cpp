// `throng-cli check` and `throng-cli run` give the same verdict on every file: the
// shipped scenes, the test scenes, every hand-made broken file, and the cases where they
// used to differ. What a user saw before: a scene holding a broken brain that no agent
// runs was refused by `check` (exit 1) yet run fine with `run` (exit 0), and the files
// that crashed `run` were all accepted by `check`.
#include "CliRunner.h"
#include "TestRegistry.h"

#include <QDir>
#include <QTemporaryDir>
#include <QTest>

using throng::test::runCli;
using throng::test::writeText;

class TestCheckRunAgree : public QObject {
    Q_OBJECT

    static void agree(const QString& path, int expected)
    {
        const auto check = runCli({"check", path.toStdString()});
        const auto run = runCli({"run", path.toStdString(), "--frames", "3", "--quiet", "--threads", "1"});
        const std::string what = path.toStdString() + "\ncheck: " + check.out + check.err + "\nrun: " + run.out + run.err;
        QVERIFY2((check.status == 0) == (run.status == 0), what.c_str());
        if (expected >= 0)
            QVERIFY2(check.status == expected, what.c_str());
    }

private slots:
    void everyFileGetsOneVerdict_data()
    {
        QTest::addColumn<QString>("path");
        for (const QString& d : {QStringLiteral(THRONG_SOURCE_DIR "/resources/scenes"), QStringLiteral(THRONG_TEST_DATA_DIR "/scenes"),
                                 QStringLiteral(THRONG_TEST_DATA_DIR "/broken")}) {
            const QDir dir(d);
            for (const QString& f : dir.entryList({"*.yaml"}, QDir::Files))
                if (!f.endsWith(".brain.yaml"))
                    QTest::newRow(qPrintable(dir.dirName() + "/" + f)) << dir.filePath(f);
        }
    }

    void everyFileGetsOneVerdict()
    {
        QFETCH(QString, path);
        agree(path, -1);
    }

    void aBrokenBrainNoAgentRunsIsAWarning()
    {
        QTemporaryDir tmp;
        const QString path = writeText(tmp.filePath("idle.yaml"), R"(throng: 1
brains:
  - name: draft
    nodes:
      - {id: 1, type: fuzz.triangle}
agent_types:
  - {name: walker}
agents:
  - {id: 1, type: walker, position: [0, 0]}
)");
        agree(path, 0);
        const auto check = runCli({"check", path.toStdString()});
        QVERIFY2(check.err.find("idle.yaml:5:9: warning: brains[0]: brain 'draft' is run by no agent") != std::string::npos,
                 check.err.c_str());
        // Once an agent type runs it, both refuse it.
        const QString used = writeText(tmp.filePath("used.yaml"), R"(throng: 1
brains:
  - name: draft
    nodes:
      - {id: 1, type: fuzz.triangle}
agent_types:
  - {name: walker, brain: draft}
agents:
  - {id: 1, type: walker, position: [0, 0]}
)");
        agree(used, 1);
    }

    void sizesThatExhaustMemoryAreRefusedByBoth()
    {
        QTemporaryDir tmp;
        const QString path = writeText(tmp.filePath("tiny-cells.yaml"), R"(throng: 1
settings: {nav_cell: 0.001}
agent_types:
  - {name: walker, navigation: astar}
goals:
  - {name: exit, position: [10, 0]}
agents:
  - {id: 1, type: walker, position: [0, 0], goal: exit}
)");
        agree(path, 1);
        const auto check = runCli({"check", path.toStdString()});
        QVERIFY2(check.err.find("tiny-cells.yaml:2:22: error: settings.nav_cell: the navigation grid would need") !=
                     std::string::npos,
                 check.err.c_str());
    }
};

THRONG_REGISTER_TEST(TestCheckRunAgree)
#include "TestCheckRunAgree.moc"
