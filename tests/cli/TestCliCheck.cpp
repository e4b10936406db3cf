// `throng-cli check`, `--help`, `--version` and usage errors, as a user or a pipeline
// script sees them: exit status and compiler-style messages.
#include "CliRunner.h"
#include "TestRegistry.h"

#include <QDir>
#include <QFile>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

using throng::test::runCli;

class TestCliCheck : public QObject {
    Q_OBJECT
private slots:
    void validDemoScenes_data()
    {
        QTest::addColumn<QString>("path");
        const QDir dir(QStringLiteral(THRONG_SOURCE_DIR "/resources/scenes"));
        for (const QString& f : dir.entryList({"*.yaml"}, QDir::Files))
            QTest::newRow(qPrintable(f)) << dir.filePath(f);
    }

    void validDemoScenes()
    {
        QFETCH(QString, path);
        const auto r = runCli({"check", path.toStdString()});
        QCOMPARE(r.status, 0);
        QVERIFY(r.out.find(": valid (") != std::string::npos);
        QVERIFY2(r.err.empty(), r.err.c_str());
    }

    // Every broken file fails with exit status 1 and messages file:line:col: error: key: ...
    void everyBrokenFileIsRejected()
    {
        const QDir dir(QStringLiteral(THRONG_TEST_DATA_DIR "/broken"));
        const QRegularExpression format(R"(^(.+):(\d+):(\d+): (error|warning): .+$)");
        QFile manifest(dir.filePath("EXPECTED.tsv"));
        QVERIFY(manifest.open(QIODevice::ReadOnly | QIODevice::Text));
        const QString expected = QString::fromUtf8(manifest.readAll());
        int checked = 0;
        for (const QString& f : dir.entryList({"*.yaml"}, QDir::Files)) {
            const auto r = runCli({"check", dir.filePath(f).toStdString()});
            QVERIFY2(expected.contains(f + "\t"), qPrintable(f + " is not in EXPECTED.tsv"));
            const bool expectValid = expected.contains(f + "\tvalid\t");
            QCOMPARE(r.status, expectValid ? 0 : 1);
            const QStringList lines = QString::fromStdString(r.err).split('\n', Qt::SkipEmptyParts);
            QVERIFY2(!lines.isEmpty(), qPrintable(f));
            for (const QString& line : lines) {
                const auto m = format.match(line);
                QVERIFY2(m.hasMatch(), qPrintable(f + ": " + line));
                QCOMPARE(m.captured(1), dir.filePath(f));
                QVERIFY(m.captured(2).toInt() >= 1);
            }
            ++checked;
        }
        QVERIFY(checked >= 15);
    }

    void reportsEveryErrorAndASummary()
    {
        QTemporaryDir tmp;
        const QString path = throng::test::writeText(tmp.filePath("two.yaml"), "throng: 1\nagent_types:\n  - {name: a, radius: -1}\n"
                                                   "agents:\n  - {type: b, position: [0, 0]}\n");
        const auto r = runCli({"check", path.toStdString()});
        QCOMPARE(r.status, 1);
        QVERIFY(r.err.find(":3:23: error: agent_types[0].radius:") != std::string::npos);
        QVERIFY(r.err.find(":5:12: error: agents[0].type: no agent type named 'b'") != std::string::npos);
        QVERIFY(r.out.find("invalid: 2 errors, 0 warnings") != std::string::npos);
    }

    // A brain is compiled by check: a compiler error and a sensor the World cannot fill
    // are errors at their nodes; run refuses the scene instead of running it silently.
    void brainErrorsNameTheNode()
    {
        QTemporaryDir tmp;
        const QString path = throng::test::writeText(tmp.filePath("brains.yaml"), R"(throng: 1
agent_types: [{name: w, brain: broken}]
brains:
  - name: broken
    nodes:
      - {id: 1, type: input, params: {sensor: sound_bearing, channel: bell}}
      - {id: 2, type: fuzz.triangle, params: {points: [0, 1, 2]}}
      - {id: 3, type: output, params: {channel: speed}}
    links:
      - {from: [1, 0], to: [3, 0]}
agents: [{type: w, position: [0, 0]}]
)");
        auto r = runCli({"check", path.toStdString()});
        QCOMPARE(r.status, 1);
        QVERIFY2(r.err.find("brains.yaml:7:9: error: brains[0]: node 2 (fuzz.triangle): input 0 'x' is not connected") !=
                     std::string::npos, r.err.c_str());
        QVERIFY(r.out.find("invalid: 1 error") != std::string::npos);
        r = runCli({"run", path.toStdString(), "--frames", "3"});
        QCOMPARE(r.status, 1);
        QVERIFY2(r.err.find("nothing was run") != std::string::npos, r.err.c_str());

        // Fixed, the sound sensor is fine (the World provides it); an attribute agents do
        // not have is an error at its node.
        const QString fixed = throng::test::writeText(tmp.filePath("fixed.yaml"), R"(throng: 1
agent_types: [{name: w, brain: deaf}]
brains:
  - name: deaf
    nodes:
      - {id: 1, type: input, params: {sensor: sound_bearing, channel: bell}}
      - {id: 3, type: output, params: {channel: turn}}
    links:
      - {from: [1, 0], to: [3, 0]}
agents: [{type: w, position: [0, 0]}]
)");
        r = runCli({"check", fixed.toStdString()});
        QCOMPARE(r.status, 0);
        const QString vague = throng::test::writeText(tmp.filePath("vague.yaml"), R"(throng: 1
agent_types: [{name: w, brain: vague}]
brains:
  - name: vague
    nodes:
      - {id: 1, type: input, params: {sensor: attribute, name: wingspan}}
      - {id: 3, type: output, params: {channel: turn}}
    links:
      - {from: [1, 0], to: [3, 0]}
agents: [{type: w, position: [0, 0]}]
)");
        r = runCli({"check", vague.toStdString()});
        QCOMPARE(r.status, 1);
        QVERIFY2(r.err.find("vague.yaml:6:9: error: brains[0]: node 1 (input): attribute 'wingspan' is not an agent attribute") !=
                     std::string::npos, r.err.c_str());
    }

    void missingFile()
    {
        const auto r = runCli({"check", "/no/such/scene.yaml"});
        QCOMPARE(r.status, 1);
        QCOMPARE(QString::fromStdString(r.err).trimmed(), QString("/no/such/scene.yaml: error: no such file"));
    }

    void helpAndVersion()
    {
        auto r = runCli({"--help"});
        QCOMPARE(r.status, 0);
        for (const char* word : {"check SCENE", "run SCENE", "--frames", "--seed", "--threads", "--stats",
                                 "--trajectories", "--export", "bench", "--quiet"})
            QVERIFY2(r.out.find(word) != std::string::npos, word);
        r = runCli({"--version"});
        QCOMPARE(r.status, 0);
        QVERIFY(r.out.rfind("throng-cli ", 0) == 0);
    }

    void usageErrors_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        QTest::newRow("nothing") << QStringList{} << "no command given";
        QTest::newRow("unknown command") << QStringList{"simulate", "x.yaml"} << "unknown command 'simulate'";
        QTest::newRow("unknown option") << QStringList{"run", "x.yaml", "--fast"} << "unknown option '--fast'";
        QTest::newRow("missing value") << QStringList{"run", "x.yaml", "--frames"} << "--frames needs a value";
        QTest::newRow("bad number") << QStringList{"run", "x.yaml", "--frames", "ten"} << "needs a whole number";
        QTest::newRow("negative threads") << QStringList{"run", "x.yaml", "--threads", "-2"} << "needs a whole number";
        QTest::newRow("two scenes") << QStringList{"check", "a.yaml", "b.yaml"} << "exactly one SCENE";
        QTest::newRow("run option on check") << QStringList{"check", "a.yaml", "--stats", "s.json"} << "belong to 'run'";
        QTest::newRow("unknown scenario") << QStringList{"bench", "--scenario", "zoo", "--quiet"} << "unknown scenario";
        QTest::newRow("window of 0") << QStringList{"bench", "--window", "0", "--quiet"}
                                     << "--window needs a whole number >= 1";
        QTest::newRow("window on run") << QStringList{"run", "x.yaml", "--window", "10"}
                                       << "--window belongs to 'bench'";
    }

    void usageErrors()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        std::vector<std::string> a;
        for (const QString& s : args)
            a.push_back(s.toStdString());
        const auto r = runCli(a);
        QCOMPARE(r.status, 2);
        const QString err = QString::fromStdString(r.err);
        QVERIFY2(err.contains(message), r.err.c_str());
        // The mistake stays in view: its line and where help is, not the whole usage. A bare
        // throng-cli gets the usage.
        if (a.empty()) {
            QVERIFY2(err.contains("commands:") && err.contains("run SCENE"), r.err.c_str());
        } else {
            QVERIFY2(err.trimmed().split('\n').size() <= 2 && !err.contains("commands:"), r.err.c_str());
            QVERIFY2(err.startsWith("throng-cli: "), r.err.c_str());
        }
    }

    // A mistyped option: the line that says so and where help is, nothing else.
    void aMistakeStaysInView()
    {
        const auto r = runCli({"run", "x.yaml", "--fast"});
        QCOMPARE(r.status, 2);
        QCOMPARE(QString::fromStdString(r.err),
                 QString("throng-cli: unknown option '--fast'\n"
                         "throng-cli: 'throng-cli --help' lists the commands and their options\n"));
    }
};

THRONG_REGISTER_TEST(TestCliCheck)
#include "TestCliCheck.moc"
