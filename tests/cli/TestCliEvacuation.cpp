// `throng-cli run` on the evacuation demo's hall with a tenth of its crowd (2,000 people;
// the full 20,000 take minutes, see README): the stats carry the share out, the time to
// 99 % out and each exit's flow per metre of door width.
#include "CliRunner.h"
#include "TestRegistry.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

using throng::test::runCli;

class TestCliEvacuation : public QObject {
    Q_OBJECT
private slots:
    void aTenthOfTheHallEmptiesThroughThreeExits()
    {
        QFile demo(THRONG_SOURCE_DIR "/resources/scenes/evacuation.yaml");
        QVERIFY(demo.open(QIODevice::ReadOnly | QIODevice::Text));
        QString text = QString::fromUtf8(demo.readAll());
        QCOMPARE(text.count("count: 6666"), 1);
        QCOMPARE(text.count("count: 6667"), 2);
        text.replace("count: 6666", "count: 666").replace("count: 6667", "count: 667");
        QTemporaryDir tmp;
        const QString scene = tmp.filePath("evacuation-2000.yaml"), stats = tmp.filePath("stats.json");
        QFile out(scene);
        QVERIFY(out.open(QIODevice::WriteOnly | QIODevice::Text));
        out.write(text.toUtf8());
        out.close();

        // 100 s of the shot at its 12 fps.
        const auto r = runCli({"run", scene.toStdString(), "--frames", "1200", "--stats", stats.toStdString(), "--quiet"});
        QCOMPARE(r.status, 0);
        QFile f(stats);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QJsonObject o = QJsonDocument::fromJson(f.readAll()).object();
        QCOMPARE(o["agents"].toInt(), 2000);
        QCOMPARE(o["exit_agents"].toInt(), 2000);
        QVERIFY2(o["fraction_out"].toDouble() >= 0.99, qPrintable(QString::number(o["fraction_out"].toDouble())));
        QVERIFY(o["agents_out"].toInt() >= 1980);
        const double t99 = o["time_to_99_percent_out"].toDouble();
        QVERIFY2(t99 > 10.0 && t99 < 100.0, qPrintable(QString::number(t99)));
        QCOMPARE(o["wall_penetrations"].toInt(), 0);
        QCOMPARE(o["non_finite_values"].toInt(), 0);
        const QJsonArray exits = o["exits"].toArray();
        QCOMPARE(exits.size(), 3);
        for (const QJsonValue& v : exits) {
            const QJsonObject e = v.toObject();
            QCOMPARE(e["door_width_m"].toDouble(), 10.0);
            const double flow = e["flow_per_metre_per_second"].toDouble();
            QVERIFY2(flow > 0.3 && flow < 5.0, qPrintable(QString::number(flow)));
            qInfo("%s: %d out, %.2f persons/m/s", qPrintable(e["goal"].toString()), e["agents_out"].toInt(), flow);
        }
        qInfo("99 %% out after %.1f s", t99);
    }
};

THRONG_REGISTER_TEST(TestCliEvacuation)
#include "TestCliEvacuation.moc"
