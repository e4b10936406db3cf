// `throng-cli run` as a pipeline uses it: the stats JSON, the trajectories CSV, the
// export, --frames/--seed/--threads, and nothing written for an invalid scene.
#include "CliRunner.h"
#include "TestRegistry.h"

#include <QDir>
#include <QFile>
#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>

using throng::test::runCli;

namespace {

// A JSON object of the 9 step phases' times (stats' phase_seconds, bench's
// phase_ms_per_step): whether it holds all 9, none negative; their sum in `sum`, else why not.
bool phasesAddUp(const QJsonObject& phases, double& sum, QString& why)
{
    sum = 0.0;
    if (phases.size() != 9) {
        why = QString("%1 phases, not 9").arg(phases.size());
        return false;
    }
    for (const QString& key : phases.keys()) {
        if (!(phases[key].toDouble(-1.0) >= 0.0)) {
            why = key + " is negative or not a number";
            return false;
        }
        sum += phases[key].toDouble();
    }
    return true;
}

const char* kScene = R"(throng: 1
settings: {fps: 10, duration: 3, seed: 4}
agent_types: [{name: walker, max_speed: 1.5, max_force: 6}]
goals: [{name: exit, position: [8, 0], radius: 1}]
walls: [{points: [[4, -20], [4, -1.5]]}, {points: [[4, 1.5], [4, 20]]}]
groups: [{name: g, type: walker, count: 40, rect: {min: [-6, -5], max: [0, 5]}, goal: exit}]
)";

// 3,000 walkers cross a hall with a wall and posts in it to two doors on the far sides,
// and leave: enough agents that a second thread takes part of every step.
const char* kBigScene = R"(throng: 1
settings: {fps: 12, duration: 4, seed: 8, bounds: {min: [-40, -40], max: [40, 40]}}
agent_types: [{name: walker, radius: 0.3, max_speed: 1.4, max_force: 6}]
goals: [{name: east, position: [31, 0], radius: 1.5, exit: true}, {name: west, position: [-31, 0], radius: 1.5, exit: true}]
walls: [{points: [[0, -10], [0, 10]]}]
obstacles: [{shape: circle, center: [10, 5], radius: 1}, {shape: box, center: [-10, -5], size: [3, 2], angle: 20}]
groups:
  - {name: a, type: walker, count: 1500, rect: {min: [-28, -25], max: [-2, 25]}, goal: east}
  - {name: b, type: walker, count: 1500, rect: {min: [2, -25], max: [28, 25]}, goal: west}
)";

QJsonObject readJson(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly))
        return {};
    return QJsonDocument::fromJson(f.readAll()).object();
}

QStringList readLines(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly | QIODevice::Text))
        return {};
    return QString::fromUtf8(f.readAll()).split('\n', Qt::SkipEmptyParts);
}

}  // namespace

class TestCliRun : public QObject {
    Q_OBJECT
private slots:
    void statsCarryTheContractFigures()
    {
        QTemporaryDir tmp;
        const QString scene = throng::test::writeText(tmp.filePath("s.yaml"), kScene);
        const QString stats = tmp.filePath("stats.json");
        const auto r = runCli({"run", scene.toStdString(), "--stats", stats.toStdString(), "--quiet"});
        QCOMPARE(r.status, 0);
        QVERIFY(r.out.find("stats: " + stats.toStdString()) != std::string::npos);
        const QJsonObject o = readJson(stats);
        QCOMPARE(o["agents"].toInt(), 40);
        QCOMPARE(o["frames"].toInt(), 30);  // duration 3 s x 10 fps
        QCOMPARE(o["seed"].toInt(), 4);
        QVERIFY(o["wall_seconds"].toDouble() > 0.0);
        QVERIFY(o["agent_steps_per_second"].toDouble() > 0.0);
        QCOMPARE(o["wall_penetrations"].toInt(), 0);
        QCOMPARE(o["non_finite_values"].toInt(), 0);
        for (const char* key : {"obstacle_penetrations", "overlapping_pairs", "red_light_violations", "arrived"})
            QVERIFY2(o.contains(key), key);
        // Where the run's time went: every phase, the move phase's above zero, the brains'
        // zero (this scene has none), together no more than the run's wall time.
        const QJsonObject phases = o["phase_seconds"].toObject();
        double sum = 0.0;
        QString why;
        QVERIFY2(phasesAddUp(phases, sum, why), qPrintable(why));
        QVERIFY(phases["move"].toDouble() > 0.0 && phases["count"].toDouble() > 0.0);
        QCOMPARE(phases["brain"].toDouble(), 0.0);
        QVERIFY2(sum <= o["wall_seconds"].toDouble(), qPrintable(QString::number(sum)));
    }

    void crossroadsStatsCarryTrafficFigures()
    {
        // The demo's first 50 s: two cycles of each light.
        QTemporaryDir tmp;
        const std::string scene = std::string(THRONG_SOURCE_DIR) + "/resources/scenes/crossroads.yaml";
        const QString stats = tmp.filePath("stats.json"), csv = tmp.filePath("t.csv");
        const auto r = runCli({"run", scene, "--frames", "1200", "--stats", stats.toStdString(), "--trajectories",
                               csv.toStdString(), "--quiet"});
        QCOMPARE(r.status, 0);
        const QJsonObject o = readJson(stats);
        QCOMPARE(o["vehicles"].toInt(), 16);
        QCOMPARE(o["heroes"].toInt(), 1);
        for (const char* key : {"red_light_violations", "pedestrian_red_light_violations", "vehicle_red_light_violations",
                                "car_pedestrian_collisions", "wall_penetrations", "non_finite_values"})
            QVERIFY2(o.contains(key) && o[key].toInt() == 0, key);
        QVERIFY(o["vehicle_crossings"].toInt() > 0);
        QVERIFY(o["pedestrian_crossings"].toInt() > 0);
        const QJsonArray flows = o["throughput_per_green"].toArray();
        QCOMPARE(flows.size(), 8);  // four lanes' stop lines, four crosswalks
        int laneLines = 0;
        for (const QJsonValue& v : flows) {
            const QJsonObject f = v.toObject();
            QVERIFY(!f["light"].toString().isEmpty());
            QVERIFY(f["green_phases"].toInt() >= 1);
            QCOMPARE(f["per_green"].toDouble(), f["crossings"].toDouble() / f["green_phases"].toDouble());
            laneLines += f.contains("lane") ? 1 : 0;
        }
        QCOMPARE(laneLines, 4);
        // Vehicles and the hero are rows of the trajectories, like every other agent.
        const QStringList rows = readLines(csv);
        QCOMPARE(rows.size(), 1 + 1200 * o["agents"].toInt());
        QCOMPARE(o["agents"].toInt(), 210 + 16 + 1);  // 200 walkers, the 10-walker shortest-path group, cars, hero
    }

    void framesSeedAndThreads()
    {
        QTemporaryDir tmp;
        const QString scene = throng::test::writeText(tmp.filePath("s.yaml"), kScene);
        auto csvFor = [&](const char* name, std::vector<std::string> extra) {
            const QString csv = tmp.filePath(name);
            std::vector<std::string> args{"run", scene.toStdString(), "--trajectories", csv.toStdString(), "--quiet"};
            args.insert(args.end(), extra.begin(), extra.end());
            const auto r = runCli(args);
            if (r.status != 0)
                qWarning("%s", r.err.c_str());
            return readLines(csv);
        };
        const QStringList one = csvFor("one.csv", {"--frames", "12", "--threads", "1"});
        QCOMPARE(one.size(), 1 + 12 * 40);
        QCOMPARE(one[0], QString("frame,agent,x,y,z,heading,speed,clip,phase"));
        QVERIFY(one[1].startsWith("0,1,"));
        QVERIFY(one.last().startsWith("11,40,"));
        // Same seed, two threads: byte-identical trajectories.
        QCOMPARE(csvFor("two.csv", {"--frames", "12", "--threads", "2"}), one);
        // Another seed spawns another crowd.
        QVERIFY(csvFor("seed.csv", {"--frames", "12", "--seed", "99"}) != one);
    }

    // 3,000 walkers on 1 and on 2 threads: the same trajectories and figures, and the
    // stats show that the second thread stepped agents (40 walkers, as above, fit in one
    // chunk of work: there the second thread never runs).
    void twoThreadsWorkAndAgreeWithOne()
    {
        QTemporaryDir tmp;
        const QString scene = throng::test::writeText(tmp.filePath("big.yaml"), kBigScene);
        QStringList csv[2];
        QJsonObject stats[2];
        for (int t = 0; t < 2; ++t) {
            const QString c = tmp.filePath(QString("t%1.csv").arg(t + 1)), j = tmp.filePath(QString("t%1.json").arg(t + 1));
            const auto r = runCli({"run", scene.toStdString(), "--threads", std::to_string(t + 1), "--trajectories",
                                   c.toStdString(), "--stats", j.toStdString(), "--quiet"});
            QCOMPARE(r.status, 0);
            csv[t] = readLines(c);
            stats[t] = readJson(j);
        }
        QCOMPARE(stats[0]["agents"].toInt(), 3000);
        QCOMPARE(csv[0].size(), 1 + 48 * 3000);
        QCOMPARE(stats[1]["threads"].toInt(), 2);
        const QJsonArray chunks = stats[1]["chunks_per_thread"].toArray();
        QCOMPARE(chunks.size(), 2);
        QVERIFY2(chunks[0].toDouble() > 0 && chunks[1].toDouble() > 0, "the second thread did no work");
        QVERIFY(csv[1] == csv[0]);
        for (const QString& key : stats[0].keys())
            if (key != "wall_seconds" && key != "agent_steps_per_second" && key != "threads" &&
                key != "chunks_per_thread" && key != "phase_seconds")
                QVERIFY2(stats[1][key] == stats[0][key], qPrintable(key));
    }

    void exportWritesAGlb()
    {
        QTemporaryDir tmp;
        const QString scene = throng::test::writeText(tmp.filePath("s.yaml"), kScene);
        const QString glb = tmp.filePath("crowd.glb");
        const auto r = runCli({"run", scene.toStdString(), "--frames", "20", "--export", glb.toStdString(), "--quiet"});
        QCOMPARE(r.status, 0);
        QFile f(glb);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.read(4), QByteArray("glTF"));
        QVERIFY(f.size() > 1000);
    }

    void invalidSceneRunsNothingAndWritesNothing()
    {
        QTemporaryDir tmp;
        const QString scene = throng::test::writeText(tmp.filePath("bad.yaml"), "throng: 1\nagents: [{type: ghost}]\n");
        const auto r = runCli({"run", scene.toStdString(), "--stats", tmp.filePath("s.json").toStdString()});
        QCOMPARE(r.status, 1);
        QVERIFY(r.err.find("bad.yaml:2:") != std::string::npos);
        QVERIFY(!QFile::exists(tmp.filePath("s.json")));
    }

    // An output that cannot be written is refused before the run, not after hours of it:
    // every such output named with the reason, nothing simulated, nothing written.
    void unwritableOutputFailsClearly()
    {
        QTemporaryDir tmp;
        const QString scene = throng::test::writeText(tmp.filePath("s.yaml"), kScene);
        const std::string file = throng::test::writeText(tmp.filePath("plain.txt"), "x").toStdString();
        const std::string good = tmp.filePath("good.csv").toStdString();
        const auto r = runCli({"run", scene.toStdString(), "--frames", "2", "--stats", "/no/such/dir/s.json",
                               "--export", good, "--export", file + "/cache/", "--report", tmp.path().toStdString(),
                               "--quiet"});
        QCOMPARE(r.status, 1);
        for (const std::string& line :
             {std::string("--stats /no/such/dir/s.json: cannot be written: the folder '/no/such/dir' does not exist"),
              "--export " + file + "/cache/: cannot be written: '" + file + "' is not a folder",
              "--report " + tmp.path().toStdString() + ": cannot be written: it is a folder",
              std::string("throng-cli: nothing was run")})
            QVERIFY2(r.err.find(line) != std::string::npos, (line + "\nin:\n" + r.err).c_str());
        QVERIFY2(r.out.find("simulated") == std::string::npos, r.out.c_str());
        QVERIFY(!QFile::exists(QString::fromStdString(good)));
        // A directory output whose folders do not exist yet is made by its writer.
        const std::string cache = tmp.filePath("new/deeper/cache/").toStdString();
        const auto made = runCli({"run", scene.toStdString(), "--frames", "2", "--export", cache, "--quiet"});
        QVERIFY2(made.status == 0, made.err.c_str());
        QVERIFY(QFile::exists(tmp.filePath("new/deeper/cache/agent_1.txt")));
        // And given relative to the working folder, none of its folders there yet.
        const QString before = QDir::currentPath();
        QVERIFY(QDir::setCurrent(tmp.path()));
        const auto relative =
            runCli({"run", scene.toStdString(), "--frames", "2", "--export", "fresh/cache/", "--quiet"});
        QVERIFY(QDir::setCurrent(before));
        QVERIFY2(relative.status == 0, relative.err.c_str());
        QVERIFY(QFile::exists(tmp.filePath("fresh/cache/agent_1.txt")));
    }

    void progressOnStderrUnlessQuiet()
    {
        QTemporaryDir tmp;
        const QString scene = throng::test::writeText(tmp.filePath("s.yaml"), kScene);
        // 40 agents x 60,000 frames passes the "long run" threshold.
        auto r = runCli({"run", scene.toStdString(), "--frames", "60000", "--threads", "1"});
        QCOMPARE(r.status, 0);
        QVERIFY2(r.err.find("simulating") != std::string::npos && r.err.find("100%") != std::string::npos,
                 r.err.c_str());
        r = runCli({"run", scene.toStdString(), "--frames", "60000", "--threads", "1", "--quiet"});
        QVERIFY(r.err.empty());
    }

    void benchPrintsJson()
    {
        const auto r = runCli({"bench", "--agents", "500", "--steps", "20", "--scenario", "corridor", "--quiet"});
        QCOMPARE(r.status, 0);
        const QJsonObject o = QJsonDocument::fromJson(QByteArray::fromStdString(r.out)).object();
        QCOMPARE(o["scenario"].toString(), QString("corridor"));
        QCOMPARE(o["agents"].toInt(), 500);
        QCOMPARE(o["steps"].toInt(), 20);
        for (const char* key : {"seconds", "agent_steps_per_second", "ms_per_step", "steps_per_second",
                                "peak_memory_bytes_per_agent", "overlapping_pairs_per_step", "fraction_arrived",
                                "wall_penetrations"})
            QVERIFY2(o.contains(key), key);
        QCOMPARE(o["agents_with_brain"].toInt(), 0);
        QCOMPARE(o["placed_in_grid_order"].toBool(), false);  // walkers keep their order
        // Two-way walkers 0.6 m across, most of them not touching: the contact rounds pass
        // most by, and not all (those meeting head-on).
        const double passed = o["contact_rounds_passed_by"].toDouble(-1.0);
        QVERIFY2(passed > 0.5 && passed < 1.0, qPrintable(QString::number(passed)));
        // Where the steps' time went: every phase, none negative, the move phase's above
        // zero and the brains' zero (the corridor has none), together within a step's time.
        const QJsonObject phases = o["phase_ms_per_step"].toObject();
        QCOMPARE(phases.size(), 9);
        double sum = 0.0;
        for (const char* key : {"enter", "grid", "navigate", "brain", "traffic", "move", "collide", "commit", "count"}) {
            QVERIFY2(phases.contains(key) && phases[key].toDouble() >= 0.0, key);
            sum += phases[key].toDouble();
        }
        QVERIFY(phases["move"].toDouble() > 0.0);
        QCOMPARE(phases["brain"].toDouble(), 0.0);
        QVERIFY2(sum <= o["ms_per_step"].toDouble(), qPrintable(QString::number(sum)));
        QVERIFY(!o.contains("windows"));  // only with --window
    }

    // bench --window: the run cut into windows of steps, each with its own figures, which
    // add up to the run's. The cross's walkers start with their two ring neighbours within
    // perception, and list more as the rings close in on the middle.
    void benchPrintsWindows()
    {
        const auto r = runCli({"bench", "--agents", "2000", "--steps", "500", "--window", "120", "--scenario", "cross",
                               "--threads", "2", "--quiet"});
        QCOMPARE(r.status, 0);
        const QJsonObject o = QJsonDocument::fromJson(QByteArray::fromStdString(r.out)).object();
        const QJsonArray windows = o["windows"].toArray();
        QCOMPARE(windows.size(), 5);  // 4 x 120 steps and the last 20
        int next = 0;
        double seconds = 0.0, overlaps = 0.0, firstNeighbours = 0.0, lastNeighbours = 0.0;
        for (const QJsonValue& value : windows) {
            const QJsonObject w = value.toObject();
            QCOMPARE(w["first_step"].toInt(), next);
            const int steps = w["steps"].toInt();
            QCOMPARE(steps, std::min(120, 500 - next));
            next += steps;
            const double ms = w["ms_per_step"].toDouble();
            QVERIFY(ms > 0.0);
            seconds += ms * steps / 1000.0;
            overlaps += w["overlapping_pairs_per_step"].toDouble() * steps;
            const QJsonObject phases = w["phase_ms_per_step"].toObject();
            double sum = 0.0;
            QString why;
            QVERIFY2(phasesAddUp(phases, sum, why), qPrintable(why));
            QVERIFY(phases["move"].toDouble() > 0.0);
            QVERIFY2(sum <= ms, qPrintable(QString("%1 > %2").arg(sum).arg(ms)));
            const double neighbours = w["mean_neighbours"].toDouble(-1.0);
            QVERIFY2(neighbours >= 0.0 && neighbours <= 8.0, qPrintable(QString::number(neighbours)));
            if (w["first_step"].toInt() == 0)
                firstNeighbours = neighbours;
            lastNeighbours = neighbours;
        }
        QCOMPARE(next, 500);
        // The windows' time is the run's (the run's leaves out what the windows' figures took).
        QVERIFY2(std::abs(seconds - o["seconds"].toDouble()) <= 0.05 * o["seconds"].toDouble(),
                 qPrintable(QString("%1 against %2").arg(seconds).arg(o["seconds"].toDouble())));
        QVERIFY(std::abs(overlaps - o["overlapping_pairs_per_step"].toDouble() * 500) < 1e-6);
        QVERIFY2(firstNeighbours > 1.9 && firstNeighbours < 2.5, qPrintable(QString::number(firstNeighbours)));
        QVERIFY2(lastNeighbours > firstNeighbours + 1.0, qPrintable(QString::number(lastNeighbours)));
    }

    // `run` stores 70,000 placed birds (at least kGridOrderFrom) in the grid's order, and
    // each bird still starts where the file puts it and keeps its id: frame 0 of the
    // trajectories holds every id at its own place, and every frame holds every bird.
    void runStoresABigFlockInTheGridsOrderAndKeepsEachBird()
    {
        QTemporaryDir dir;
        QString text = "throng: 1\n"
                       "settings: {fps: 24, duration: 1, seed: 2, bounds: {min: [-300, -300], max: [300, 300]}}\n"
                       "agent_types: [{name: bird, kind: flier, radius: 0.2, max_speed: 12, min_speed: 4, "
                       "perception: 3, behaviours: {separation: 2, alignment: 1, cohesion: 1, wander: 0.2}}]\n"
                       "agents:\n  columns: [id, type, x, y, z]\n  rows: |\n";
        constexpr int kBirds = 70000, kSide = 41;  // a 41 x 41 x 42 lattice, 5 m apart, numbered along x first
        QHash<int, QString> at;
        for (int i = 0; i < kBirds; ++i) {
            const int x = i % kSide, y = (i / kSide) % kSide, z = i / (kSide * kSide);
            const QString place = QString("%1,%2,%3").arg(x * 5 - 100).arg(20 + y * 2).arg(z * 5 - 100);
            at[i + 1] = place;
            text += QString("    %1 bird %2 %3 %4\n").arg(i + 1).arg(x * 5 - 100).arg(20 + y * 2).arg(z * 5 - 100);
        }
        const QString scene = dir.filePath("birds.yaml"), csv = dir.filePath("birds.csv");
        QFile f(scene);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(text.toUtf8());
        f.close();
        const auto r =
            runCli({"run", scene.toStdString(), "--frames", "3", "--trajectories", csv.toStdString(), "--quiet"});
        QVERIFY2(r.status == 0, r.err.c_str());
        const QStringList lines = readLines(csv);
        QCOMPARE(lines.size(), 1 + 3 * kBirds);  // the header, then frames 0 to 2
        QSet<int> seen;
        QList<int> firstIds;
        for (int k = 1; k <= kBirds; ++k) {
            const QStringList v = lines[k].split(',');  // frame,agent,x,y,z,...
            QCOMPARE(v[0], QString("0"));
            const int id = v[1].toInt();
            if (k <= 3)
                firstIds << id;
            QVERIFY(!seen.contains(id));
            seen.insert(id);
            const QString place = QString("%1,%2,%3").arg(v[2].toDouble()).arg(v[3].toDouble()).arg(v[4].toDouble());
            QCOMPARE(place, at[id]);
        }
        QCOMPARE(seen.size(), kBirds);
        // The rows come in the grid's order, not the file's: bird 1, then the birds above
        // it (up its column first), not birds 2 and 3 beside it.
        QCOMPARE(firstIds, (QList<int>{1, 1 + kSide, 1 + 2 * kSide}));
        for (int frame = 1; frame <= 2; ++frame) {
            QSet<int> ids;
            for (int k = 1 + frame * kBirds; k <= (frame + 1) * kBirds; ++k)
                ids.insert(lines[k].section(',', 1, 1).toInt());
            QCOMPARE(ids, seen);
        }
    }

    // A flock of 70,000 placed birds (at least kGridOrderFrom) is stored in the grid's
    // order before it runs; 2,000 keep the scenario's.
    void benchStoresABigFlockInTheGridsOrder()
    {
        for (const auto& [agents, ordered] : {std::pair{"70000", true}, std::pair{"2000", false}}) {
            const auto r = runCli({"bench", "--agents", agents, "--steps", "2", "--scenario", "flock", "--quiet"});
            QCOMPARE(r.status, 0);
            const QJsonObject o = QJsonDocument::fromJson(QByteArray::fromStdString(r.out)).object();
            QCOMPARE(o["agents"].toInt(), std::stoi(agents));
            QCOMPARE(o["placed_in_grid_order"].toBool(), ordered);
            QCOMPARE(o["non_finite_values"].toInt(), 0);
        }
    }

    // The scenario of issue 27's million walkers with brains: every walker of `cross` runs
    // the 40-node brain, and the figures come out finite.
    void benchCrossBrainRunsTheBrain()
    {
        const auto r = runCli({"bench", "--agents", "400", "--steps", "60", "--scenario", "cross-brain", "--quiet"});
        QCOMPARE(r.status, 0);
        const QJsonObject o = QJsonDocument::fromJson(QByteArray::fromStdString(r.out)).object();
        QCOMPARE(o["scenario"].toString(), QString("cross-brain"));
        QCOMPARE(o["agents"].toInt(), 400);
        QCOMPARE(o["agents_with_brain"].toInt(), 400);
        QVERIFY(o["steps_per_second"].toDouble() > 0.0);
        QVERIFY(o["phase_ms_per_step"].toObject()["brain"].toDouble() > 0.0);
        QCOMPARE(o["non_finite_values"].toInt(), 0);
    }
};

THRONG_REGISTER_TEST(TestCliRun)
#include "TestCliRun.moc"
