// A four-lane signalised crossroads with random arrivals and a stream of walkers on all
// four crosswalks, run for a long time: nobody runs a red light, no car touches a walker
// or another car, both cars and walkers flow every green, and the run is the same for
// one and two threads.
#include "TestRegistry.h"

#include "TrafficHarness.h"

#include <QTest>

using namespace throng::sim;
using throng::test::CrossingRun;
using throng::test::CrossingSetup;

class TestTrafficCrossing : public QObject {
    Q_OBJECT
private slots:
    void longRunHasNoViolationsOrCollisions()
    {
        CrossingSetup setup;  // 6 cars per lane, 10 walkers per crosswalk, open lanes
        const double minutes = 30.0;
        const CrossingRun run = throng::test::runCrossing(setup, minutes * 60.0, 0);
        const TrafficCounters& c = run.counters;
        qInfo("%.0f min: %llu vehicle-steps, red-light violations %llu (vehicles) %llu (walkers), car-walker contacts "
              "%llu, car-car contacts %llu, walker crossings %llu, fewest re-entries of a car %u",
              minutes, (unsigned long long)c.vehicleSteps, (unsigned long long)c.vehicleRedLightViolations,
              (unsigned long long)c.pedestrianRedLightViolations, (unsigned long long)c.carPedestrianCollisions,
              (unsigned long long)c.vehicleCollisions, (unsigned long long)run.walkerCrossings, run.minRespawns);
        QCOMPARE(c.vehicleRedLightViolations, std::uint64_t(0));
        QCOMPARE(c.pedestrianRedLightViolations, std::uint64_t(0));
        QCOMPARE(c.carPedestrianCollisions, std::uint64_t(0));
        QCOMPARE(c.vehicleCollisions, std::uint64_t(0));
        QCOMPARE(c.nonFiniteValues, std::uint64_t(0));
        // Both flow: every stop line passes cars (or walkers) in its green phases.
        for (const StopLineThroughput& t : run.throughput) {
            qInfo("stop line of light %d, %s %d: %llu crossings in %llu greens, %.1f per green", t.light,
                  t.lane >= 0 ? "lane" : "crosswalk", t.lane >= 0 ? t.lane : t.crosswalk,
                  (unsigned long long)t.crossings, (unsigned long long)t.greenPhases, t.perGreen());
            QVERIFY(t.greenPhases >= 35);  // 30 min of 50 s cycles
            QVERIFY2(t.perGreen() >= 3.0, "traffic flows through every green");
        }
        QVERIFY2(run.minRespawns >= 5, "every car keeps driving through the crossing, none is stuck");
        QVERIFY(run.walkerCrossings > 500);
    }

    void loopingLanesAlsoFlowSafely()
    {
        CrossingSetup setup;
        setup.loopLanes = true;
        setup.carsPerLane = 8;
        setup.seed = 21;
        const CrossingRun run = throng::test::runCrossing(setup, 20.0 * 60.0, 0);
        QCOMPARE(run.counters.redLightViolations(), std::uint64_t(0));
        QCOMPARE(run.counters.carPedestrianCollisions, std::uint64_t(0));
        QCOMPARE(run.counters.vehicleCollisions, std::uint64_t(0));
        for (const StopLineThroughput& t : run.throughput)
            QVERIFY(t.perGreen() >= 3.0);
    }

    void everyCarFollowingModelRunsTheCrossingSafely_data()
    {
        QTest::addColumn<int>("model");
        QTest::newRow("idm") << int(FollowingModel::Idm);
        QTest::newRow("gap_time") << int(FollowingModel::GapTime);
        QTest::newRow("fuzzy") << int(FollowingModel::Fuzzy);
    }
    void everyCarFollowingModelRunsTheCrossingSafely()
    {
        QFETCH(int, model);
        CrossingSetup setup;
        setup.model = FollowingModel(model);
        setup.carsPerLane = 10;
        const CrossingRun run = throng::test::runCrossing(setup, 15.0 * 60.0, 0);
        double perGreen = 0.0;
        for (const StopLineThroughput& t : run.throughput)
            if (t.lane >= 0)
                perGreen += t.perGreen() / 4.0;
        qInfo("%s: %.1f cars per green per lane, violations %llu, car-walker contacts %llu, car-car contacts %llu",
              toString(setup.model), perGreen, (unsigned long long)run.counters.redLightViolations(),
              (unsigned long long)run.counters.carPedestrianCollisions, (unsigned long long)run.counters.vehicleCollisions);
        QCOMPARE(run.counters.redLightViolations(), std::uint64_t(0));
        QCOMPARE(run.counters.carPedestrianCollisions, std::uint64_t(0));
        QCOMPARE(run.counters.vehicleCollisions, std::uint64_t(0));
        QVERIFY(perGreen >= 3.0);
    }

    void sameResultForOneAndTwoThreads()
    {
        // 320 vehicles, enough for the step to run on both threads.
        CrossingSetup setup;
        setup.carsPerLane = 80;
        setup.laneLengthM = 1200.0f;
        const CrossingRun one = throng::test::runCrossing(setup, 60.0, 1);
        const CrossingRun two = throng::test::runCrossing(setup, 60.0, 2);
        const CrossingRun again = throng::test::runCrossing(setup, 60.0, 2);
        QCOMPARE(one.stateHash, two.stateHash);
        QCOMPARE(two.stateHash, again.stateHash);
        QCOMPARE(one.counters.vehicleSteps, two.counters.vehicleSteps);
        QCOMPARE(one.walkerCrossings, two.walkerCrossings);
        setup.seed = 8;
        QCOMPARE(one.counters.redLightViolations(), std::uint64_t(0));
        QCOMPARE(one.counters.vehicleCollisions, std::uint64_t(0));
        QVERIFY2(throng::test::runCrossing(setup, 60.0, 2).stateHash != one.stateHash, "the seed matters");
    }
};

THRONG_REGISTER_TEST(TestTrafficCrossing)
#include "TestTrafficCrossing.moc"
