// Signalised mid-block crosswalks (no junction: a road, a crosswalk and two lights, cars'
// and walkers'), on two layouts of our own, with the shipped `car` and `pedestrian` brains
// and without brains, over several light timings and frame rates. Every rule is
// recomputed from the trajectories CSV and the scene's own geometry and timing:
// - no walker's centre enters the road part of the crosswalk (inside the strip and on a
//   lane's carriageway) on a frame whose walk light is red, and the stats agree (0);
// - no vehicle's front crosses its stop line on red unless it could not stop: at the
//   first frame of that red, v^2 / (2 x 8 m/s^2) (the car-following model's full braking)
//   is more than its front's distance to the line less 5 cm; the stats count every red
//   crossing, excused or not;
// - a vehicle standing past its stop line on red does not enter the crosswalk before green;
// - walkers caught on the road by red leave it to the nearer kerb: nobody is on the
//   road at the end of a red, and none stays on it long after red begins;
// - no walker is ever on a carriageway off the crosswalk.
// What a user saw on main: walkers stepped from the kerb onto the lane on red 6-9 times,
// dozens stood in the lanes through their red, and a car on the `car` brain stopped 3 cm
// past its stop line and then drove over the crosswalk on red at 5 m/s, while
// red_light_violations, vehicle_red_light_violations and car_pedestrian_collisions said 0.
#include "CliRunner.h"
#include "TestRegistry.h"
#include "TrajectoryTable.h"

#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <cmath>

using namespace throng::test;

namespace {

struct Rect {
    double x0, z0, x1, z1;
    bool holds(double x, double z) const { return x >= x0 && x <= x1 && z >= z0 && z <= z1; }
};

// A straight lane as the checks see it: its direction, its stop line and the near edge of
// the crosswalk after it, as points along that direction.
struct LaneCheck {
    double dirX, dirZ;
    double lineX, lineZ;    // a point of the stop line
    double stripX, stripZ;  // a point of the crosswalk's near edge
    double along(double x, double z, double px, double pz) const { return (x - px) * dirX + (z - pz) * dirZ; }
};

struct Layout {
    const char* name;
    const char* set;  // lanes, crosswalk, paths, groups, vehicles (YAML)
    std::vector<Rect> carriageways;
    Rect strip;  // the crosswalk strip (axis-aligned in these layouts; its inside, open)
    std::vector<LaneCheck> lanes;
};

// A two-way road running north-south at x = 0 (carriageway |x| <= 3.5), the crosswalk
// from x = -6 to 6, 4 m wide; stop lines 3 m before the strip. Walkers go round a loop
// over the crosswalk, eastward on its north half, westward on its south half.
const Layout kTwoWay{"two-way", R"(lanes:
  - {name: north, points: [[1.75, 60], [1.75, -60]], width: 3.5, loop: false}
  - {name: south, points: [[-1.75, -60], [-1.75, 60]], width: 3.5, loop: false}
crosswalks:
  - {name: mid, from: [-6, 0], to: [6, 0], width: 4}
paths:
  - {name: loop, radius: 0.8, closed: true, points: [[-15, -1], [15, -1], [15, 1], [-15, 1]]}
groups:
  - {name: west, type: walker, count: 25, rect: {min: [-14, -3], max: [-7, 3]}, path: loop}
  - {name: east, type: walker, count: 25, rect: {min: [7, -3], max: [14, 3]}, path: loop}
vehicles:
  - {type: car, lane: north, at: 5, speed: 10}
  - {type: car, lane: north, at: 25, speed: 10}
  - {type: car, lane: north, at: 45, speed: 12}
  - {type: car, lane: north, at: 70}
  - {type: car, lane: south, at: 10, speed: 10}
  - {type: car, lane: south, at: 30, speed: 10}
  - {type: car, lane: south, at: 50, speed: 8}
  - {type: car, lane: south, at: 90}
)",
                      {{-3.5, -60, 3.5, 60}},
                      {-6, -2, 6, 2},
                      {{0, -1, 1.75, 5, 1.75, 2}, {0, 1, -1.75, -5, -1.75, -2}}};

// A one-way road of two westbound lanes along z = 20, far from the origin (carriageway
// z in [16.5, 23.5]), the crosswalk over it at x = 30 from z = 13 to 27, 3 m wide; stop
// lines 3.5 m before the strip. Walkers cross southward on its west half, northward on
// its east half.
const Layout kOneWay{"one-way", R"(lanes:
  - {name: inner, points: [[90, 18.25], [-30, 18.25]], width: 3.5, loop: false}
  - {name: outer, points: [[90, 21.75], [-30, 21.75]], width: 3.5, loop: false}
crosswalks:
  - {name: mid, from: [30, 13], to: [30, 27], width: 3}
paths:
  - {name: loop, radius: 0.6, closed: true, points: [[29.2, 4], [29.2, 36], [30.8, 36], [30.8, 4]]}
groups:
  - {name: north, type: walker, count: 20, rect: {min: [26, 4], max: [34, 11]}, path: loop}
  - {name: south, type: walker, count: 20, rect: {min: [26, 29], max: [34, 36]}, path: loop}
vehicles:
  - {type: car, lane: inner, at: 5, speed: 12}
  - {type: car, lane: inner, at: 30, speed: 12}
  - {type: car, lane: inner, at: 50, speed: 13}
  - {type: car, lane: inner, at: 80}
  - {type: car, lane: outer, at: 15, speed: 12}
  - {type: car, lane: outer, at: 40, speed: 10}
  - {type: car, lane: outer, at: 52, speed: 13.9}
  - {type: car, lane: outer, at: 100}
)",
                      {{-30, 16.5, 90, 23.5}},
                      {28.5, 13, 31.5, 27},
                      {{-1, 0, 35, 18.25, 31.5, 18.25}, {-1, 0, 35, 21.75, 31.5, 21.75}}};

struct Case {
    const Layout* layout;
    int fps;
    bool brains;
    LightTiming walk, cars;
    double maxClearS;  // longest a walker may stay on the road after red begins
};

QByteArray sceneText(const Case& c, double durationS)
{
    const QString brains = c.brains ? QString(R"(brains:
  - {name: pedestrian, file: %1/resources/brains/pedestrian.brain.yaml}
  - {name: car, file: %1/resources/brains/car.brain.yaml}
)")
                                          .arg(THRONG_SOURCE_DIR)
                                    : QString();
    const QString brainWalker = c.brains ? ", brain: pedestrian" : "", brainCar = c.brains ? ", brain: car" : "";
    auto light = [](const LightTiming& t) {
        return QString("green: %1, yellow: %2, red: %3, offset: %4").arg(t.green).arg(t.yellow).arg(t.red).arg(t.offset);
    };
    const bool twoWay = c.layout == &kTwoWay;
    const QString text =
        QString(R"(throng: 1
settings: {fps: %1, duration: %2, seed: 11, bounds: {min: [-70, -70], max: [100, 70]}}
%3agent_types:
  - {name: walker, kind: pedestrian, radius: 0.3, max_speed: 1.4, max_force: 6, perception: 4, view_angle: 270%4,
     behaviours: {arrival: 1, path_following: 1, separation: 1.5}}
  - {name: car, kind: vehicle, radius: 1.1, max_speed: 13.9, max_force: 5000, mass: 1200, perception: 45, view_angle: 90%5}
%6traffic_lights:
  - {name: cars, %7, stop_lines: [%8]}
  - {name: walk, %9, stop_lines: [{crosswalk: mid}]}
)")
            .arg(c.fps)
            .arg(durationS)
            .arg(brains, brainWalker, brainCar, QString::fromUtf8(c.layout->set), light(c.cars),
                 twoWay ? "{lane: north, at: 55}, {lane: south, at: 55}" : "{lane: inner, at: 55}, {lane: outer, at: 55}",
                 light(c.walk));
    return text.toUtf8();
}

}  // namespace

class TestCliMidBlockCrossing : public QObject {
    Q_OBJECT
private slots:
    void rulesHoldOnTheTrajectories_data()
    {
        QTest::addColumn<int>("row");
        QTest::newRow("two-way, brains, 24 fps, walk 10 s of 30") << 0;
        QTest::newRow("two-way, no brains, 30 fps, walk 6 s of 30") << 1;
        QTest::newRow("two-way, brains, 25 fps, walk 8 s of 24") << 2;
        QTest::newRow("one-way, brains, 24 fps, walk 7 s of 30") << 3;
        QTest::newRow("one-way, no brains, 20 fps, walk 12 s of 40") << 4;
    }

    void rulesHoldOnTheTrajectories()
    {
        QFETCH(int, row);
        // Each walk green starts a second or more after the cars' red begins, and ends
        // (with its yellow) 2 s or more before the cars' next green.
        const Case cases[] = {
            {&kTwoWay, 24, true, {10, 2, 18, -16}, {12, 3, 15, 0}, 6.0},
            {&kTwoWay, 30, false, {6, 3, 21, -18}, {14, 3, 13, 0}, 6.0},
            {&kTwoWay, 25, true, {8, 2, 14, -11}, {8, 2, 14, 0}, 6.0},
            {&kOneWay, 24, true, {7, 2, 21, -19}, {15, 3, 12, 0}, 6.0},
            {&kOneWay, 20, false, {12, 3, 25, -21}, {17, 3, 20, 0}, 6.0},
        };
        const Case& c = cases[row];
        const double duration = 120.0, dt = 1.0 / c.fps;
        QTemporaryDir tmp;
        QFile scene(tmp.filePath("midblock.yaml"));
        QVERIFY(scene.open(QIODevice::WriteOnly));
        scene.write(sceneText(c, duration));
        scene.close();
        const QString csv = tmp.filePath("t.csv"), statsPath = tmp.filePath("s.json");
        const auto r = runCli({"run", scene.fileName().toStdString(), "--trajectories", csv.toStdString(), "--stats",
                               statsPath.toStdString(), "--quiet"});
        QVERIFY2(r.status == 0, r.err.c_str());
        const TrajectoryTable table = TrajectoryTable::read(csv);
        const QJsonObject stats = readStats(statsPath);
        const Layout& L = *c.layout;
        QCOMPARE(table.frames, int(std::lround(duration * c.fps)));

        auto onCarriageway = [&](double x, double z) {
            return std::any_of(L.carriageways.begin(), L.carriageways.end(), [&](const Rect& q) { return q.holds(x, z); });
        };
        auto inStrip = [&](double x, double z) {
            return x > L.strip.x0 && x < L.strip.x1 && z > L.strip.z0 && z < L.strip.z1;
        };
        auto onRoadPart = [&](const TrajectoryRow& p) { return inStrip(p.x, p.z) && onCarriageway(p.x, p.z); };

        // Vehicles are the agents whose first row lies on a lane's centre line.
        std::vector<std::uint32_t> vehicles, walkers;
        for (const auto& [id, rows] : table.agents) {
            const TrajectoryRow& p = rows.begin()->second;
            const bool onLane = std::any_of(L.lanes.begin(), L.lanes.end(), [&](const LaneCheck& l) {
                return std::abs(l.dirX) > 0.5 ? std::abs(p.z - l.lineZ) < 1e-3 : std::abs(p.x - l.lineX) < 1e-3;
            });
            (onLane ? vehicles : walkers).push_back(id);
        }
        QCOMPARE(vehicles.size(), std::size_t(8));

        std::uint64_t walkerRed = 0, offCrosswalk = 0, onRoadAtRedEnd = 0, entries = 0;
        double longestClear = 0.0;
        for (std::uint32_t id : walkers) {
            const auto& rows = table.agents.at(id);
            double redOnRoadSince = -1.0;
            for (auto it = std::next(rows.begin()); it != rows.end(); ++it) {
                const TrajectoryRow& a = std::prev(it)->second;
                const TrajectoryRow& b = it->second;
                const double t = it->first * dt;
                const char phase = c.walk.phaseAt(t);
                const bool on = onRoadPart(b);
                entries += on && !onRoadPart(a);
                if (on && !onRoadPart(a) && phase == 'R') {
                    ++walkerRed;
                    qWarning("walker %u onto the road on red at %.3f s: (%.3f, %.3f) -> (%.3f, %.3f)", id, t, a.x, a.z,
                             b.x, b.z);
                }
                offCrosswalk += onCarriageway(b.x, b.z) && !inStrip(b.x, b.z);
                // On the road while red: since when (from the red's first frame).
                if (phase == 'R' && on) {
                    if (redOnRoadSince < 0.0)
                        redOnRoadSince = t;
                    longestClear = std::max(longestClear, t - redOnRoadSince + dt);
                } else {
                    redOnRoadSince = -1.0;
                }
                if (on && phase == 'R' && c.walk.phaseAt(t + dt) != 'R') {
                    ++onRoadAtRedEnd;
                    qWarning("walker %u on the road at the end of a red, %.2f s: (%.3f, %.3f) at %.2f m/s, heading %.1f", id, t,
                             b.x, b.z, b.speed, b.headingDeg);
                }
            }
        }

        std::uint64_t vehicleRed = 0, unexcused = 0, heldPastLine = 0, wentFromPastLine = 0, lineCrossings = 0;
        for (std::uint32_t id : vehicles) {
            const auto& rows = table.agents.at(id);
            const TrajectoryRow& first = rows.begin()->second;
            const LaneCheck* lane = nullptr;
            for (const LaneCheck& l : L.lanes)
                if (std::abs(l.dirX) > 0.5 ? std::abs(first.z - l.lineZ) < 1e-3 : std::abs(first.x - l.lineX) < 1e-3)
                    lane = &l;
            auto front = [&](const TrajectoryRow& p, double& fx, double& fz) {
                const double h = p.headingDeg * M_PI / 180.0;
                fx = p.x + std::cos(h) * 1.1;
                fz = p.z - std::sin(h) * 1.1;
            };
            bool stoodPastLine = false;
            for (auto it = std::next(rows.begin()); it != rows.end(); ++it) {
                const TrajectoryRow& a = std::prev(it)->second;
                const TrajectoryRow& b = it->second;
                const double t1 = it->first * dt, t0 = t1 - dt;
                double ax, az, bx, bz;
                front(a, ax, az);
                front(b, bx, bz);
                const double la = lane->along(ax, az, lane->lineX, lane->lineZ), lb = lane->along(bx, bz, lane->lineX, lane->lineZ);
                if (la <= 0.0 && lb > 0.0 && lb - la < 10.0) {  // over the line (not a re-entry at the lane's start)
                    ++lineCrossings;
                    const double tc = t0 + dt * (-la) / (lb - la);
                    if (c.cars.phaseAt(tc) == 'R') {
                        ++vehicleRed;
                        // The first frame of this red: step back from the crossing to the red's start.
                        int k = it->first;
                        while (k > 0 && c.cars.phaseAt((k - 1) * dt) == 'R')
                            --k;
                        const TrajectoryRow& s = rows.at(k);
                        double sx, sz;
                        front(s, sx, sz);
                        const double d = -lane->along(sx, sz, lane->lineX, lane->lineZ);
                        const bool couldStop = s.speed * s.speed / (2.0 * 8.0) <= d - 0.05;
                        unexcused += couldStop;
                        if (couldStop)
                            qWarning("vehicle %u over its line on red at %.2f s: at %.2f s %.2f m before it at %.2f m/s", id,
                                     tc, k * dt, d, s.speed);
                    }
                }
                const double sb = lane->along(bx, bz, lane->stripX, lane->stripZ);
                const double sa = lane->along(ax, az, lane->stripX, lane->stripZ);
                if (c.cars.phaseAt(t1) != 'R') {
                    stoodPastLine = false;
                } else if (lb > 0.0 && sb < 0.0 && b.speed < 0.1 && !stoodPastLine) {
                    stoodPastLine = true;
                    ++heldPastLine;
                }
                if (stoodPastLine && sa < 0.0 && sb >= 0.0) {
                    ++wentFromPastLine;
                    qWarning("vehicle %u stood past its line and entered the crosswalk on red at %.2f s", id, t1);
                }
            }
        }

        qInfo("%s: walkers %zu, road entries %llu (%llu on red), longest on the road after red began %.2f s; "
              "vehicle line crossings %llu (%llu on red, %llu could have stopped), stood past the line on red %llu; "
              "stats: pedestrian %d, vehicle %d, car-pedestrian %d, crossings %d / %d",
              L.name, walkers.size(), (unsigned long long)entries, (unsigned long long)walkerRed, longestClear,
              (unsigned long long)lineCrossings, (unsigned long long)vehicleRed, (unsigned long long)unexcused,
              (unsigned long long)heldPastLine, stats["pedestrian_red_light_violations"].toInt(),
              stats["vehicle_red_light_violations"].toInt(), stats["car_pedestrian_collisions"].toInt(),
              stats["pedestrian_crossings"].toInt(), stats["vehicle_crossings"].toInt());

        // Both flow: walkers cross on their greens, cars on theirs.
        QVERIFY(entries >= 40);
        QVERIFY(lineCrossings >= 10);
        QCOMPARE(walkerRed, std::uint64_t(0));
        QCOMPARE(stats["pedestrian_red_light_violations"].toInt(), 0);
        QCOMPARE(unexcused, std::uint64_t(0));
        QCOMPARE(std::uint64_t(stats["vehicle_red_light_violations"].toInt()), vehicleRed);
        QCOMPARE(wentFromPastLine, std::uint64_t(0));
        QCOMPARE(offCrosswalk, std::uint64_t(0));
        QCOMPARE(onRoadAtRedEnd, std::uint64_t(0));
        QVERIFY2(longestClear <= c.maxClearS, qPrintable(QString::number(longestClear)));
        QCOMPARE(stats["car_pedestrian_collisions"].toInt(), 0);
    }

    void aCarStandingPastItsLineWaitsForGreen_data()
    {
        QTest::addColumn<bool>("brain");
        QTest::addColumn<double>("pastM");
        QTest::newRow("car brain, 3 cm past") << true << 0.03;
        QTest::newRow("no brain, 3 cm past") << false << 0.03;
        QTest::newRow("car brain, 1.5 m past") << true << 1.5;
    }

    void aCarStandingPastItsLineWaitsForGreen()
    {
        // The car that drove over the crosswalk on red: standing with its front past its
        // stop line (55 m along the lane, z = 5) and short of the strip (z = 2) while its
        // light is red until 20 s. On main it moved off after its reaction delay, the
        // stop line behind it, and crossed the strip at 5 m/s on red.
        QFETCH(bool, brain);
        QFETCH(double, pastM);
        const QString atM = QString::number(55.0 + pastM - 1.1, 'f', 3);
        const QString text = QString(R"(throng: 1
settings: {fps: 24, duration: 30, seed: 3, bounds: {min: [-30, -70], max: [30, 70]}}
brains:
  - {name: car, file: %1/resources/brains/car.brain.yaml}
agent_types:
  - {name: car, kind: vehicle, radius: 1.1, max_speed: 13.9, max_force: 5000, mass: 1200, perception: 45, view_angle: 90%2}
lanes:
  - {name: north, points: [[1.75, 60], [1.75, -60]], width: 3.5, loop: false}
  - {name: south, points: [[-1.75, -60], [-1.75, 60]], width: 3.5, loop: false}
crosswalks:
  - {name: mid, from: [-6, 0], to: [6, 0], width: 4}
traffic_lights:
  - {name: cars, green: 20, yellow: 3, red: 20, offset: 23, stop_lines: [{lane: north, at: 55}, {lane: south, at: 55}]}
  - {name: walk, green: 15, yellow: 3, red: 25, offset: 0, stop_lines: [{crosswalk: mid}]}
vehicles:
  - {id: 7, type: car, lane: north, at: %3}
)")
                                 .arg(THRONG_SOURCE_DIR, brain ? ", brain: car" : "", atM);
        QTemporaryDir tmp;
        const QString scene = writeText(tmp.filePath("s.yaml"), text.toUtf8().constData());
        const QString csv = tmp.filePath("t.csv"), statsPath = tmp.filePath("s.json");
        const auto r = runCli({"run", scene.toStdString(), "--trajectories", csv.toStdString(), "--stats",
                               statsPath.toStdString(), "--quiet"});
        QVERIFY2(r.status == 0, r.err.c_str());
        const TrajectoryTable table = TrajectoryTable::read(csv);
        const auto& rows = table.agents.at(7);
        const LightTiming cars{20, 3, 20, 23};
        const double dt = 1.0 / 24.0;
        QCOMPARE(cars.phaseAt(0.0), 'R');
        QCOMPARE(cars.phaseAt(19.99), 'R');
        QCOMPARE(cars.phaseAt(20.01), 'G');
        double enteredStripS = -1.0;
        const double startFrontZ = rows.begin()->second.z - 1.1;
        for (const auto& [frame, p] : rows)
            if (enteredStripS < 0.0 && p.z - 1.1 < 2.0)
                enteredStripS = frame * dt;
        qInfo("front starts %.3f m past the line; enters the crosswalk at %.2f s (green at 20 s)", 5.0 - startFrontZ,
              enteredStripS);
        QVERIFY(std::abs(5.0 - startFrontZ - pastM) < 1e-3);
        QVERIFY2(enteredStripS >= 20.0, "not over the crosswalk on red");
        QVERIFY2(enteredStripS < 25.0, "and off on green");
        QCOMPARE(readStats(statsPath)["vehicle_red_light_violations"].toInt(), 0);
    }
};

THRONG_REGISTER_TEST(TestCliMidBlockCrossing)
#include "TestCliMidBlockCrossing.moc"
