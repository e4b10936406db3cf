// The plots draw the analysis they are given: the occupancy chart's lines are the agents in
// the scene and out on the frames they plot, the flow chart's steps hold every crossing of
// each line and every agent out of each exit, the speed-density chart plots each area's
// samples beside Weidmann's curve, and the density ground plot paints its densest cell in
// the top colour of its scale (and nothing in it for an empty run).
#include "TestRegistry.h"

#include "report/AnalysisCharts.h"
#include "report/GroundPlot.h"
#include "simcore/analysis/RunAnalysis.h"
#include "simcore/io/SceneIO.h"
#include "simcore/world/World.h"

#include <QtCharts/QLineSeries>
#include <QtCharts/QScatterSeries>

#include <QTest>

using namespace throng;

namespace {

const char* kCorridor = R"(throng: 1
settings: {fps: 30, duration: 45, seed: 5, bounds: {min: [-5, -10], max: [45, 10]}}
agent_types:
  - {name: walker, radius: 0.25, max_speed: 1.3}
goals:
  - {name: out, position: [40, 0], radius: 3, exit: true}
groups:
  - {name: crowd, type: walker, count: 60, rect: {min: [0, -3], max: [10, 3]}, goal: out}
measurements:
  - {name: gate, line: [[20, -6], [20, 6]]}
  - {name: middle, area: [[16, -4], [24, -4], [24, 4], [16, 4]]}
)";

struct Recorded {
    sim::Scene scene;
    sim::FrameCache cache;
};

Recorded record(const char* yaml, double seconds)
{
    Recorded r;
    const sim::LoadResult loaded = sim::parseScene(yaml, "charts.yaml", "");
    if (!loaded.ok())
        qFatal("%s", loaded.diagnostics[0].format().c_str());
    r.scene = loaded.scene;
    sim::World world(r.scene);
    world.startRecording(r.cache);
    std::vector<sim::AgentFrame> frame;
    while (world.timeS() < seconds - 1e-9) {
        world.step();
        world.snapshot(frame);
        r.cache.append(frame);
    }
    return r;
}

template <typename S>
std::vector<S*> seriesOf(QChart& chart)
{
    std::vector<S*> out;
    for (QAbstractSeries* s : chart.series())
        if (auto* typed = qobject_cast<S*>(s))
            out.push_back(typed);
    return out;
}

// The area under a step series of (t0, y), (t1, y) pairs: persons/s x s = persons.
double stepArea(const QLineSeries& s)
{
    double total = 0.0;
    for (int k = 0; k + 1 < s.count(); k += 2)
        total += s.at(k).y() * (s.at(k + 1).x() - s.at(k).x());
    return total;
}

int pixelsOf(const QImage& image, QColor colour)
{
    int n = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            n += image.pixelColor(x, y) == colour ? 1 : 0;
    return n;
}

}  // namespace

class TestAnalysisCharts : public QObject {
    Q_OBJECT

private slots:
    void theOccupancyChartPlotsWhoIsInAndOut()
    {
        const Recorded r = record(kCorridor, 45.0);
        const sim::RunAnalysis a = sim::analyseRun(r.scene, r.cache);
        QVERIFY(a.occupancy.evacuationS > 0.0);
        const auto chart = report::occupancyChart(a);
        const std::vector<QLineSeries*> lines = seriesOf<QLineSeries>(*chart);
        QCOMPARE(lines.size(), std::size_t(3));  // in, out, the time everyone was out
        QCOMPARE(lines[0]->count(), int(a.frames));
        for (int k = 0; k < lines[0]->count(); ++k) {
            const std::size_t f = std::size_t(std::lround(lines[0]->at(k).x() * 30.0));
            QCOMPARE(lines[0]->at(k).y(), double(a.occupancy.inScene[f]));
            QCOMPARE(lines[1]->at(k).y(), double(a.occupancy.out[f]));
        }
        QCOMPARE(lines[2]->at(0).x(), a.occupancy.evacuationS);
        QVERIFY(lines[2]->name().contains(QString::number(a.occupancy.evacuationS, 'f', 1)));
    }

    void theFlowChartHoldsEveryCrossingAndEveryExit()
    {
        const Recorded r = record(kCorridor, 45.0);
        const sim::RunAnalysis a = sim::analyseRun(r.scene, r.cache);
        QCOMPARE(a.lines[0].forward, std::uint64_t(60));
        const auto chart = report::flowChart(a);
        const std::vector<QLineSeries*> lines = seriesOf<QLineSeries>(*chart);
        QCOMPARE(lines.size(), std::size_t(2));
        QCOMPARE(lines[0]->name(), QString("Line gate"));
        QCOMPARE(lines[1]->name(), QString("Exit out"));
        QCOMPARE(stepArea(*lines[0]), 60.0);
        QCOMPARE(stepArea(*lines[1]), double(a.occupancy.exits[0].agentsOut()));
        QCOMPARE(a.occupancy.exits[0].agentsOut(), std::uint64_t(60));
    }

    void theSpeedDensityChartPlotsEverySampleBesideWeidmann()
    {
        const Recorded r = record(kCorridor, 45.0);
        const sim::RunAnalysis a = sim::analyseRun(r.scene, r.cache);
        const auto chart = report::speedDensityChart(a);
        const std::vector<QScatterSeries*> points = seriesOf<QScatterSeries>(*chart);
        QCOMPARE(points.size(), std::size_t(1));
        const sim::AreaSpeedDensity& middle = a.speedDensity[0];
        QVERIFY(middle.samples.size() > 50 && middle.samples.size() < 1500);
        QCOMPARE(points[0]->count(), int(middle.samples.size()));
        for (int k = 0; k < points[0]->count(); ++k) {
            QCOMPARE(points[0]->at(k).x(), middle.samples[std::size_t(k)].densityPerM2);
            QCOMPARE(points[0]->at(k).y(), middle.samples[std::size_t(k)].speedMps);
        }
        std::vector<QLineSeries*> curve;
        for (QLineSeries* s : seriesOf<QLineSeries>(*chart))
            if (!qobject_cast<QScatterSeries*>(s))
                curve.push_back(s);
        QCOMPARE(curve.size(), std::size_t(1));
        for (int k = 0; k < curve[0]->count(); ++k)
            QCOMPARE(curve[0]->at(k).y(), sim::weidmannSpeed(curve[0]->at(k).x()));
    }

    void theHeatmapPaintsTheDensestCellInTheTopColour()
    {
        const Recorded r = record(kCorridor, 45.0);
        const sim::RunAnalysis a = sim::analyseRun(r.scene, r.cache);
        const QColor top = report::densityColour(1.0);
        const QImage heat = report::paintGround(r.scene, a, report::GroundLayer::Density, QSize(900, 600));
        QVERIFY(heat.width() <= 900 && heat.height() <= 600);
        // The densest cell is one metre square, drawn at about 15 px: its fill and the scale's top.
        QVERIFY2(pixelsOf(heat, top) > 100, qPrintable(QString::number(pixelsOf(heat, top))));

        // Nobody walks: no cell in any colour of the scale but its own bar.
        const Recorded empty = record(R"(throng: 1
settings: {fps: 30, duration: 2, bounds: {min: [-5, -10], max: [45, 10]}}
agent_types:
  - {name: walker, radius: 0.25, max_speed: 1.3}
)", 2.0);
        const sim::RunAnalysis none = sim::analyseRun(empty.scene, empty.cache);
        QCOMPARE(none.density.totalPersons(), 0.0);
        const QImage blank = report::paintGround(empty.scene, none, report::GroundLayer::Density, QSize(900, 600));
        QVERIFY(pixelsOf(blank, top) < pixelsOf(heat, top));
        const QImage noPaths =
            report::paintGround(empty.scene, none, report::GroundLayer::Trajectories, QSize(900, 600));
        const QImage paths = report::paintGround(r.scene, a, report::GroundLayer::Trajectories, QSize(900, 600));
        QVERIFY(paths != noPaths);
    }
};

THRONG_REGISTER_TEST(TestAnalysisCharts)
#include "TestAnalysisCharts.moc"
