// The PedPy export (issue 26) as a researcher would check it: a run of walkers round a
// plaza's walls and obstacles and over a signalled crosswalk, with a car, written as
// PedPy's trajectory text and the set as WKT. Read back by PedPy's rules and Shapely
// (pedpy-check.py), the frame rate and unit are the run's, every walker row is the CSV's
// row in PedPy's axes (x, -z, y), the car is left out, and no walker stands outside the
// walkable area or steps across a wall or a kerb.
#include "RecordRun.h"
#include "TestRegistry.h"

#include "export/ExportFormats.h"
#include "export/PedPyExport.h"
#include "export/TrajectoryCsv.h"
#include "simcore/io/SceneIO.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <map>
#include <tuple>

using namespace throng;

namespace pedpy_test {

// A 40 m x 30 m plaza at 25 fps: a street (two lanes) with a crosswalk whose light turns
// green after 4 s, a wall with a gap, a round and a turned square obstacle, 30 walkers
// going east over the crosswalk, a car.
const char* kPlaza = R"(throng: 1
settings: {fps: 25, seed: 11, bounds: {min: [-20, -15], max: [20, 15]}}
agent_types:
  - {name: walker, radius: 0.25}
  - {name: car, kind: vehicle, radius: 2}
lanes:
  - {name: north, points: [[1.75, 15], [1.75, -15]], width: 3.5}
  - {name: south, points: [[-1.75, -15], [-1.75, 15]], width: 3.5}
crosswalks:
  - {name: mid, from: [-7, 0], to: [7, 0], width: 5}
traffic_lights:
  - {name: walk, green: 20, yellow: 3, red: 4, offset: 23, position: [-4, 3], stop_lines: [{crosswalk: mid}]}
walls:
  - {points: [[-18, -6], [-10, -6]]}
  - {points: [[-18, 6], [-10, 6], [-10, 3]]}
obstacles:
  - {shape: circle, center: [12, 2], radius: 1}
  - {shape: box, center: [12, -3], size: [2, 1], angle: 30}
goals:
  - {name: east, position: [17, 0], radius: 2}
groups:
  - {name: crowd, type: walker, count: 30, rect: {min: [-17, -5], max: [-11, 5]}, goal: east}
vehicles:
  - {id: 900, type: car, lane: north, at: 2, speed: 8}
)";

using Row = std::tuple<std::string, std::string, std::string, std::string>;  // x y z as written

QStringList fileLines(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QString::fromUtf8(f.readAll()).split('\n', Qt::SkipEmptyParts);
}

}  // namespace pedpy_test

using namespace pedpy_test;

class TestPedPyExport : public QObject {
    Q_OBJECT
private slots:
    void walkersReadBackByPedPysRulesWithTheirSet()
    {
        const sim::LoadResult loaded = sim::parseScene(kPlaza, "plaza.yaml", "");
        QVERIFY(loaded.ok());
        sim::World world(loaded.scene);
        sim::FrameCache cache;
        test::recordRun(world, 25 * 24, cache);
        QTemporaryDir dir;
        const QString txt = dir.filePath("plaza.txt"), wkt = dir.filePath("plaza.wkt"), csv = dir.filePath("plaza.csv");
        exporting::ExportRequest request;
        request.path = txt.toStdString();
        const exporting::ExportFormat* format = exporting::formatForPath(request.path);
        QVERIFY(format && format->key == "pedpy");
        const exporting::ExportResult r = format->write(loaded.scene, cache, request, {});
        QVERIFY2(r.ok(), r.error.c_str());
        QCOMPARE(r.writtenPaths, (std::vector<std::string>{txt.toStdString(), wkt.toStdString()}));
        QVERIFY(exporting::writeTrajectoryCsv(cache, csv.toStdString()).ok());

        // Every walker row of the CSV, in PedPy's axes; none of the car's.
        std::map<std::pair<QString, QString>, QStringList> expected;  // (id, frame) -> x y z
        int carRows = 0;
        for (const QString& line : fileLines(csv).mid(1)) {
            const QStringList f = line.split(',');
            if (f[1] == "900") {
                ++carRows;
                continue;
            }
            const QString y = f[4].startsWith('-') ? f[4].mid(1) : (f[4] == "0" ? f[4] : "-" + f[4]);
            expected[{f[1], f[0]}] = {f[2], y, f[3]};
        }
        QVERIFY(carRows > 0);
        int rows = 0;
        for (const QString& line : fileLines(txt)) {
            if (line.startsWith('#'))
                continue;
            const QStringList f = line.split(' ');
            QCOMPARE(f.size(), 5);
            const auto at = expected.find({f[0], f[1]});
            QVERIFY2(at != expected.end(), qPrintable("a row the CSV does not have: " + line));
            QVERIFY2(f.mid(2) == at->second, qPrintable(line + " | " + at->second.join(' ')));
            ++rows;
        }
        QCOMPARE(rows, int(expected.size()));
        QCOMPARE(rows, 30 * 25 * 24);

        // Read as PedPy reads it, against the set as Shapely reads it.
        QProcess check;
        check.start(QFile::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3",
                    {THRONG_SOURCE_DIR "/tests/export/pedpy-check.py", txt, wkt});
        QVERIFY(check.waitForFinished(120000));
        const QString err = QString::fromUtf8(check.readAllStandardError());
        QVERIFY2(check.exitStatus() == QProcess::NormalExit && check.exitCode() == 0, qPrintable(err));
        const QJsonObject s = QJsonDocument::fromJson(check.readAllStandardOutput().trimmed()).object();
        qInfo("%s", QJsonDocument(s).toJson(QJsonDocument::Compact).constData());
        QCOMPARE(s["frameRate"].toDouble(), 25.0);
        QCOMPARE(s["unit"].toString(), QString("m"));
        QCOMPARE(s["rows"].toInt(), rows);
        QCOMPARE(s["agents"].toInt(), 30);
        QCOMPARE(s["firstFrame"].toInt(), 0);
        QCOMPARE(s["lastFrame"].toInt(), 25 * 24 - 1);
        QCOMPARE(s["boundsArea"].toDouble(), 40.0 * 30.0);
        QCOMPARE(s["obstacles"].toInt(), 2);
        QVERIFY(s["walls"].toInt() >= 2 + 4);  // the two walls, and kerbs on either side of the crosswalk
        QVERIFY(s["walkableArea"].toDouble() < 40.0 * 30.0 - 3.0);  // the obstacles are cut out
        QCOMPARE(s["pointsOutsideWalkable"].toInt(), 0);
        QCOMPARE(s["pointsInObstacles"].toInt(), 0);
        QCOMPARE(s["stepsAcrossWalls"].toInt(), 0);
        // The walkers crossed the street: the last frame has them east of the far kerb.
        int across = 0;
        for (std::size_t i = 0; i < cache.agentCount(); ++i)
            across += cache.agents()[i].id != 900 && cache.at(cache.frameCount() - 1, i).position.x > 3.5f;
        QVERIFY2(across >= 25, qPrintable(QString::number(across)));
    }

    // A stepped-out walker's mistake, seen by the check: a row moved into an obstacle, and
    // one step across a wall, are counted (the check can fail).
    void theCheckSeesAWalkerInAnObstacleOrThroughAWall()
    {
        const sim::LoadResult loaded = sim::parseScene(kPlaza, "plaza.yaml", "");
        QVERIFY(loaded.ok());
        sim::World world(loaded.scene);
        sim::FrameCache cache;
        test::recordRun(world, 3, cache);
        QTemporaryDir dir;
        const QString txt = dir.filePath("bad.txt");
        QVERIFY(exporting::writePedPyTrajectories(loaded.scene, cache, txt.toStdString()).ok());
        QFile f(txt);
        QVERIFY(f.open(QIODevice::Append));
        f.write("5000 0 12 -2 0\n5000 1 12 -2 0\n");       // inside the round obstacle (y = -z)
        f.write("5001 0 -14 -5.8 0\n5001 1 -14 -6.2 0\n");  // across the wall at z = 6
        f.close();
        QProcess check;
        check.start(QFile::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3",
                    {THRONG_SOURCE_DIR "/tests/export/pedpy-check.py", txt, dir.filePath("bad.wkt")});
        QVERIFY(check.waitForFinished(60000));
        QCOMPARE(check.exitCode(), 0);
        const QJsonObject s = QJsonDocument::fromJson(check.readAllStandardOutput().trimmed()).object();
        QCOMPARE(s["pointsInObstacles"].toInt(), 2);
        QCOMPARE(s["stepsAcrossWalls"].toInt(), 1);
        QVERIFY(s["pointsOutsideWalkable"].toInt() >= 2);
    }
};

THRONG_REGISTER_TEST(TestPedPyExport)
#include "TestPedPyExport.moc"
