// The analysis of a run (issue 26's plots): crossings of a measurement line, the density
// heatmap, speed against density in a measurement area, the agents in the scene and out
// through each exit, and the time to evacuate — each recounted here from the positions the
// World reports while it steps, not from the frame cache the analysis reads; the same
// figures at far coordinates; and the scene file's `measurements`, kept and checked.
#include "TestRegistry.h"

#include "simcore/analysis/RunAnalysis.h"
#include "simcore/io/SceneIO.h"
#include "simcore/world/RunStats.h"
#include "simcore/world/World.h"

#include <QTest>

#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using namespace throng;
using namespace throng::sim;

namespace {

Scene parseAnalysed(const std::string& yaml)
{
    const LoadResult r = parseScene(yaml, "analysed.yaml", "");
    if (!r.ok())
        qFatal("%s", r.diagnostics[0].format().c_str());
    return r.scene;
}

// What the test sees of each step, straight from the World: every agent's (x, z) in scene
// coordinates and whether it is in the shot.
struct Watched {
    Scene scene;
    FrameCache cache;
    std::vector<std::vector<glm::dvec2>> at;    // [frame][agent]
    std::vector<std::vector<char>> inShot;      // [frame][agent]
    std::vector<std::vector<char>> out;         // [frame][agent]
    RunStats stats;
};

Watched watch(const std::string& yaml, double seconds)
{
    Watched w;
    w.scene = parseAnalysed(yaml);
    World world(w.scene, WorldOptions{0, false, 1});
    world.startRecording(w.cache);
    auto look = [&] {
        std::vector<glm::dvec2> p(world.agentCount());
        std::vector<char> in(world.agentCount()), out(world.agentCount());
        for (std::size_t i = 0; i < p.size(); ++i) {
            const glm::vec3 at = world.positions()[i];
            p[i] = {double(at.x) + world.origin().x, double(at.z) + world.origin().z};
            out[i] = world.isOut(i) ? 1 : 0;
            in[i] = out[i] ? 0 : 1;
        }
        w.at.push_back(std::move(p));
        w.inShot.push_back(std::move(in));
        w.out.push_back(std::move(out));
    };
    look();
    std::vector<AgentFrame> frame;
    while (world.timeS() < seconds - 1e-9) {
        world.step();
        world.snapshot(frame);
        w.cache.append(frame);
        look();
    }
    w.stats = RunStats::from(world, w.cache.frameCount(), 0.0);
    return w;
}

// 40 walkers start in [0, 8] x [-3, 3] and walk east to an exit at x = 40; a measurement
// line across the way at x = 20 and an 8 m x 8 m area around it; everything shifted by
// `shift` metres in x and z.
std::string corridor(double shift = 0.0, const char* extra = "")
{
    auto at = [&](double x, double z) {
        std::ostringstream s;
        s.precision(12);
        s << "[" << x + shift << ", " << z + shift << "]";
        return s.str();
    };
    std::ostringstream y;
    y << "throng: 1\nsettings: {fps: 24, seed: 3, duration: 60, bounds: {min: " << at(-5, -10) << ", max: "
      << at(45, 10) << "}}\n"
      << "agent_types:\n  - {name: walker, radius: 0.25, max_speed: 1.3, variation: {speed: [1, 1]}}\n"
      << "goals:\n  - {name: out, position: " << at(40, 0) << ", radius: 3, exit: true}\n"
      << "groups:\n  - {name: crowd, type: walker, count: 40, rect: {min: " << at(0, -3) << ", max: " << at(8, 3)
      << "}, goal: out}\n"
      << "measurements:\n"
      << "  - {name: gate, line: [" << at(20, -6) << ", " << at(20, 6) << "]}\n"
      << "  - {name: middle, area: [" << at(16, -4) << ", " << at(24, -4) << ", " << at(24, 4) << ", " << at(16, 4)
      << "]}\n"
      << extra;
    return y.str();
}

// (frame, walker) of every step that takes a walker in the shot east over x = lineX (or
// west, with eastward false) within |z - zMid| <= 6: the recount of a line's crossings.
std::vector<std::pair<std::size_t, std::size_t>> stepsOver(const Watched& w, double lineX, double zMid,
                                                           bool eastward = true)
{
    std::vector<std::pair<std::size_t, std::size_t>> steps;
    for (std::size_t f = 1; f < w.at.size(); ++f)
        for (std::size_t i = 0; i < w.at[f].size(); ++i) {
            if (!w.inShot[f - 1][i])
                continue;
            const glm::dvec2 p = w.at[f - 1][i], q = w.at[f][i];
            if (eastward ? p.x < lineX && q.x >= lineX : p.x >= lineX && q.x < lineX) {
                const double z = p.y + (q.y - p.y) * (lineX - p.x) / (q.x - p.x);
                if (std::abs(z - zMid) <= 6.0)
                    steps.push_back({f, i});
            }
        }
    return steps;
}

}  // namespace

class TestRunAnalysis : public QObject {
    Q_OBJECT

private slots:
    void aLineCountsEveryWalkerThatCrossesIt()
    {
        const Watched w = watch(corridor(), 50.0);
        const std::vector<LineFlow> lines = countLineCrossings(w.scene, w.cache);
        QCOMPARE(lines.size(), std::size_t(1));
        const LineFlow& gate = lines[0];
        QCOMPARE(gate.name, std::string("gate"));
        QCOMPARE(gate.lengthM, 12.0f);
        const auto recount = stepsOver(w, 20.0, 0.0);
        // Every walker walked through the gate once, eastward, which is the line's forward
        // side: (z1 - z0, x0 - x1) = (12, 0).
        QCOMPARE(recount.size(), std::size_t(40));
        QCOMPARE(gate.forward, std::uint64_t(40));
        QCOMPARE(gate.backward, std::uint64_t(0));
        QCOMPARE(gate.crossings.size(), recount.size());
        for (std::size_t k = 0; k < recount.size(); ++k) {
            QCOMPARE(gate.crossings[k].frame, recount[k].first);
            QCOMPARE(std::size_t(gate.crossings[k].agent), recount[k].second);
            QVERIFY(gate.crossings[k].forward);
        }
        // The flow over time holds every crossing, in the bin of the second it happened in.
        const std::vector<double> flow = flowPerSecond(gate, w.cache.fps(), w.cache.frameCount(), 2.0);
        QCOMPARE(flow.size(), std::size_t(std::ceil(double(w.cache.frameCount()) / 24.0 / 2.0 - 1e-9)));
        double total = 0.0;
        for (double perS : flow)
            total += perS * 2.0;
        QCOMPARE(total, 40.0);
        const std::size_t firstBin = recount.front().first / 48;
        QVERIFY(flow[firstBin] > 0.0);
        for (std::size_t k = 0; k < firstBin; ++k)
            QCOMPARE(flow[k], 0.0);
    }

    void aLineDrawnTheOtherWayCountsTheSameWalkersBackward()
    {
        std::string yaml = corridor();
        const std::string from = "[[20, -6], [20, 6]]", to = "[[20, 6], [20, -6]]";
        yaml.replace(yaml.find(from), from.size(), to);
        const Watched w = watch(yaml, 50.0);
        const LineFlow gate = countLineCrossings(w.scene, w.cache)[0];
        QCOMPARE(gate.forward, std::uint64_t(0));
        QCOMPARE(gate.backward, std::uint64_t(40));
    }

    void theDensityMapTotalsTheWalkersInTheShot()
    {
        const Watched w = watch(corridor(), 50.0);
        for (std::size_t f : {std::size_t(0), std::size_t(300), std::size_t(700), w.cache.frameCount() - 1}) {
            const DensityMap one = densityMap(w.scene, w.cache, 1.0, f, f + 1);
            std::size_t inShot = 0;
            for (char c : w.inShot[f])
                inShot += std::size_t(c);
            QCOMPARE(one.totalPersons(), double(inShot));
            // Each walker is in the cell its position falls in.
            std::vector<double> recount(one.cols * one.rows, 0.0);
            for (std::size_t i = 0; i < w.at[f].size(); ++i)
                if (w.inShot[f][i])
                    recount[std::size_t(std::floor(w.at[f][i].y + 10.0)) * one.cols +
                            std::size_t(std::floor(w.at[f][i].x + 5.0))] += 1.0;
            QCOMPARE(one.persons, recount);
        }
        // At the start the crowd fills its rectangle: 40 walkers in 8 m x 6 m.
        const DensityMap start = densityMap(w.scene, w.cache, 1.0, 0, 1);
        QCOMPARE(start.cols, std::size_t(50));
        QCOMPARE(start.rows, std::size_t(20));
        double inRect = 0.0;
        for (std::size_t r = 7; r < 13; ++r)
            for (std::size_t c = 5; c < 13; ++c)
                inRect += start.personsAt(c, r);
        QCOMPARE(inRect, 40.0);
        // Over the whole run, the map holds the mean count of walkers in the shot.
        const DensityMap all = densityMap(w.scene, w.cache, 1.0, 0, w.cache.frameCount());
        double mean = 0.0;
        for (std::size_t f = 0; f < w.cache.frameCount(); ++f)
            for (char c : w.inShot[f])
                mean += double(c);
        mean /= double(w.cache.frameCount());
        QVERIFY(mean > 5.0 && mean < 40.0);
        QVERIFY(std::abs(all.totalPersons() - mean) < 1e-9);
        QCOMPARE(all.outsidePersons, 0.0);
    }

    void anAreaMeasuresDensityAndSpeed()
    {
        // 4 x 5 walkers standing 1 m apart, with nowhere to go, inside a 10 m x 8 m area:
        // 0.25 persons per m² and no speed; and the corridor's free walkers at their speed.
        std::ostringstream y;
        y << "throng: 1\nsettings: {fps: 30, seed: 1, duration: 2}\n"
             "agent_types:\n  - {name: walker, radius: 0.2, max_speed: 1.3}\n"
             "agents:\n";
        for (int i = 0; i < 20; ++i)
            y << "  - {id: " << i + 1 << ", type: walker, position: [" << (i % 4) << ", 0, " << (i / 4) << "]}\n";
        y << "measurements:\n  - {name: room, area: [[-3, -1.5], [7, -1.5], [7, 6.5], [-3, 6.5]]}\n"
             "  - {name: empty, area: [[20, 20], [21, 20], [20.5, 21]]}\n";
        const Watched standing = watch(y.str(), 2.0);
        const std::vector<AreaSpeedDensity> areas = measureSpeedDensity(standing.scene, standing.cache, 1);
        QCOMPARE(areas.size(), std::size_t(2));
        QCOMPARE(areas[0].areaM2, 80.0);
        QCOMPARE(areas[0].samples.size(), standing.cache.frameCount());
        for (const SpeedDensitySample& s : areas[0].samples) {
            QCOMPARE(s.walkers, 20u);
            QCOMPARE(s.densityPerM2, 0.25);
            QVERIFY(s.speedMps < 1e-6);
        }
        QVERIFY(areas[1].samples.empty());  // nobody in it: no sample, not a zero density

        const Watched walking = watch(corridor(), 50.0);
        const AreaSpeedDensity middle = measureSpeedDensity(walking.scene, walking.cache, 1)[0];
        QCOMPARE(middle.areaM2, 64.0);
        QVERIFY(middle.samples.size() > 100);
        for (const SpeedDensitySample& s : middle.samples) {
            std::uint32_t inside = 0;
            for (std::size_t i = 0; i < walking.at[s.frame].size(); ++i) {
                const glm::dvec2 p = walking.at[s.frame][i];
                inside += walking.inShot[s.frame][i] && p.x > 16 && p.x < 24 && p.y > -4 && p.y < 4 ? 1 : 0;
            }
            QCOMPARE(s.walkers, inside);
            QCOMPARE(s.densityPerM2, double(inside) / 64.0);
            // Below 1 person per m² walkers keep near their free speed of 1.3 m/s.
            if (s.densityPerM2 < 0.3)
                QVERIFY2(s.speedMps > 1.0 && s.speedMps < 1.35, qPrintable(QString::number(s.speedMps)));
        }
    }

    void weidmannsCurve()
    {
        QCOMPARE(weidmannSpeed(0.0), 1.34);
        QVERIFY(std::abs(weidmannSpeed(1.0) - 1.0584) < 1e-3);
        QVERIFY(std::abs(weidmannSpeed(2.0) - 0.6062) < 1e-3);
        QVERIFY(std::abs(weidmannSpeed(5.4)) < 1e-12);
        QCOMPARE(weidmannSpeed(6.0), 0.0);
        for (double rho = 0.1; rho < 5.4; rho += 0.1)
            QVERIFY(weidmannSpeed(rho + 0.1) < weidmannSpeed(rho));
    }

    void occupancyCountsWhoLeftByWhichExitAndWhen()
    {
        // 30 walkers bound for the east exit and 20 for a west one; then the same with one
        // more walker who stays.
        std::string yaml = corridor(0.0, "  - {name: west, line: [[-0.5, -6], [-0.5, 6]]}\n");
        const std::string goals = "goals:\n  - {name: out, position: [40, 0], radius: 3, exit: true}\n";
        yaml.replace(yaml.find(goals), goals.size(),
                     goals + "  - {name: back, position: [-3, 0], radius: 2, exit: true}\n");
        const std::string group = "count: 40, rect: {min: [0, -3], max: [8, 3]}, goal: out}\n";
        yaml.replace(yaml.find(group), group.size(),
                     "count: 30, rect: {min: [4, -3], max: [8, 3]}, goal: out}\n"
                     "  - {name: homeward, type: walker, count: 20, rect: {min: [0, -3], max: [3, 3]}, goal: back}\n");
        const Watched w = watch(yaml, 50.0);
        const Occupancy o = measureOccupancy(w.scene, w.cache);
        QCOMPARE(o.exits.size(), std::size_t(2));
        QCOMPARE(o.exits[0].exit, std::string("out"));
        QCOMPARE(o.exits[1].exit, std::string("back"));
        // Recount: each walker leaves on the first frame it is out, by the exit on its side.
        std::vector<std::size_t> east, west;
        for (std::size_t f = 1; f < w.out.size(); ++f)
            for (std::size_t i = 0; i < w.out[f].size(); ++i)
                if (w.out[f][i] && !w.out[f - 1][i])
                    (w.at[f][i].x > 20.0 ? east : west).push_back(f);
        QCOMPARE(east.size(), std::size_t(30));
        QCOMPARE(west.size(), std::size_t(20));
        QCOMPARE(o.exits[0].frames, east);
        QCOMPARE(o.exits[1].frames, west);
        QCOMPARE(o.exits[0].agentsOut(), w.stats.nav.exits[0].agentsOut);
        QCOMPARE(o.exits[1].agentsOut(), w.stats.nav.exits[1].agentsOut);
        for (std::size_t f = 0; f < w.cache.frameCount(); ++f) {
            std::uint32_t in = 0, out = 0;
            for (std::size_t i = 0; i < w.out[f].size(); ++i)
                (w.out[f][i] ? out : in) += 1;
            QCOMPARE(o.inScene[f], in);
            QCOMPARE(o.out[f], out);
        }
        QCOMPARE(o.peakInScene, std::uint64_t(50));
        // Everybody left: the time to evacuate is the last one's frame.
        QCOMPARE(o.evacuationS, double(std::max(east.back(), west.back())) / 24.0);
        // The west line sees the homeward walkers cross it backward (westward).
        const std::vector<LineFlow> lines = countLineCrossings(w.scene, w.cache);
        QCOMPARE(lines.size(), std::size_t(2));
        QCOMPARE(lines[1].name, std::string("west"));
        QCOMPARE(lines[1].forward, std::uint64_t(0));
        QCOMPARE(stepsOver(w, -0.5, 0.0, false).size(), std::size_t(20));
        QCOMPARE(lines[1].backward, std::uint64_t(20));

        // One walker that never leaves: no time to evacuate.
        std::string stays = yaml;
        stays += "agents:\n  - {id: 900, type: walker, position: [10, 0, 8]}\n";
        const Occupancy held = measureOccupancy(parseAnalysed(stays), watch(stays, 50.0).cache);
        QCOMPARE(held.evacuationS, -1.0);
        QCOMPARE(held.inScene.back(), 1u);
    }

    void farCoordinatesGiveTheSameFigures()
    {
        const Watched near = watch(corridor(), 50.0);
        const Watched far = watch(corridor(250'000.0), 50.0);
        const RunAnalysis a = analyseRun(near.scene, near.cache), b = analyseRun(far.scene, far.cache);
        QCOMPARE(b.lines[0].forward, a.lines[0].forward);
        QCOMPARE(b.lineFlowPerSecond, a.lineFlowPerSecond);
        // The runs themselves differ in the last bits (the far one steps about its own origin),
        // so a walker on a cell's edge may fall in the next cell; the totals agree.
        QVERIFY(std::abs(b.density.totalPersons() - a.density.totalPersons()) < 1e-9);
        double moved = 0.0;
        for (std::size_t c = 0; c < a.density.persons.size(); ++c)
            moved += std::abs(b.density.persons[c] - a.density.persons[c]);
        QVERIFY2(moved < 0.02 * a.density.totalPersons(), qPrintable(QString::number(moved)));
        QCOMPARE(b.occupancy.evacuationS, a.occupancy.evacuationS);
        const std::size_t nearSamples = a.speedDensity[0].samples.size(), farSamples = b.speedDensity[0].samples.size();
        QVERIFY(nearSamples > 100);
        QVERIFY2(std::max(nearSamples, farSamples) - std::min(nearSamples, farSamples) <= 2,
                 qPrintable(QString("%1 against %2 samples").arg(farSamples).arg(nearSamples)));
        QCOMPARE(b.boundsMin.x - a.boundsMin.x, 250'000.0);
        QCOMPARE(b.trajectories.size(), a.trajectories.size());
        QVERIFY(std::abs(b.trajectories[0].points[0].x - a.trajectories[0].points[0].x - 250'000.0) < 1e-3);
    }

    void trajectoriesFollowEachWalkerFromStartToExit()
    {
        const Watched w = watch(corridor(), 50.0);
        AnalysisOptions options;
        options.maxTrajectories = 10;
        options.maxTrajectoryPoints = 50;
        const RunAnalysis a = analyseRun(w.scene, w.cache, options);
        QCOMPARE(a.walkers, std::size_t(40));
        QCOMPARE(a.trajectories.size(), std::size_t(10));
        for (const Trajectory& t : a.trajectories) {
            QVERIFY(t.points.size() >= 10 && t.points.size() <= 52);
            QVERIFY(glm::length(t.points.front() - w.at[0][t.agent]) < 1e-3);
            std::size_t last = 0;
            while (last + 1 < w.inShot.size() && w.inShot[last + 1][t.agent])
                ++last;
            QVERIFY(glm::length(t.points.back() - w.at[last][t.agent]) < 1e-3);
            QVERIFY(t.points.back().x > 35.0);  // it walked to the exit
        }
    }

    // The stages report their progress in order up to 1; told to stop (here as the lines
    // come next), the analysis returns at once, incomplete, without the lines' and exits'
    // figures; never told, it gives what analyseRun gives without a control.
    void anAnalysisReportsProgressAndStopsWhenTold()
    {
        const Watched w = watch(corridor(), 50.0);
        std::vector<double> progress;
        std::vector<std::string> stages;
        std::atomic<bool> stop{false};
        AnalysisControl control;
        control.progress = [&](double done, const std::string& next) {
            progress.push_back(done);
            stages.push_back(next);
        };
        control.stop = &stop;
        const RunAnalysis whole = analyseRun(w.scene, w.cache, {}, control);
        QVERIFY(whole.complete);
        QCOMPARE(stages, (std::vector<std::string>{"trajectories", "density", "areas", "lines", "exits", ""}));
        QVERIFY(std::is_sorted(progress.begin(), progress.end()) && progress.front() == 0.0 && progress.back() == 1.0);
        const RunAnalysis plain = analyseRun(w.scene, w.cache);
        QCOMPARE(whole.lines[0].forward, plain.lines[0].forward);
        QCOMPARE(whole.occupancy.evacuationS, plain.occupancy.evacuationS);
        QCOMPARE(whole.density.totalPersons(), plain.density.totalPersons());

        control.progress = [&](double, const std::string& next) { stop = stop || next == "lines"; };
        const RunAnalysis stopped = analyseRun(w.scene, w.cache, {}, control);
        QVERIFY(!stopped.complete);
        QVERIFY(stopped.lines.empty() && stopped.occupancy.inScene.empty());
        QCOMPARE(stopped.density.totalPersons(), plain.density.totalPersons());
        QCOMPARE(stopped.trajectories.size(), plain.trajectories.size());
        // Each measure stops within its frames too: a flag set beforehand leaves nothing counted.
        QVERIFY(countLineCrossings(w.scene, w.cache, &stop)[0].crossings.empty());
        QVERIFY(measureOccupancy(w.scene, w.cache, &stop).inScene.empty());
        QVERIFY(measureSpeedDensity(w.scene, w.cache, 1, &stop)[0].samples.empty());
    }

    void theFileKeepsMeasurementsAndRefusesBadOnes()
    {
        const Scene scene = parseAnalysed(corridor());
        QCOMPARE(scene.measurements.size(), std::size_t(2));
        QCOMPARE(scene.measurements[0].shape, MeasurementShape::Line);
        QCOMPARE(scene.measurements[1].shape, MeasurementShape::Area);
        QCOMPARE(scene.measurements[1].points.size(), std::size_t(4));
        const std::string text = sceneToYaml(scene);
        QVERIFY(text.find("measurements:") != std::string::npos);
        QVERIFY(parseAnalysed(text) == scene);

        const std::string base = "throng: 1\nmeasurements:\n";
        const std::pair<const char*, const char*> bad[] = {
            {"  - {name: a, line: [[0, 0], [1, 0], [2, 0]]}\n", "two points"},
            {"  - {name: a, line: [[0, 0], [0, 0]]}\n", "same point"},
            {"  - {name: a, area: [[0, 0], [1, 1], [1, 0], [0, 1]]}\n", "crosses itself"},
            {"  - {name: a, area: [[0, 0], [1, 1], [2, 2]]}\n", "crosses itself"},
            {"  - {name: a, area: [[0, 0], [1, 1]]}\n", "at least 3"},
            {"  - {name: a}\n", "give a 'line"},
            {"  - {name: a, line: [[0, 0], [1, 0]], area: [[0, 0], [1, 0], [0, 1]]}\n", "give a 'line"},
            {"  - {name: a, line: [[0, 0], [1, 0]]}\n  - {name: a, line: [[0, 1], [1, 1]]}\n", "a"},
        };
        for (const auto& [item, words] : bad) {
            const LoadResult r = parseScene(base + item, "bad.yaml", "");
            QVERIFY2(!r.ok(), item);
            const std::string message = r.diagnostics[0].format();
            QVERIFY2(message.find(words) != std::string::npos, message.c_str());
            QVERIFY2(message.find("bad.yaml:3") != std::string::npos || message.find("bad.yaml:4") != std::string::npos,
                     message.c_str());
        }
        const LoadResult unknown = parseScene(base + "  - {name: a, line: [[0, 0], [1, 0]], width: 2}\n", "w.yaml", "");
        QVERIFY(!unknown.diagnostics.empty());
        QVERIFY(unknown.diagnostics[0].format().find("width") != std::string::npos);
    }
};

THRONG_REGISTER_TEST(TestRunAnalysis)
#include "TestRunAnalysis.moc"
