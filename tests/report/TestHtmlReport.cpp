// throng-cli run … --report OUT.html, run as a user runs it: the real program, in a process
// with no display. The report is one file that fetches nothing; its five plots are PNGs
// that decode; and the data it embeds is recounted from the trajectories CSV of the same
// run (line crossings, agents in the scene, the density map's total, speed and density in
// an area, the time to evacuate) and from the run's stats JSON (agents out per exit, agents
// in the scene each second). 1 and 2 threads give the same report byte for byte. An
// output that cannot be written fails the run with the path named.
#include "TestRegistry.h"
#include "TrajectoryTable.h"

#include <QDir>
#include <QFile>
#include <QImage>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <set>

using namespace throng::test;

namespace {

// A room 16 m x 10 m with a door 1.2 m wide in its east wall and one in its south wall,
// each opening onto a passage and an exit 3 m beyond; 90 walkers bound for the east door
// and 60 for the south one. A line across each doorway and an area in front of the east
// door.
const char* kScene = R"(throng: 1
settings: {fps: 24, duration: 150, seed: 21, bounds: {min: [-2, -2], max: [24, 18]}, nav_cell: 0.2}
agent_types:
  - {name: walker, radius: 0.22, max_speed: 1.34, navigation: flow_field}
walls:
  - {points: [[16, 4.4], [16, 0], [0, 0], [0, 10], [7.4, 10]]}
  - {points: [[8.6, 10], [16, 10], [16, 5.6]]}
  - {points: [[16, 4.4], [19, 4.4]]}
  - {points: [[16, 5.6], [19, 5.6]]}
  - {points: [[7.4, 10], [7.4, 13]]}
  - {points: [[8.6, 10], [8.6, 13]]}
goals:
  - {name: east, position: [20, 5], radius: 1, exit: true}
  - {name: south, position: [8, 14], radius: 1, exit: true}
groups:
  - {name: eastward, type: walker, count: 90, rect: {min: [1, 0.5], max: [9, 6]}, goal: east}
  - {name: southward, type: walker, count: 60, rect: {min: [10, 6.5], max: [15, 9.5]}, goal: south}
measurements:
  - {name: east_door, line: [[16, 4.4], [16, 5.6]]}
  - {name: south_door, line: [[8.6, 10], [7.4, 10]]}
  - {name: before_east, area: [[13, 3], [16, 3], [16, 7], [13, 7]]}
)";

QString writeText(const QString& path, const char* text)
{
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly))
        qFatal("cannot write %s", qPrintable(path));
    f.write(text);
    return path;
}

// 3,000 walkers on open ground crossing a line on their way to a wide exit: enough for
// every thread to step agents.
const char* kCrowd = R"(throng: 1
settings: {fps: 24, duration: 20, seed: 8, bounds: {min: [-5, -35], max: [95, 35]}}
agent_types:
  - {name: walker, radius: 0.25, max_speed: 1.34}
goals:
  - {name: far, position: [90, 0], radius: 30, exit: true}
groups:
  - {name: crowd, type: walker, count: 3000, rect: {min: [0, -30], max: [40, 30]}, goal: far}
measurements:
  - {name: middle, line: [[45, -30], [45, 30]]}
  - {name: start, area: [[0, -30], [40, -30], [40, 30], [0, 30]]}
)";

struct Ran {
    int status = -1;
    QString err;
};

// throng-cli with `args`, in a process with no display and no Qt platform chosen: as on a
// farm node.
Ran runHeadless(const QStringList& args)
{
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.remove("DISPLAY");
    env.remove("WAYLAND_DISPLAY");
    env.remove("QT_QPA_PLATFORM");
    p.setProcessEnvironment(env);
    p.start(THRONG_CLI_PATH, args);
    if (!p.waitForFinished(300'000))
        return {};
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, QString::fromUtf8(p.readAllStandardError())};
}

QByteArray readAll(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

QJsonObject embeddedData(const QString& html)
{
    const QRegularExpression re(
        QStringLiteral("<script type=\"application/json\" id=\"throng-analysis\">\\n(.*)\\n</script>"),
        QRegularExpression::DotMatchesEverythingOption);
    const QRegularExpressionMatch m = re.match(html);
    return m.hasMatch() ? QJsonDocument::fromJson(m.captured(1).toUtf8()).object() : QJsonObject();
}

// Crossings of segment a-b by consecutive rows of each agent, by direction along
// (bz - az, ax - bx).
std::pair<int, int> recountCrossings(const TrajectoryTable& t, double ax, double az, double bx, double bz)
{
    int forward = 0, backward = 0;
    for (const auto& [id, frames] : t.agents) {
        const TrajectoryRow* before = nullptr;
        int previous = -2;
        for (const auto& [f, row] : frames) {
            if (before && previous == f - 1 && segmentsCrossD(before->x, before->z, row.x, row.z, ax, az, bx, bz)) {
                const double along = (bz - az) * (row.x - before->x) + (ax - bx) * (row.z - before->z);
                ++(along > 0 ? forward : backward);
            }
            before = &row;
            previous = f;
        }
    }
    return {forward, backward};
}

std::vector<int> rowsPerFrame(const TrajectoryTable& t)
{
    std::vector<int> n(std::size_t(t.frames), 0);
    for (const auto& [id, frames] : t.agents)
        for (const auto& [f, row] : frames)
            ++n[std::size_t(f)];
    return n;
}

}  // namespace

class TestHtmlReport : public QObject {
    Q_OBJECT

private slots:
    void aRunWritesAReportWhoseFiguresTheTrajectoriesConfirm()
    {
        QTemporaryDir dir;
        const QString scene = writeText(dir.filePath("rooms.yaml"), kScene);
        const QString html = dir.filePath("report.html"), csv = dir.filePath("t.csv"), stats = dir.filePath("s.json");
        const Ran ran = runHeadless({"run", scene, "--quiet", "--threads", "1", "--report", html, "--trajectories", csv,
                                     "--stats", stats});
        QVERIFY2(ran.status == 0, qPrintable(ran.err));
        const QString text = QString::fromUtf8(readAll(html));
        QVERIFY(text.startsWith("<!DOCTYPE html>"));
        QVERIFY(text.contains("rooms.yaml"));

        // One file: nothing to fetch.
        for (const char* outside : {"src=\"http", "href=\"http", "<link", "url(", "<script src", "src=\"file:"})
            QVERIFY2(!text.contains(outside), outside);
        // Five plots, each a PNG that decodes and shows something.
        const QRegularExpression img(
            QStringLiteral("<img alt=\"([^\"]+)\"[^>]* src=\"data:image/png;base64,([^\"]+)\""));
        QStringList alts;
        for (auto it = img.globalMatch(text); it.hasNext();) {
            const QRegularExpressionMatch m = it.next();
            alts << m.captured(1);
            QImage image;
            QVERIFY(image.loadFromData(QByteArray::fromBase64(m.captured(2).toLatin1()), "PNG"));
            QVERIFY(image.width() >= 600 && image.height() >= 250);
            std::set<QRgb> colours;
            for (int y = 0; y < image.height(); y += 3)
                for (int x = 0; x < image.width(); x += 3)
                    colours.insert(image.pixel(x, y));
            QVERIFY2(colours.size() > 20, qPrintable(m.captured(1)));
        }
        QCOMPARE(alts, QStringList({"Trajectories", "Density heatmap", "Speed against density", "Flow over time",
                                    "Agents in the scene and out over time"}));

        const QJsonObject data = embeddedData(text);
        QVERIFY(!data.isEmpty());
        const TrajectoryTable t = TrajectoryTable::read(csv);
        const QJsonObject s = readStats(stats);
        QCOMPARE(data["frames"].toInt(), 3600);
        QCOMPARE(data["walkers"].toInt(), 150);

        // The lines' crossings, recounted from the CSV.
        const QJsonArray lines = data["lines"].toArray();
        QCOMPARE(lines.size(), 2);
        const auto east = recountCrossings(t, 16, 4.4, 16, 5.6), south = recountCrossings(t, 8.6, 10, 7.4, 10);
        QCOMPARE(east, std::make_pair(90, 0));
        QCOMPARE(south, std::make_pair(60, 0));
        QCOMPARE(lines[0].toObject()["forward"].toInt(), east.first);
        QCOMPARE(lines[0].toObject()["backward"].toInt(), east.second);
        QCOMPARE(lines[1].toObject()["forward"].toInt(), south.first);
        // The flow over time holds every crossing.
        const double bin = data["flow_bin_s"].toDouble();
        QCOMPARE(bin, 2.0);
        for (int l = 0; l < 2; ++l) {
            double total = 0.0;
            for (const QJsonValue v : lines[l].toObject()["flow_per_s"].toArray())
                total += v.toDouble() * bin;
            QCOMPARE(std::lround(total), long(l == 0 ? 90 : 60));
        }
        // Agents out per exit as the stats count them.
        const QJsonArray exits = data["exits"].toArray(), statExits = s["exits"].toArray();
        QCOMPARE(exits.size(), 2);
        QCOMPARE(exits[0].toObject()["out"].toInt(), 90);
        QCOMPARE(exits[1].toObject()["out"].toInt(), 60);
        for (int e = 0; e < 2; ++e) {
            QCOMPARE(statExits[e].toObject()["goal"].toString(), exits[e].toObject()["name"].toString());
            QCOMPARE(statExits[e].toObject()["agents_out"].toInt(), exits[e].toObject()["out"].toInt());
        }

        // Agents in the scene: the CSV's rows per frame, and the stats' samples each second.
        const std::vector<int> rows = rowsPerFrame(t);
        const QJsonArray inEachSecond = data["in_scene_each_second"].toArray();
        const QJsonArray statsEachSecond = s["agents_in_scene_each_second"].toArray();
        QVERIFY(inEachSecond.size() >= 100);
        for (int k = 0; k < inEachSecond.size(); ++k) {
            const int f = k * 24;
            QCOMPARE(inEachSecond[k].toInt(), f < int(rows.size()) ? rows[std::size_t(f)] : 0);
            if (k < statsEachSecond.size())
                QCOMPARE(inEachSecond[k].toInt(), statsEachSecond[k].toInt());
        }
        // Everybody left: the time to evacuate is the frame after the CSV's last row.
        int last = int(rows.size()) - 1;
        while (last >= 0 && rows[std::size_t(last)] == 0)
            --last;
        QVERIFY(std::abs(data["evacuation_s"].toDouble() - (last + 1) / 24.0) < 1e-6);
        QVERIFY(data["evacuation_s"].toDouble() > 30.0);

        // The density map holds the mean number of walkers in the scene over the frames.
        double mean = 0.0;
        for (int n : rows)
            mean += n;
        mean /= 3600.0;
        const QJsonObject map = data["density_map"].toObject();
        QVERIFY(std::abs(map["total_persons"].toDouble() - mean) < 1e-4 * mean);

        // Speed and density in front of the east door, frame by frame from the CSV.
        const QJsonObject area = data["areas"].toArray()[0].toObject();
        QCOMPARE(area["area_m2"].toDouble(), 12.0);
        std::vector<double> density, speed;
        for (int f = 0; f < 3600; ++f) {
            int inside = 0;
            double speeds = 0.0;
            for (const auto& [id, frames] : t.agents)
                if (auto it = frames.find(f); it != frames.end() && it->second.x > 13 && it->second.x < 16 &&
                                              it->second.z > 3 && it->second.z < 7) {
                    ++inside;
                    speeds += it->second.speed;
                }
            if (inside > 0) {
                density.push_back(inside / 12.0);
                speed.push_back(speeds / inside);
            }
        }
        const QJsonArray gotDensity = area["density"].toArray(), gotSpeed = area["speed"].toArray();
        QCOMPARE(std::size_t(gotDensity.size()), density.size());
        QVERIFY(density.size() > 100);
        double densest = 0.0;
        for (std::size_t k = 0; k < density.size(); ++k) {
            QVERIFY(std::abs(gotDensity[qsizetype(k)].toDouble() - density[k]) < 1e-5);
            QVERIFY(std::abs(gotSpeed[qsizetype(k)].toDouble() - speed[k]) < 2e-3);
            densest = std::max(densest, density[k]);
        }
        QVERIFY2(densest > 1.0, "a queue forms in front of the east door");
    }

    void anyThreadCountWritesTheSameReport()
    {
        QTemporaryDir dir;
        const QString scene = writeText(dir.filePath("crowd.yaml"), kCrowd);
        QByteArray reports[2];
        for (int threads : {1, 2}) {
            const QString html = dir.filePath(QString("r%1.html").arg(threads)), stats = dir.filePath("s.json");
            const Ran ran = runHeadless({"run", scene, "--quiet", "--threads", QString::number(threads), "--report",
                                         html, "--stats", stats});
            QVERIFY2(ran.status == 0, qPrintable(ran.err));
            const QJsonArray chunks = readStats(stats)["chunks_per_thread"].toArray();
            QCOMPARE(chunks.size(), threads);
            for (const QJsonValue c : chunks)
                QVERIFY2(c.toInt() > 0, "every thread stepped agents");
            reports[threads - 1] = readAll(html);
        }
        QVERIFY(reports[0].size() > 100'000);
        QVERIFY(reports[0] == reports[1]);
        // Someone crossed the middle line within the run: the report has figures, not zeros.
        const QJsonObject data = embeddedData(QString::fromUtf8(reports[0]));
        QVERIFY(data["lines"].toArray()[0].toObject()["forward"].toInt() > 100);
    }

    // --report-cell and --report-trajectories: the heatmap in cells of 0.5 m holds the same
    // walkers as in cells of 1 m, in four times the cells; the plan draws 5 walkers and says
    // so. Without --report they are refused.
    void theReportTakesItsCellAndItsWalkers()
    {
        QTemporaryDir dir;
        const QString scene = writeText(dir.filePath("crowd.yaml"), kCrowd);
        QJsonObject maps[2], data[2];
        int k = 0;
        for (const QStringList& extra : {QStringList{}, QStringList{"--report-cell", "0.5", "--report-trajectories", "5"}}) {
            const QString html = dir.filePath(QString("r%1.html").arg(k));
            const Ran ran = runHeadless(QStringList{"run", scene, "--quiet", "--frames", "240", "--report", html} + extra);
            QVERIFY2(ran.status == 0, qPrintable(ran.err));
            const QString text = QString::fromUtf8(readAll(html));
            data[k] = embeddedData(text);
            maps[k] = data[k]["density_map"].toObject();
            if (k == 1)
                QVERIFY2(text.contains(QString("<p>5 of the %1 walkers, picked evenly.</p>").arg(data[k]["walkers"].toInt())),
                         "the plan says it draws 5");
            ++k;
        }
        QCOMPARE(maps[0]["cell_m"].toDouble(), 1.0);
        QCOMPARE(maps[1]["cell_m"].toDouble(), 0.5);
        QCOMPARE(maps[1]["cols"].toInt(), 2 * maps[0]["cols"].toInt());
        QCOMPARE(maps[1]["rows"].toInt(), 2 * maps[0]["rows"].toInt());
        QVERIFY(std::abs(maps[1]["total_persons"].toDouble() - maps[0]["total_persons"].toDouble()) < 1e-9);
        QVERIFY(maps[1]["peak_density"].toDouble() >= maps[0]["peak_density"].toDouble());
        QCOMPARE(data[1]["walkers_drawn"].toInt(), 5);
        QCOMPARE(data[0]["walkers_drawn"].toInt(), std::min(2000, data[0]["walkers"].toInt()));  // the default
        const Ran alone = runHeadless({"run", scene, "--quiet", "--report-cell", "0.5"});
        QCOMPARE(alone.status, 2);
        QVERIFY2(alone.err.contains("give --report OUT.html too"), qPrintable(alone.err));
        const Ran tiny = runHeadless({"run", scene, "--quiet", "--report", dir.filePath("t.html"), "--report-cell", "0"});
        QCOMPARE(tiny.status, 2);
        QVERIFY2(tiny.err.contains("0.1 to 100"), qPrintable(tiny.err));
    }

    void anUnwritableReportFailsTheRunAndNamesThePath()
    {
        QTemporaryDir dir;
        const QString scene = writeText(dir.filePath("rooms.yaml"), kScene);
        const QString html = dir.filePath("no/such/folder/report.html");
        const Ran ran = runHeadless({"run", scene, "--quiet", "--frames", "48", "--report", html});
        QCOMPARE(ran.status, 1);
        QVERIFY2(ran.err.contains(html), qPrintable(ran.err));
        QVERIFY(!QFile::exists(html));
        const Ran misplaced = runHeadless({"check", scene, "--report", dir.filePath("r.html")});
        QCOMPARE(misplaced.status, 2);
        QVERIFY2(misplaced.err.contains("--report"), qPrintable(misplaced.err));
    }
};

THRONG_REGISTER_TEST(TestHtmlReport)
#include "TestHtmlReport.moc"
