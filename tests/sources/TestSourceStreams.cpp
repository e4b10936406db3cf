// Ten minutes of a street, and of the crossroads, fed by sources (issue 26). Walkers come
// in at both ends of a 60 m street and leave through the door at the far end. After the
// first walkers have had time to cross, the number in the street stays within 15 % of its
// mean for the rest of the ten minutes: second by second with steady arrivals, and over
// each minute with Poisson arrivals (whose count in the street swings by its square root,
// about 14 %, second by second); nobody is left off stage for want of room; and the counts
// agree. The crossroads demo with sources on its sidewalks holds its crowd alike.
#include "TestRegistry.h"

#include "simcore/io/SceneIO.h"
#include "simcore/world/RunStats.h"
#include "simcore/world/World.h"

#include <QTest>

#include <algorithm>
#include <numeric>

using namespace throng;
using namespace throng::sim;

namespace {

constexpr const char* kStreet = R"(throng: 1
settings: {fps: 24, seed: 9, duration: 600, bounds: {min: [-40, -10], max: [40, 10]}}
agent_types:
  - {name: walker, max_speed: 1.3, variation: {speed: [0.85, 1.15]}, behaviours: {seek: 1, separation: 1}}
walls:
  - {name: north_side, points: [[-32, -4], [32, -4]]}
  - {name: south_side, points: [[-32, 4], [32, 4]]}
goals:
  - {name: east_end, position: [31, 0], radius: 2.5, exit: true}
  - {name: west_end, position: [-31, 0], radius: 2.5, exit: true}
sources:
  - {name: from_west, type: walker, line: [[-30, -3], [-30, 3]], rate: 0.6, arrivals: ARRIVALS, goal: east_end}
  - {name: from_east, type: walker, line: [[30, -3], [30, 3]], rate: 0.4, arrivals: ARRIVALS, goal: west_end}
)";

std::string street(const std::string& arrivals)
{
    std::string yaml = kStreet;
    for (std::size_t at; (at = yaml.find("ARRIVALS")) != std::string::npos;)
        yaml.replace(at, 8, arrivals);
    return yaml;
}

// Steps the World for ten minutes; the agents in the scene at 0 s, 1 s, ..., 600 s.
std::vector<std::uint64_t> tenMinutesInScene(World& world)
{
    std::vector<std::uint64_t> inScene;
    RunStats::sampleInScene(world, inScene);
    while (world.timeS() < 600.0 - 1e-9) {
        world.step();
        RunStats::sampleInScene(world, inScene);
    }
    return inScene;
}

// The mean of each whole window of `seconds` samples, from the first on.
std::vector<double> windowMeans(const std::vector<std::uint64_t>& series, std::size_t seconds)
{
    std::vector<double> means;
    for (std::size_t s = 0; s + seconds <= series.size(); s += seconds) {
        const auto from = series.begin() + std::ptrdiff_t(s);
        means.push_back(double(std::accumulate(from, from + std::ptrdiff_t(seconds), std::uint64_t(0))) /
                        double(seconds));
    }
    return means;
}

}  // namespace

class TestSourceStreams : public QObject {
    Q_OBJECT

private slots:
    void aStreetKeepsItsCrowdForTenMinutes_data()
    {
        QTest::addColumn<QString>("arrivals");
        QTest::addColumn<int>("averageS");  // the count is averaged over this many seconds
        QTest::newRow("steady, each second") << "steady" << 1;
        QTest::newRow("poisson, each minute") << "poisson" << 60;
    }

    void aStreetKeepsItsCrowdForTenMinutes()
    {
        QFETCH(QString, arrivals);
        QFETCH(int, averageS);
        const LoadResult r = parseScene(street(arrivals.toStdString()), "street.yaml", "");
        QVERIFY2(r.ok(), r.ok() ? "" : r.diagnostics[0].format().c_str());
        World world(r.scene);
        const std::vector<std::uint64_t> inScene = tenMinutesInScene(world);
        QCOMPARE(inScene.size(), std::size_t(601));
        // Warm-up: 60 m at about 1.3 m/s is 46 s; count from 90 s on.
        const std::vector<std::uint64_t> steady(inScene.begin() + 90, inScene.end());
        const double mean = windowMeans(steady, steady.size()).front();
        const std::vector<double> averages = windowMeans(steady, std::size_t(averageS));
        QVERIFY(averages.size() >= 8);
        const auto [lo, hi] = std::minmax_element(averages.begin(), averages.end());
        // Arrivals at 1 a second that each take about 46 s to cross: about 46 in the street.
        QVERIFY2(mean > 35.0 && mean < 60.0, qPrintable(QString::number(mean)));
        QVERIFY2(double(*lo) >= 0.85 * mean && double(*hi) <= 1.15 * mean,
                 qPrintable(QString("from 90 s: %1 to %2 walkers over %3 s, mean %4").arg(*lo).arg(*hi).arg(averageS)
                                .arg(mean)));
        const RunStats stats = RunStats::from(world, 600 * 24 + 1, 0.0);
        QVERIFY2(stats.sourceAgents > 500 && stats.sourceAgents < 700, qPrintable(QString::number(stats.sourceAgents)));
        QVERIFY2(stats.offstage <= 2, qPrintable(QString::number(stats.offstage)));
        // Everyone that came in is in the street or out through its door.
        QCOMPARE(stats.inScene + stats.nav.agentsOut, stats.sourceAgents - stats.offstage);
        QCOMPARE(stats.inScene, inScene.back());
        QCOMPARE(stats.counters.wallPenetrations, std::uint64_t(0));
        qInfo("%llu walkers came in over 600 s; from 90 s on %.1f to %.1f in the street over %d s, mean %.1f",
              (unsigned long long)(stats.sourceAgents - stats.offstage), *lo, *hi, averageS, mean);
    }

    // The crossroads demo fed by sources (resources/scenes/crossroads-streams.yaml): walkers
    // enter at the eight sidewalk paths' starts on the border and leave at their ends. After
    // two minutes' warm-up (the demo's first crowd walks off), the walkers in the scene stay
    // within 15 % of their mean over every ten seconds for the rest of the ten minutes
    // (Poisson arrivals: second by second the count swings by a few more per cent); the
    // sources' walkers arrive at the rate asked, none waits off stage for long, and the
    // crossroads stays safe: nobody through a wall, on red, or under a car.
    void theCrossroadsKeepsItsCrowdForTenMinutes()
    {
        const LoadResult r = loadScene(THRONG_SOURCE_DIR "/resources/scenes/crossroads-streams.yaml");
        QVERIFY2(r.ok(), r.ok() ? "" : r.diagnostics[0].format().c_str());
        QCOMPARE(r.scene.sources.size(), std::size_t(8));
        World world(r.scene);
        const std::vector<std::uint64_t> inScene = tenMinutesInScene(world);
        QCOMPARE(inScene.size(), std::size_t(601));
        const std::vector<std::uint64_t> steady(inScene.begin() + 120, inScene.end() - 1);
        const double mean = windowMeans(steady, steady.size()).front();
        const std::vector<double> tens = windowMeans(steady, 10);
        QCOMPARE(tens.size(), std::size_t(48));
        const auto [lo, hi] = std::minmax_element(tens.begin(), tens.end());
        const auto [lo1, hi1] = std::minmax_element(steady.begin(), steady.end());
        qInfo("crossroads with sources, from 120 s to 600 s: mean %.1f in the scene; ten-second means %.1f to %.1f; "
              "second by second %llu to %llu",
              mean, *lo, *hi, (unsigned long long)*lo1, (unsigned long long)*hi1);
        // The demo starts with 227 in the scene (210 walkers, 16 cars, the courier); the
        // sidewalks' sources at 0.15 a second hold about 175.
        QVERIFY2(mean > 150.0 && mean < 210.0, qPrintable(QString::number(mean)));
        QVERIFY2(*lo >= 0.85 * mean && *hi <= 1.15 * mean,
                 qPrintable(QString("ten-second means %1 to %2 about %3").arg(*lo).arg(*hi).arg(mean)));
        const RunStats stats = RunStats::from(world, 600 * 24 + 1, 0.0);
        // 8 sources at 0.15 a second for 600 s: 720 expected, Poisson spread about 27.
        QVERIFY2(stats.sourceAgents > 640 && stats.sourceAgents < 800, qPrintable(QString::number(stats.sourceAgents)));
        QVERIFY2(stats.offstage <= 4, qPrintable(QString::number(stats.offstage)));
        QVERIFY2(stats.nav.agentsOut > 600, qPrintable(QString::number(stats.nav.agentsOut)));
        QCOMPARE(stats.inScene, inScene.back());
        QCOMPARE(stats.counters.wallPenetrations, std::uint64_t(0));
        QCOMPARE(stats.counters.redLightViolations, std::uint64_t(0));
        QCOMPARE(stats.carPedestrianCollisions, std::uint64_t(0));
    }
};

THRONG_REGISTER_TEST(TestSourceStreams)
#include "TestSourceStreams.moc"
