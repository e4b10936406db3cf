// Every counter of `throng-cli run --stats` counts a violation that really happens, and
// counts it as often as the trajectories CSV shows it, recomputed here from the rows and
// the scene's own geometry and light timing. A user found them all at 0 while a car drove
// over a crosswalk on red and walkers stepped onto the lane on red; box obstacles were
// never counted at all. Where the simulation prevents a violation, the scene makes it
// happen by construction (an agent placed in an obstacle by a wall, agents inside boxes, a
// keyframed hero, a car too fast to stop, lanes that cross without a signal), and the real
// World counts it.
#include "CliRunner.h"
#include "TestRegistry.h"
#include "TrajectoryTable.h"

#include <QTemporaryDir>
#include <QTest>

#include <algorithm>
#include <array>
#include <cmath>

using namespace throng::test;

namespace {

struct Run {
    TrajectoryTable table;
    QJsonObject stats;
};

Run runScene(const QTemporaryDir& tmp, const char* yaml)
{
    const QString scene = writeText(tmp.filePath("scene.yaml"), yaml);
    const QString csv = tmp.filePath("t.csv"), stats = tmp.filePath("s.json");
    const auto r = runCli({"run", scene.toStdString(), "--threads", "2", "--trajectories", csv.toStdString(), "--stats",
                           stats.toStdString(), "--quiet"});
    if (r.status != 0)
        qWarning("%s", r.err.c_str());
    return {TrajectoryTable::read(csv), readStats(stats)};
}

// A ground box as the scene writes it: centre, full size along its own x and z, angle
// counter-clockwise seen from above (its x axis is (cos a, -sin a) in x, z).
struct Box {
    double cx, cz, w, d, angleDeg;
    std::array<std::array<double, 2>, 4> corners() const
    {
        const double a = angleDeg * M_PI / 180.0;
        const double ux = std::cos(a), uz = -std::sin(a), vx = std::sin(a), vz = std::cos(a);
        std::array<std::array<double, 2>, 4> c;
        const double sx[4] = {-1, 1, 1, -1}, sz[4] = {-1, -1, 1, 1};
        for (int k = 0; k < 4; ++k)
            c[k] = {cx + ux * sx[k] * w / 2 + vx * sz[k] * d / 2, cz + uz * sx[k] * w / 2 + vz * sz[k] * d / 2};
        return c;
    }
    // Distance from a point to the box (0 inside).
    double distance(double x, double z) const
    {
        const double a = angleDeg * M_PI / 180.0;
        const double px = x - cx, pz = z - cz;
        const double u = px * std::cos(a) - pz * std::sin(a), v = px * std::sin(a) + pz * std::cos(a);
        const double ou = std::max(std::abs(u) - w / 2, 0.0), ov = std::max(std::abs(v) - d / 2, 0.0);
        return std::hypot(ou, ov);
    }
};

constexpr double kToleranceM = 0.01;  // the stats' overlap and obstacle tolerance (docs)

// Walls, circles and boxes. Walker 1 stands in a circle obstacle that overlaps a wall:
// walked out of the circle the shortest way, it ends on the wall's other side. Walkers 2
// and 3 stand inside two boxes (one turned 30 degrees) and walk out of them. Hero 9 walks
// through a circle and a box turned 45 degrees.
const char* kWallScene = R"(throng: 1
settings: {fps: 24, duration: 6, seed: 5, bounds: {min: [-30, -30], max: [30, 30]}}
agent_types:
  - {name: walker, kind: pedestrian, radius: 0.3, max_speed: 1.4, max_force: 6}
walls:
  - {points: [[0, -5], [0, 5]]}
obstacles:
  - {shape: circle, center: [-1, 0], radius: 1}
  - {shape: box, center: [10, 0], size: [3, 2]}
  - {shape: box, center: [10, 10], size: [4, 2], angle: 30}
  - {shape: circle, center: [-10, 10], radius: 1.5}
  - {shape: box, center: [-10, -10], size: [2, 2], angle: 45}
agents:
  - {id: 1, type: walker, position: [-0.35, 0]}
  - {id: 2, type: walker, position: [10.2, 0.1]}
  - {id: 3, type: walker, position: [10.5, 10.2]}
heroes:
  - id: 9
    name: cutter
    type: walker
    keyframes:
      - {time: 0, position: [-15, 10]}
      - {time: 3, position: [-5, 10]}
      - {time: 6, position: [-10, -15]}
)";

// A mid-block crossing over a two-lane road running north-south (carriageway |x| <= 3.5),
// the crosswalk strip from x = -6 to 6 over z in [-2, 2]. Walk light: green 0-10, yellow
// 10-12, red 12-30 of each 30 s. Cars' light: red until 17, then green 10, yellow 3, red 17.
// Hero 50 crosses on red (13-23 s), back on green (31-39 s) and again on red (45-55 s).
// Car 60 starts 6 m (front to line) before its stop line at 13.9 m/s while its light is
// red: braking at 8 m/s^2 it needs 12 m, so it runs the red.
const char* kRedScene = R"(throng: 1
settings: {fps: 25, duration: 60, seed: 9, bounds: {min: [-40, -70], max: [40, 70]}}
agent_types:
  - {name: walker, kind: pedestrian, radius: 0.3, max_speed: 1.4, max_force: 6}
  - {name: car, kind: vehicle, radius: 1.1, max_speed: 13.9, max_force: 5000, mass: 1200}
lanes:
  - {name: north, points: [[1.75, 60], [1.75, -60]], width: 3.5, loop: false}
  - {name: south, points: [[-1.75, -60], [-1.75, 60]], width: 3.5, loop: false}
crosswalks:
  - {name: mid, from: [-6, 0], to: [6, 0], width: 4}
traffic_lights:
  - {name: cars, green: 10, yellow: 3, red: 17, offset: 13, stop_lines: [{lane: north, at: 55}, {lane: south, at: 55}]}
  - {name: walk, green: 10, yellow: 2, red: 18, stop_lines: [{crosswalk: mid}]}
vehicles:
  - {id: 60, type: car, lane: north, at: 47.9, speed: 13.9}
heroes:
  - id: 50
    name: jaywalker
    type: walker
    keyframes:
      - {time: 0, position: [-9, 0.5]}
      - {time: 13, position: [-9, 0.5]}
      - {time: 23, position: [9, 0.5]}
      - {time: 31, position: [9, 0.5]}
      - {time: 39, position: [-9, 0.5]}
      - {time: 45, position: [-9, 0.5]}
      - {time: 55, position: [9, 0.5]}
      - {time: 60, position: [9, 0.5]}
)";

// Two lanes crossing at the origin with no signal: cars 101 (eastbound) and 102
// (northbound) reach the crossing together and drive through each other. Hero 201 steps
// onto the eastbound lane about 6 m in front of car 101 at 13 m/s (it needs 11 m to stop),
// stands there 3 s, and leaves; the car cannot stop and drives through it. Heroes 202 and 203 walk through each other.
const char* kContactScene = R"(throng: 1
settings: {fps: 24, duration: 12, seed: 2, bounds: {min: [-70, -50], max: [70, 50]}}
agent_types:
  - {name: walker, kind: pedestrian, radius: 0.3, max_speed: 1.4, max_force: 6}
  - {name: car, kind: vehicle, radius: 1.1, max_speed: 13.9, max_force: 5000, mass: 1200}
lanes:
  - {name: ew, points: [[-60, 0], [60, 0]], width: 3.5, loop: false}
  - {name: ns, points: [[0, 40], [0, -40]], width: 3.5, loop: false}
vehicles:
  - {id: 101, type: car, lane: ew, at: 30, speed: 10}
  - {id: 102, type: car, lane: ns, at: 10, speed: 10}
heroes:
  - id: 201
    name: stepper
    type: walker
    keyframes:
      - {time: 0, position: [35, -4]}
      - {time: 4.6, position: [35, -4]}
      - {time: 5, position: [35, 0]}
      - {time: 8, position: [35, 0]}
      - {time: 9, position: [35, -4]}
  - id: 202
    name: left
    type: walker
    keyframes: [{time: 0, position: [-10, 10]}, {time: 6, position: [10, 10]}]
  - id: 203
    name: right
    type: walker
    keyframes: [{time: 0, position: [10, 10.2]}, {time: 6, position: [-10, 10.2]}]
)";


// 60 walkers spawned at random in a small room, pressing through a 1 m door.
const char* const kDenseRoom = R"(throng: 1
settings: {fps: 24, duration: 12, seed: 5, bounds: {min: [-6, -6], max: [8, 6]}}
agent_types:
  - {name: walker, radius: 0.25}
walls:
  - {points: [[4, 0.5], [4, 4], [-4, 4], [-4, -4], [4, -4], [4, -0.5]]}
goals:
  - {name: door, position: [4.3, 0], radius: 0.5, exit: true}
groups:
  - {name: crowd, type: walker, count: 60, rect: {min: [-3.5, -3.5], max: [3, 3.5]}, goal: door}
)";

}  // namespace

class TestCliCounters : public QObject {
    Q_OBJECT
private slots:
    void wallAndObstaclePenetrations()
    {
        QTemporaryDir tmp;
        const Run run = runScene(tmp, kWallScene);
        QVERIFY(run.table.frames == 144);
        // Wall segments as walkers meet them: the wall, and each box's four sides.
        std::vector<std::array<double, 4>> walls = {{0, -5, 0, 5}};
        const std::vector<Box> boxes = {{10, 0, 3, 2, 0}, {10, 10, 4, 2, 30}, {-10, -10, 2, 2, 45}};
        for (const Box& b : boxes) {
            const auto c = b.corners();
            for (int k = 0; k < 4; ++k)
                walls.push_back({c[k][0], c[k][1], c[(k + 1) % 4][0], c[(k + 1) % 4][1]});
        }
        const std::vector<std::array<double, 3>> circles = {{-1, 0, 1}, {-10, 10, 1.5}};
        std::uint64_t crossings = 0, inObstacle = 0, inBox = 0;
        for (const auto& [id, rows] : run.table.agents) {
            for (auto it = std::next(rows.begin()); it != rows.end(); ++it) {
                const TrajectoryRow& a = std::prev(it)->second;
                const TrajectoryRow& b = it->second;
                // A walker that starts inside a box walks out across that box's side: that
                // crossing is the way out of a bad placement, not a penetration (docs/stats.md).
                auto ownBoxSide = [&](const std::array<double, 4>& w) {
                    for (const Box& box : boxes)
                        if (box.distance(a.x, a.z) == 0.0 && box.distance(rows.begin()->second.x, rows.begin()->second.z) == 0.0 &&
                            box.distance(0.5 * (w[0] + w[2]), 0.5 * (w[1] + w[3])) < 1e-6)
                            return true;
                    return false;
                };
                if (id != 9)  // the hero goes where its keyframes say: no wall holds it
                    for (const auto& w : walls)
                        crossings += segmentsCrossD(a.x, a.z, b.x, b.z, w[0], w[1], w[2], w[3]) && !ownBoxSide(w);
                for (const auto& c : circles)
                    inObstacle += std::hypot(b.x - c[0], b.z - c[1]) < c[2] + 0.3 - kToleranceM;
                for (const Box& box : boxes) {
                    const bool in = box.distance(b.x, b.z) < 0.3 - kToleranceM;
                    inObstacle += in;
                    inBox += in;
                }
            }
        }
        const QJsonObject& s = run.stats;
        qInfo("wall crossings %llu (stats %d); obstacle agent-steps %llu, %llu in boxes (stats %d)",
              (unsigned long long)crossings, s["wall_penetrations"].toInt(), (unsigned long long)inObstacle,
              (unsigned long long)inBox, s["obstacle_penetrations"].toInt());
        // Walker 1 crossed the wall once (its shortest way out of the circle lies across
        // it); walkers 2 and 3 walk out of the boxes they start in, over some steps; the
        // hero passes through a circle and a box.
        QCOMPARE(crossings, std::uint64_t(1));
        QCOMPARE(std::uint64_t(s["wall_penetrations"].toInt()), crossings);
        QVERIFY(inBox >= 20);
        QVERIFY(inObstacle > inBox);
        QCOMPARE(std::uint64_t(s["obstacle_penetrations"].toInt()), inObstacle);
    }

    void redLightViolationsOfWalkersAndVehicles()
    {
        QTemporaryDir tmp;
        const Run run = runScene(tmp, kRedScene);
        const double dt = 1.0 / 25.0;
        const LightTiming walk{10, 2, 18, 0}, cars{10, 3, 17, 13};
        QCOMPARE(run.table.frames, 1500);
        // A walker steps onto the road on red: its centre inside the strip and on the
        // carriageway (|x| <= 3.5, |z| < 2) on a frame whose time is red, and not on the frame before.
        auto onRoad = [](const TrajectoryRow& r) { return std::abs(r.x) <= 3.5 && std::abs(r.z) < 2; };
        std::uint64_t walkerRed = 0, walkerEntries = 0, vehicleRed = 0, vehicleCrossings = 0;
        for (const auto& [id, rows] : run.table.agents)
            for (auto it = std::next(rows.begin()); it != rows.end(); ++it) {
                const TrajectoryRow& a = std::prev(it)->second;
                const TrajectoryRow& b = it->second;
                const double t = it->first * dt;
                if (id == 50 && onRoad(b) && !onRoad(a)) {
                    ++walkerEntries;
                    walkerRed += walk.phaseAt(t) == 'R';
                }
                if (id == 60) {
                    // The car's front (centre + heading x radius) over the line z = 5 (at 55 m
                    // along a lane starting at z = 60), timed within the step.
                    const double fa = a.z - std::sin(a.headingDeg * M_PI / 180.0) * 1.1;
                    const double fb = b.z - std::sin(b.headingDeg * M_PI / 180.0) * 1.1;
                    if (fa >= 5.0 && fb < 5.0) {
                        ++vehicleCrossings;
                        vehicleRed += cars.phaseAt(t - dt + dt * (fa - 5.0) / (fa - fb)) == 'R';
                    }
                }
            }
        const QJsonObject& s = run.stats;
        qInfo("walker road entries %llu, %llu on red; car line crossings %llu, %llu on red",
              (unsigned long long)walkerEntries, (unsigned long long)walkerRed, (unsigned long long)vehicleCrossings,
              (unsigned long long)vehicleRed);
        QCOMPARE(walkerEntries, std::uint64_t(3));
        QCOMPARE(walkerRed, std::uint64_t(2));
        QCOMPARE(std::uint64_t(s["pedestrian_red_light_violations"].toInt()), walkerRed);
        QVERIFY(vehicleCrossings >= 1);
        QCOMPARE(vehicleRed, std::uint64_t(1));
        QCOMPARE(std::uint64_t(s["vehicle_red_light_violations"].toInt()), vehicleRed);
        QCOMPARE(std::uint64_t(s["red_light_violations"].toInt()), walkerRed + vehicleRed);
    }

    void contactsAndOverlaps()
    {
        QTemporaryDir tmp;
        const Run run = runScene(tmp, kContactScene);
        QCOMPARE(run.table.frames, 288);
        auto radius = [](std::uint32_t id) { return id < 200 ? 1.1 : 0.3; };
        std::uint64_t carCar = 0, carWalker = 0, overlaps = 0;
        std::vector<double> depths;  // of each overlapping pair-step, as a fraction of r1 + r2
        std::vector<std::uint32_t> ids;
        for (const auto& [id, rows] : run.table.agents)
            ids.push_back(id);
        for (int f = 1; f < run.table.frames; ++f)
            for (std::size_t i = 0; i < ids.size(); ++i)
                for (std::size_t j = i + 1; j < ids.size(); ++j) {
                    const TrajectoryRow& a = run.table.agents.at(ids[i]).at(f);
                    const TrajectoryRow& b = run.table.agents.at(ids[j]).at(f);
                    const double d = std::hypot(a.x - b.x, a.z - b.z), r = radius(ids[i]) + radius(ids[j]);
                    const bool cars = ids[i] < 200 && ids[j] < 200, mixed = (ids[i] < 200) != (ids[j] < 200);
                    carCar += cars && d < r;
                    carWalker += mixed && d < r;
                    if (d < r - kToleranceM) {
                        ++overlaps;
                        depths.push_back((r - d) / r);
                    }
                }
        const QJsonObject& s = run.stats;
        qInfo("car-car contact steps %llu, car-walker %llu, overlapping pairs %llu",
              (unsigned long long)carCar, (unsigned long long)carWalker, (unsigned long long)overlaps);
        // Through each other at 10 m/s each: about 2.2 m * sqrt(2) * 2 / 14 m/s = 0.44 s.
        QVERIFY(carCar >= 6);
        // The car brakes at 8 m/s^2 from 13 m/s but reaches the hero at about 7.6 m/s and
        // passes through it: 2 x 1.4 m at that speed, about 0.35 s.
        QVERIFY(carWalker >= 5);
        QVERIFY(overlaps > carCar + carWalker);  // the two heroes' pass too
        QCOMPARE(std::uint64_t(s["vehicle_collisions"].toInt()), carCar);
        QCOMPARE(std::uint64_t(s["car_pedestrian_collisions"].toInt()), carWalker);
        QCOMPARE(std::uint64_t(s["overlapping_pairs"].toInt()), overlaps);
        // How deep: the deepest overlap, and the 95th percentile as the upper edge of the
        // half-percent bin that holds it (docs/stats.md), recomputed from the CSV.
        std::sort(depths.begin(), depths.end());
        const double deepest = depths.back();
        const std::size_t rank = std::size_t(std::ceil(0.95 * double(depths.size())));
        const double p95 = std::floor(depths[std::max<std::size_t>(rank, 1) - 1] * 200.0 + 1.0) / 200.0;
        qInfo("overlap depth: p95 %.3f, deepest %.4f of r1 + r2 (stats %.3f, %.4f)", p95, deepest,
              s["overlap_depth_p95"].toDouble(), s["overlap_depth_max"].toDouble());
        QVERIFY(deepest > 0.3);  // cars drive through each other
        QVERIFY(std::abs(s["overlap_depth_max"].toDouble() - deepest) < 1e-4);
        QVERIFY(std::abs(s["overlap_depth_p95"].toDouble() - p95) < 0.005 + 1e-9);  // one bin: the CSV rounds
    }

    void overlapDepthsInADenseRoom()
    {
        // 60 walkers spawned in a small room, pressing through a 1 m door, and 12 pairs placed
        // by hand pressed 20 % to 86 % into each other (a group's members spawn clear of each
        // other, a brush stroke's need not): the pairs part over the first frames. Every
        // overlapping pair-step's depth, recomputed from the CSV, gives the stats' percentile
        // and maximum.
        std::string scene = std::string(kDenseRoom) + "agents:\n";
        for (int k = 0; k < 12; ++k) {
            const double depth = 0.2 + 0.06 * k, gap = 0.5 * (1.0 - depth), x = -3.3 + 0.55 * k;
            scene += "  - {id: " + std::to_string(2 * k + 1) + ", type: walker, position: [" + std::to_string(x) +
                     ", -3.5], goal: door}\n";
            scene += "  - {id: " + std::to_string(2 * k + 2) + ", type: walker, position: [" + std::to_string(x) +
                     ", " + std::to_string(-3.5 + gap) + "], goal: door}\n";
        }
        QTemporaryDir tmp;
        const Run run = runScene(tmp, scene.c_str());
        std::vector<double> depths;
        std::vector<std::uint32_t> ids;
        for (const auto& [id, rows] : run.table.agents)
            ids.push_back(id);
        for (int f = 1; f < run.table.frames; ++f)
            for (std::size_t i = 0; i < ids.size(); ++i)
                for (std::size_t j = i + 1; j < ids.size(); ++j) {
                    const auto& ra = run.table.agents.at(ids[i]);
                    const auto& rb = run.table.agents.at(ids[j]);
                    if (!ra.count(f) || !rb.count(f))
                        continue;  // left through the exit
                    const double d = std::hypot(ra.at(f).x - rb.at(f).x, ra.at(f).z - rb.at(f).z);
                    if (d < 0.5 - kToleranceM)
                        depths.push_back((0.5 - d) / 0.5);
                }
        QCOMPARE(std::uint64_t(run.stats["overlapping_pairs"].toInt()), std::uint64_t(depths.size()));
        QVERIFY(depths.size() >= 20);
        std::sort(depths.begin(), depths.end());
        const std::size_t rank = std::size_t(std::ceil(0.95 * double(depths.size())));
        const double p95 = std::floor(depths[rank - 1] * 200.0 + 1.0) / 200.0;
        qInfo("dense room: %zu overlapping pair-steps, depth p95 %.3f, deepest %.4f of r1 + r2 (stats %.3f, %.4f)",
              depths.size(), p95, depths.back(), run.stats["overlap_depth_p95"].toDouble(),
              run.stats["overlap_depth_max"].toDouble());
        QVERIFY(p95 < depths.back());
        QVERIFY(std::abs(run.stats["overlap_depth_max"].toDouble() - depths.back()) < 1e-4);
        QVERIFY(std::abs(run.stats["overlap_depth_p95"].toDouble() - p95) < 0.005 + 1e-9);
    }

    void peakDensityInADenseRoom()
    {
        // The same dense room: the crowd packs at the door. The peak local density, recounted
        // from the CSV at the instants the stats sample (every 0.5 s: frames 12, 24, ... at
        // 24 fps) with the kernel docs/stats.md gives, is the stats' figure, and it is not
        // beyond what bodies of 0.25 m can pack (touching hexagonally: 1 / (2 sqrt(3) r²)).
        QTemporaryDir tmp;
        const Run run = runScene(tmp, kDenseRoom);
        const double sigma = 0.5, norm = 1.0 / (2.0 * M_PI * sigma * sigma * (1.0 - std::exp(-4.5)));
        double peak = 0.0, peakS = -1.0;
        int samples = 0;
        for (int f = 12; f < run.table.frames; f += 12) {
            ++samples;
            std::vector<std::pair<double, double>> at;
            for (const auto& [id, rows] : run.table.agents)
                if (rows.count(f))
                    at.emplace_back(rows.at(f).x, rows.at(f).z);
            for (const auto& [x, z] : at) {
                double density = 0.0;
                for (const auto& [x2, z2] : at) {
                    const double d2 = (x - x2) * (x - x2) + (z - z2) * (z - z2);
                    density += d2 < 9.0 * sigma * sigma ? std::exp(-d2 / (2.0 * sigma * sigma)) * norm : 0.0;
                }
                if (density > peak) {
                    peak = density;
                    peakS = f / 24.0;
                }
            }
        }
        const double stats = run.stats["peak_density_per_m2"].toDouble();
        const double packed = 1.0 / (2.0 * std::sqrt(3.0) * 0.25 * 0.25);
        qInfo("dense room: peak density %.3f persons/m2 at %.1f s over %d samples (stats %.3f at %.3f s); "
              "touching discs pack %.2f",
              peak, peakS, samples, stats, run.stats["peak_density_time_s"].toDouble(), packed);
        QVERIFY(samples >= 20);
        QVERIFY2(peak > 2.0, "the room never got dense: the test shows nothing");
        QVERIFY(std::abs(stats - peak) < 1e-3 * peak);
        QVERIFY(std::abs(run.stats["peak_density_time_s"].toDouble() - peakS) < 1e-4);
        QVERIFY2(peak <= packed, qPrintable(QString("%1 persons/m2, beyond %2").arg(peak).arg(packed)));
    }

    void peakDensityOfAPackedLattice()
    {
        // 225 walkers of 0.3 m standing touching in a hexagonal lattice (0.6 m apart), with
        // nowhere to go: the densest the bodies can stand. In the middle of it the kernel
        // gives the lattice's density, 1 / (2 sqrt(3) 0.3²) = 3.208 persons/m².
        std::string yaml = "throng: 1\n"
                           "settings: {fps: 24, duration: 1, seed: 1, bounds: {min: [-10, -10], max: [20, 20]}}\n"
                           "agent_types:\n"
                           "  - {name: walker, radius: 0.3}\n"
                           "agents:\n";
        int id = 1;
        for (int row = 0; row < 15; ++row)
            for (int col = 0; col < 15; ++col) {
                const double x = 0.6 * col + (row % 2 ? 0.3 : 0.0), z = 0.6 * std::sqrt(0.75) * row;
                yaml += "  - {id: " + std::to_string(id++) + ", type: walker, position: [" + std::to_string(x) +
                        ", " + std::to_string(z) + "]}\n";
            }
        QTemporaryDir tmp;
        const Run run = runScene(tmp, yaml.c_str());
        const double packed = 1.0 / (2.0 * std::sqrt(3.0) * 0.3 * 0.3);
        const double peak = run.stats["peak_density_per_m2"].toDouble();
        qInfo("packed lattice: peak density %.4f persons/m2, the lattice's %.4f", peak, packed);
        QCOMPARE(run.stats["overlapping_pairs"].toInt(), 0);
        QVERIFY(std::abs(peak - packed) < 0.01 * packed);
        QVERIFY(std::abs(run.stats["peak_density_time_s"].toDouble() - 0.5) < 1e-4);
    }

    void vehiclesWaitingOffStageDoNotOverlap()
    {
        // Cars that leave an open lane wait off stage at its end to re-enter; they stand
        // on one point there. overlapping_pairs counted them every step (219 pair-steps in
        // an 8-car mid-block scene whose vehicle_collisions was 0).
        QTemporaryDir tmp;
        const Run run = runScene(tmp, R"(throng: 1
settings: {fps: 24, duration: 10, seed: 4, bounds: {min: [-30, -30], max: [30, 30]}}
agent_types:
  - {name: car, kind: vehicle, radius: 1.1, max_speed: 13.9, max_force: 5000, mass: 1200}
lanes:
  - {name: short, points: [[-20, 0], [20, 0]], width: 3.5, loop: false}
vehicles:
  - {id: 1, type: car, lane: short, at: 25, speed: 10}
  - {id: 2, type: car, lane: short, at: 33, speed: 10}
  - {id: 3, type: car, lane: short, at: 38, speed: 10}
)");
        auto offStage = [](const TrajectoryRow& r) { return r.x == 20.0 && r.z == 0.0 && r.speed == 0.0; };
        std::uint64_t together = 0, overlaps = 0;
        for (int f = 1; f < run.table.frames; ++f)
            for (std::uint32_t a = 1; a <= 3; ++a)
                for (std::uint32_t b = a + 1; b <= 3; ++b) {
                    const TrajectoryRow& p = run.table.agents.at(a).at(f);
                    const TrajectoryRow& q = run.table.agents.at(b).at(f);
                    together += offStage(p) && offStage(q);
                    if (!offStage(p) && !offStage(q))
                        overlaps += std::hypot(p.x - q.x, p.z - q.z) < 2.2 - kToleranceM;
                }
        qInfo("pair-steps with both cars off stage at the lane's end: %llu; overlapping on stage: %llu",
              (unsigned long long)together, (unsigned long long)overlaps);
        QVERIFY(together >= 10);
        QCOMPARE(std::uint64_t(run.stats["overlapping_pairs"].toInt()), overlaps);
        QCOMPARE(run.stats["vehicle_collisions"].toInt(), 0);
    }
};

THRONG_REGISTER_TEST(TestCliCounters)
#include "TestCliCounters.moc"
