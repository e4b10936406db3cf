// `throng-cli validate` (issue 26): the RiMEA tests that apply to one level run on their
// scenes in resources/validation and pass, each line saying its criterion and what was
// measured; the others say why they do not run; a scene that breaks a criterion fails
// the command, and one that does not load names its file and line.
#include "CliRunner.h"
#include "TestRegistry.h"

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <functional>
#include <map>

using throng::test::runCli;

namespace validate_test {

const QString kDir = QStringLiteral(THRONG_SOURCE_DIR "/resources/validation");

// The JSON lines of a run, by test number.
std::map<int, QJsonObject> byTest(const std::string& out)
{
    std::map<int, QJsonObject> tests;
    for (const QString& line : QString::fromStdString(out).split('\n', Qt::SkipEmptyParts)) {
        const QJsonObject o = QJsonDocument::fromJson(line.toUtf8()).object();
        tests[o["test"].toInt()] = o;
    }
    return tests;
}

// The first number in `text` after `after`.
double numberAfter(const QString& text, const QString& after)
{
    const QRegularExpression number(QRegularExpression::escape(after) + R"(\s*([0-9]+(\.[0-9]+)?))");
    const auto m = number.match(text);
    return m.hasMatch() ? m.captured(1).toDouble() : -1.0;
}

}  // namespace validate_test

using namespace validate_test;

class TestCliValidate : public QObject {
    Q_OBJECT
private slots:
    void theScenesAreValid()
    {
        const QStringList files = QDir(kDir).entryList({"*.yaml"}, QDir::Files);
        QVERIFY(files.size() >= 4);
        for (const QString& f : files) {
            const auto r = runCli({"check", QDir(kDir).filePath(f).toStdString()});
            QVERIFY2(r.status == 0 && r.err.empty(), qPrintable(f + ": " + QString::fromStdString(r.err)));
        }
    }

    void theTestsThatApplyPass()
    {
        const auto r = runCli({"validate", "--json", "--quiet"});
        QVERIFY2(r.status == 0, r.out.c_str());
        const std::map<int, QJsonObject> tests = byTest(r.out);
        QCOMPARE(int(tests.size()), 16);  // the guideline's pack, 1 to 16
        for (const auto& [number, o] : tests) {
            qInfo("RiMEA %d: %s: %s", number, qPrintable(o["result"].toString()), qPrintable(o["measured"].toString()));
            if (number == 1 || number == 4 || number == 5 || number == 6 || number == 7 || number == 9 ||
                number == 10 || number == 11 || number == 12 || number == 15 || number == 16) {
                QCOMPARE(o["result"].toString(), QString("pass"));
                QVERIFY(!o["criterion"].toString().isEmpty());
            } else {
                QCOMPARE(o["result"].toString(), QString("not run"));
                QVERIFY2(!o["reason"].toString().isEmpty(), qPrintable(QString::number(number)));
            }
        }
        for (const int stairs : {2, 3, 13})
            QVERIFY(tests.at(stairs)["reason"].toString().contains("levels"));
        // Test 4: six densities up to 4 /m2 and more, each speed near Weidmann's, each below the last.
        const QStringList points = tests.at(4)["measured"].toString().split("; ");
        QCOMPARE(points.size(), 6);
        double slower = 10.0;
        for (const QString& p : points) {
            const double speed = numberAfter(p, "/m2:");
            const double weidmann = numberAfter(p, "(Weidmann");
            QVERIFY2(std::abs(speed - weidmann) <= 0.15 && speed < slower && weidmann >= 0.0, qPrintable(p));
            slower = speed;
        }
        QVERIFY2(numberAfter(points.back(), "") >= 4.0, qPrintable(points.back()));
        // 40 m at 1.33 m/s is 30.08 s, and a walker keeps its speed.
        const double corridor = numberAfter(tests.at(1)["measured"].toString(), "");
        QVERIFY2(corridor > 29.5 && corridor < 31.0, qPrintable(QString::number(corridor)));
        QVERIFY2(tests.at(5)["measured"].toString().startsWith(
                     "10 of 10 set off within 0.25 s after their reaction time (times "),
                 qPrintable(tests.at(5)["measured"].toString()));
        QVERIFY(tests.at(5)["measured"].toString().endsWith("; 10 out"));
        QVERIFY2(tests.at(7)["measured"].toString().startsWith(
                     "50 of 50 within 0.03 m/s of Weidmann's speed for their age"),
                 qPrintable(tests.at(7)["measured"].toString()));
        QVERIFY(tests.at(6)["measured"].toString().startsWith("20 of 20 round the corner"));
        QVERIFY(tests.at(6)["measured"].toString().contains(", 0 steps through a wall (the World counts 0)"));
        const double ratio = numberAfter(tests.at(9)["measured"].toString(), "with two:");
        QVERIFY2(ratio >= 1.6 && ratio <= 2.4, qPrintable(tests.at(9)["measured"].toString()));
        QVERIFY(tests.at(10)["measured"].toString().startsWith(
            "24 of 24 left by their own exit (16 of them assigned the farther one); 24 out after"));
        QVERIFY2(tests.at(11)["measured"].toString().contains("; all 1000 out after"),
                 qPrintable(tests.at(11)["measured"].toString()));
        QVERIFY(numberAfter(tests.at(11)["measured"].toString(), "near exit,") >= 100.0);
        // Test 12: six widths, each flow above the last, a queue in front and none behind.
        const QString neck = tests.at(12)["measured"].toString();
        const QStringList widths = neck.split("; ");
        QCOMPARE(widths.size(), 6);
        double last = 0.0;
        for (const QString& w : widths) {
            const double flow = numberAfter(w, "m:"), front = numberAfter(w, "/m/s),");
            const double behind = numberAfter(w, "in front and");
            QVERIFY2(flow > last && front >= 2.0 && behind < 0.5 * front, qPrintable(w));
            last = flow;
        }
        QVERIFY(tests.at(15)["measured"].toString().startsWith("500 of 500 out in"));
        QVERIFY(tests.at(15)["measured"].toString().contains(", 0 steps through a wall (the World counts 0)"));
        // Test 16: four densities from 0.5 to 2 per metre, each speed within 0.1 m/s of
        // (1/rho - 0.36) / 1.06 (at most the free speed), recomputed here from the density
        // the line reports, each below the last.
        const QStringList file = tests.at(16)["measured"].toString().split("; ");
        QCOMPARE(file.size(), 4);
        double before = 10.0;
        for (const QString& p : file) {
            const double rho = numberAfter(p, ""), speed = numberAfter(p, "/m:");
            const double seyfried = std::clamp((1.0 / rho - 0.36) / 1.06, 0.0, 1.34);
            QVERIFY2(std::abs(numberAfter(p, "(Seyfried") - seyfried) < 0.012, qPrintable(p));  // both printed to 0.01
            QVERIFY2(std::abs(speed - seyfried) <= 0.1 && speed < before, qPrintable(p));
            before = speed;
        }
        QVERIFY2(numberAfter(file.front(), "") < 0.6 && numberAfter(file.back(), "") > 1.9,
                 qPrintable(file.join("; ")));
    }

    // The same corridor with a walker at 1 m/s takes 40 s: test 1 fails, and so does the
    // command; a corner scene with a mistake names its file and line.
    void aSceneThatBreaksItsCriterionFails()
    {
        QTemporaryDir dir;
        QFile corridor(kDir + "/rimea-01-corridor.yaml");
        QVERIFY(corridor.open(QIODevice::ReadOnly));
        QByteArray text = corridor.readAll();
        QVERIFY(text.contains("max_speed: 1.33"));
        text.replace("max_speed: 1.33", "max_speed: 1.0");
        QFile slow(dir.filePath("rimea-01-corridor.yaml"));
        QVERIFY(slow.open(QIODevice::WriteOnly));
        slow.write(text);
        slow.close();
        throng::test::writeText(dir.filePath("rimea-06-corner.yaml"), "throng: 1\nagent_types:\n  - {name: w, radius: -1}\n");
        const auto r = runCli({"validate", dir.path().toStdString(), "--quiet"});
        QCOMPARE(r.status, 1);
        const QString out = QString::fromStdString(r.out);
        QVERIFY2(out.contains("RiMEA 1: Corridor: walking speed kept: FAIL\n"), qPrintable(out));
        const double seconds = numberAfter(out, "measured:");
        QVERIFY2(seconds > 39.0 && seconds < 41.0, qPrintable(out));
        QVERIFY2(out.contains("RiMEA 6: Corner: FAIL (" + dir.filePath("rimea-06-corner.yaml") + ":3:"), qPrintable(out));
        QVERIFY(out.contains("RiMEA 9: Four against two exits: FAIL (" + dir.filePath("rimea-09-four-exits.yaml")));
        // Tests 10, 12 and 15 have no scenes in the folder: each names its missing file.
        QVERIFY(out.contains("RiMEA 10: Assigned exits: FAIL (" + dir.filePath("rimea-10-assigned-exits.yaml")));
        QVERIFY2(out.contains("0 passed, 11 failed, 5 not run\n"), qPrintable(out));
    }

    // Each newer test fails on a scene that breaks it: walkers that do not slow in a crowd (4)
    // or in single file (16);
    // walkers who all set off at once (5); a
    // crowd whose speeds do not follow its ages (7); a crowd all sent to the near exit (11);
    // a corridor whose east end is walled
    // off keeps the walkers assigned to it in (10); a room with no passage makes no queue
    // and the same flow at every width (12); a corridor walled off past the corner lets
    // nobody out (15).
    void scenesThatBreakTheNewerTestsFail()
    {
        QTemporaryDir dir;
        auto copy = [&](const QString& name, const std::function<QByteArray(const QByteArray&)>& edit) {
            QFile in(kDir + "/" + name);
            QVERIFY(in.open(QIODevice::ReadOnly));
            const QByteArray text = in.readAll(), edited = edit(text);
            QVERIFY2(edited != text, qPrintable(name));
            QFile out(dir.filePath(name));
            QVERIFY(out.open(QIODevice::WriteOnly));
            out.write(edited);
        };
        auto addWall = [](const char* wall) {
            return [wall](QByteArray text) {
                return text.replace("walls:\n", QByteArray("walls:\n  - ") + wall + "\n");
            };
        };
        copy("rimea-05-reaction-times.yaml", [](QByteArray text) {
            return text.replace("variation: {reaction: [10, 100]}", "variation: {reaction: [0, 0]}");
        });
        copy("rimea-07-walking-speed-by-age.yaml", [](QByteArray text) {
            return text.replace("variation: {speed: [1, 1], age: [20, 80]}", "variation: {speed: [0.8, 1.2]}");
        });
        // Walkers that do not slow with the density ahead (direct navigation has no rule for it).
        copy("rimea-04-fundamental-diagram.yaml", [](QByteArray text) {
            return text.replace("navigation: flow_field", "navigation: direct");
        });
        // Walkers in single file that keep no time gap walk on at their free speed however close.
        copy("rimea-16-single-file.yaml", [](QByteArray text) { return text.replace(", time_gap: 1.06", ""); });
        copy("rimea-11-exit-choice.yaml", [](QByteArray text) {
            return text.replace("exits: [west_exit, east_exit]", "goal: west_exit");
        });
        copy("rimea-10-assigned-exits.yaml", addWall("{points: [[38, -1], [38, 1]]}"));
        copy("rimea-15-large-crowd-corner.yaml", addWall("{points: [[36, -20], [42, -20]]}"));
        copy("rimea-12-bottleneck.yaml", [](const QByteArray& text) {
            QByteArray open;
            for (const QByteArray& line : text.split('\n'))
                if (!line.contains("name: front_") && !line.contains("name: neck_"))
                    open += line + "\n";
            return open;
        });
        const auto r = runCli({"validate", dir.path().toStdString(), "--quiet"});
        QCOMPARE(r.status, 1);
        const QString out = QString::fromStdString(r.out);
        QVERIFY2(out.contains("RiMEA 5: Reaction times: FAIL\n"), qPrintable(out));
        QVERIFY2(out.contains(QRegularExpression("measured: +0 of 10 set off within 0.25 s")), qPrintable(out));
        QVERIFY2(out.contains("RiMEA 7: Walking speed by age: FAIL\n"), qPrintable(out));
        QVERIFY2(out.contains("RiMEA 10: Assigned exits: FAIL\n"), qPrintable(out));
        QVERIFY2(out.contains("RiMEA 11: Exit choice under congestion: FAIL\n"), qPrintable(out));
        QVERIFY2(out.contains(QRegularExpression("measured: +[0-9]+ by the near exit, 0 by the far one")),
                 qPrintable(out));
        QVERIFY2(out.contains("RiMEA 4: Fundamental diagram: FAIL\n"), qPrintable(out));
        QVERIFY2(out.contains(QRegularExpression("measured: +1[0-9] of 24 left by their own exit")), qPrintable(out));
        QVERIFY2(out.contains("RiMEA 12: Bottleneck: FAIL\n"), qPrintable(out));
        QVERIFY2(out.contains("RiMEA 15: 500 round a corner: FAIL\n"), qPrintable(out));
        QVERIFY2(out.contains(QRegularExpression("measured: +0 of 500 out in 300")), qPrintable(out));
        QVERIFY2(out.contains("RiMEA 16: Single file: FAIL\n"), qPrintable(out));
    }
};

THRONG_REGISTER_TEST(TestCliValidate)
#include "TestCliValidate.moc"
