// Single-agent steering behaviours as a user checks them, driven through the vehicle model at
// 24 fps: seekers reach, fleers get away, arrivals stop without overshoot, pursuers lead,
// wanderers stay smooth and reproducible, path followers stay on the path.
#include "SteeringHarness.h"
#include "TestRegistry.h"

#include "simcore/steering/FlowFollowing.h"
#include "simcore/steering/PathFollowing.h"
#include "simcore/steering/PursuitBehaviours.h"
#include "simcore/steering/TargetBehaviours.h"
#include "simcore/steering/Wander.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <QTest>

#include <cmath>
#include <vector>

using namespace throng::sim;
using namespace throng::test;

namespace {

// Steps until the pursuer's centre is within the two radii of the quarry's, which walks +x at
// 1 m/s; -1 if not within 60 s.
int stepsToCatch(bool usePursuit)
{
    SteeringAgent hunter = walker({0, 0, 0});
    SteeringAgent quarry = walker({0, 0, 8}, {1.0f, 0, 0}, 1);
    for (int step = 0; step < 24 * 60; ++step) {
        if (planarDistance(hunter.position, quarry.position) < hunter.radius + quarry.radius)
            return step;
        const glm::vec3 f = usePursuit ? pursue(hunter, asNeighbour(quarry)) : seek(hunter, quarry.position);
        hunter = advance(hunter, f);
        quarry = advance(quarry, glm::vec3(0.0f));
    }
    return -1;
}

// A fast, clumsy pursuer (2.5 m/s, 2 N: turning radius 3 m) chases a walker who either evades it
// or flees from where it stands. Returns the walker's mean distance from it over 30 s.
float meanEscapeDistance(bool useEvasion, glm::vec3 start, float& minDistance)
{
    SteeringAgent bull = walker({-6, 0, 0}, {2.5f, 0, 0}, 7);
    bull.maxSpeed = 2.5f;
    bull.maxForce = 2.0f;
    SteeringAgent walkerAgent = walker(start, {}, 8);
    double sum = 0.0;
    minDistance = 1e9f;
    const int steps = 24 * 30;
    for (int step = 0; step < steps; ++step) {
        const float d = planarDistance(bull.position, walkerAgent.position);
        sum += d;
        minDistance = std::min(minDistance, d);
        const glm::vec3 fw = useEvasion ? evade(walkerAgent, asNeighbour(bull)) : flee(walkerAgent, bull.position);
        const glm::vec3 fb = pursue(bull, asNeighbour(walkerAgent));
        walkerAgent = advance(walkerAgent, fw);
        bull = advance(bull, fb);
    }
    return float(sum / steps);
}

struct WanderRun {
    std::vector<glm::vec3> positions;
    float maxSpeed = 0.0f;
    float maxTurnPerStepRad = 0.0f;
    float headingSpreadRad = 0.0f;  // largest angle between the first heading and a later one
};

WanderRun runWander(std::uint64_t seed, int steps)
{
    WanderRun run;
    SteeringAgent a = walker({0, 0, 0}, {0, 0, 1.4f}, 3);
    const glm::vec3 firstHeading = a.forward;
    WanderState state;
    for (int step = 0; step < steps; ++step) {
        const WanderResult w = wander(a, state, signedRandom3(seed, a.id, std::uint64_t(step)));
        state = w.state;
        const glm::vec3 before = a.forward;
        a = advance(a, w.force);
        run.positions.push_back(a.position);
        run.maxSpeed = std::max(run.maxSpeed, a.speed());
        run.maxTurnPerStepRad = std::max(run.maxTurnPerStepRad, angleBetween(before, a.forward));
        run.headingSpreadRad = std::max(run.headingSpreadRad, angleBetween(firstHeading, a.forward));
    }
    return run;
}

}  // namespace

class TestSteeringBehaviours : public QObject {
    Q_OBJECT
private slots:
    void seekReachesTarget_data()
    {
        QTest::addColumn<glm::vec3>("start");
        QTest::addColumn<glm::vec3>("velocity");
        QTest::newRow("from rest") << glm::vec3(0, 0, 0) << glm::vec3(0.0f);
        QTest::newRow("moving away") << glm::vec3(2, 0, -3) << glm::vec3(-1.4f, 0, 0);
    }

    void seekReachesTarget()
    {
        QFETCH(glm::vec3, start);
        QFETCH(glm::vec3, velocity);
        const glm::vec3 target(8, 0, 5);
        SteeringAgent a = walker(start, velocity);
        int reachedAt = -1;
        for (int step = 0; step < 24 * 30 && reachedAt < 0; ++step) {
            a = advance(a, seek(a, target));
            if (planarDistance(a.position, target) < 0.5f)
                reachedAt = step;
        }
        QVERIFY2(reachedAt >= 0, "the seeker never came within 0.5 m of its target");
        // Straight-line time at top speed plus 3 s to accelerate and turn.
        const float budgetS = glm::distance(start, target) / a.maxSpeed + 3.0f;
        QVERIFY(reachedAt * kDt < budgetS);
    }

    // The force toward a desired velocity (behave::towards, which every path calls): none at
    // all, +0 in every component, for an agent already at that velocity, even where the
    // difference of the two is a zero of negative sign; none for one so fast that the force
    // would overflow; else the difference over the response time, at most the agent's force.
    void steeringForceTowardsADesiredVelocity()
    {
        // Straight at a target across x = -0: seek asks for (-0, 0, 1.4) m/s, which it has.
        const SteeringAgent there = walker({0, 0, 0}, {0.0f, 0.0f, 1.4f});
        const glm::vec3 none = seek(there, {-0.0f, 0.0f, 10.0f});
        QCOMPARE(none, glm::vec3(0.0f));
        QVERIFY(!std::signbit(none.x) && !std::signbit(none.y) && !std::signbit(none.z));

        const SteeringAgent wild = walker({0, 0, 0}, {3e37f, 0.0f, 0.0f});
        const glm::vec3 overflow = seek(wild, {0.0f, 0.0f, 10.0f});
        QCOMPARE(overflow, glm::vec3(0.0f));
        QVERIFY(!std::signbit(overflow.x));  // nothing asked, not a force scaled down to a zero

        // 0.5 m/s short of the desired velocity, with a response time of 0.5 s and a mass of
        // 1 kg: 1 N, within the 3 N it may use; 4 m/s off: truncated to 3 N, the same way.
        const SeekParams params{0.5f};
        const SteeringAgent slow = walker({0, 0, 0}, {0.0f, 0.0f, 0.9f});
        const glm::vec3 gentle = seek(slow, {0.0f, 0.0f, 10.0f}, params);
        QCOMPARE(gentle.z, 1.0f);
        QCOMPARE(gentle.x, 0.0f);
        const SteeringAgent backwards = walker({0, 0, 0}, {0.0f, 0.0f, -2.6f});
        const glm::vec3 hard = seek(backwards, {0.0f, 0.0f, 10.0f}, params);
        QCOMPARE(hard.z, 3.0f);
    }

    void fleeIncreasesDistanceMonotonically()
    {
        const glm::vec3 threat(0, 0, 0);
        SteeringAgent a = walker({1.0f, 0, 0.5f});
        float last = planarDistance(a.position, threat);
        for (int step = 0; step < 24 * 20; ++step) {
            a = advance(a, flee(a, threat));
            const float d = planarDistance(a.position, threat);
            QVERIFY2(d > last, qPrintable(QString("distance fell from %1 to %2 at step %3").arg(last).arg(d).arg(step)));
            last = d;
        }
        QVERIFY(last > 20.0f);
    }

    void fleeIgnoresThreatsBeyondPanicDistance()
    {
        const SteeringAgent a = walker({6, 0, 0}, {0.5f, 0, 0});
        FleeParams params;
        params.panicDistanceM = 5.0f;
        QCOMPARE(flee(a, glm::vec3(0.0f), params), glm::vec3(0.0f));
        params.panicDistanceM = 7.0f;
        QVERIFY(glm::dot(flee(a, glm::vec3(0.0f), params), glm::vec3(1, 0, 0)) > 0.0f);
    }

    void arrivalStopsWithoutOvershoot_data()
    {
        QTest::addColumn<glm::vec3>("start");
        QTest::addColumn<glm::vec3>("velocity");
        QTest::newRow("from rest, far") << glm::vec3(-6, 0, -3) << glm::vec3(0.0f);
        QTest::newRow("at top speed toward it") << glm::vec3(-8, 0, 0) << glm::vec3(1.4f, 0, 0);
        QTest::newRow("from rest, inside the slowing distance") << glm::vec3(-0.5f, 0, 0.2f) << glm::vec3(0.0f);
    }

    void arrivalStopsWithoutOvershoot()
    {
        QFETCH(glm::vec3, start);
        QFETCH(glm::vec3, velocity);
        const glm::vec3 target(0, 0, 0);
        const glm::vec3 approach = glm::normalize(target - start);
        SteeringAgent a = walker(start, velocity);
        for (int step = 0; step < 24 * 20; ++step) {
            a = advance(a, arrive(a, target));
            const float along = glm::dot(target - a.position, approach);
            QVERIFY2(along >= 0.0f, qPrintable(QString("overshot by %1 m at step %2").arg(-along).arg(step)));
        }
        QVERIFY2(planarDistance(a.position, target) < 0.05f, "did not stop within 5 cm");
        QVERIFY2(a.speed() < 0.01f, "still moving after 20 s");
        // Stopped inside the tolerance, it has nothing more to say... once it stands still.
        SteeringAgent still = a;
        still.velocity = glm::vec3(0.0f);
        if (planarDistance(a.position, target) <= ArrivalParams{}.toleranceM)
            QCOMPARE(arrive(still, target), glm::vec3(0.0f));
    }

    void pursuitCatchesSoonerThanSeek()
    {
        const int pursuit = stepsToCatch(true);
        const int seekSteps = stepsToCatch(false);
        QVERIFY2(pursuit > 0, "pursuit never caught the quarry");
        QVERIFY2(seekSteps > 0, "seek never caught the quarry");
        QVERIFY2(pursuit < seekSteps, qPrintable(QString("pursuit %1 steps, seek %2").arg(pursuit).arg(seekSteps)));
    }

    void evasionKeepsFartherThanFlee_data()
    {
        QTest::addColumn<glm::vec3>("start");
        QTest::newRow("beside its path") << glm::vec3(0, 0, 1);
        QTest::newRow("ahead and aside") << glm::vec3(3, 0, -2);
        QTest::newRow("behind it") << glm::vec3(-9, 0, 1);
        QTest::newRow("far ahead") << glm::vec3(6, 0, 4);
    }

    void evasionKeepsFartherThanFlee()
    {
        QFETCH(glm::vec3, start);
        float minEvade = 0.0f, minFlee = 0.0f;
        const float evadeMean = meanEscapeDistance(true, start, minEvade);
        const float fleeMean = meanEscapeDistance(false, start, minFlee);
        // Evading steps out of the clumsy pursuer's predicted path; fleeing runs ahead of it. (Dead
        // ahead on its line the two are the same behaviour, so that start is not a row.)
        QVERIFY2(evadeMean > 1.1f * fleeMean, qPrintable(QString("mean distance: evade %1 m, flee %2 m").arg(evadeMean).arg(fleeMean)));
        QVERIFY2(minEvade > minFlee, qPrintable(QString("closest: evade %1 m, flee %2 m").arg(minEvade).arg(minFlee)));
    }

    void offsetPursuitHoldsTheOffset()
    {
        // The leader walks +x at 1 m/s; the follower keeps 1 m to its right and 1.5 m behind.
        SteeringAgent leader = walker({0, 0, 0}, {1.0f, 0, 0}, 1);
        SteeringAgent follower = walker({-3, 0, 4}, {}, 2);
        OffsetPursuitParams params;
        params.offsetM = {1.0f, 0.0f, -1.5f};
        float worst = 0.0f;
        for (int step = 0; step < 24 * 20; ++step) {
            follower = advance(follower, pursueOffset(follower, asNeighbour(leader), params));
            leader = advance(leader, glm::vec3(0.0f));
            if (step >= 24 * 10)
                worst = std::max(worst, glm::distance(follower.position, pointInFrameOf(asNeighbour(leader), params.offsetM)));
        }
        QVERIFY2(worst < 0.05f, qPrintable(QString("offset error %1 m after settling").arg(worst)));
        // The frame convention, checked independently of pointInFrameOf: heading +x with y up, the
        // leader's right is +z, so "1 m right, 1.5 m behind" is (x - 1.5, z + 1).
        QVERIFY(std::abs(follower.position.z - (leader.position.z + 1.0f)) < 0.05f);
        QVERIFY(std::abs(follower.position.x - (leader.position.x - 1.5f)) < 0.05f);
    }

    void wanderIsBoundedSmoothAndReproducible()
    {
        const WanderRun run = runWander(42, 24 * 60);
        QVERIFY(run.maxSpeed <= 1.4f + 1e-5f);
        // The desired direction stays within asin(radius / distance) = asin(0.5 / 2) = 14.5 deg of the
        // velocity, so |desired - v| <= 2 * 1.4 * sin(7.25 deg) = 0.35 m/s; over the 0.5 s response
        // time that is 0.71 m/s^2 sideways, a turn of 0.71 / 1.4 * (1/24) = 0.021 rad = 1.2 deg per
        // step at top speed. 1.5 deg allows for the speed dipping a little in turns; the vehicle
        // itself could turn 3 N / 1 kg / 1.4 m/s / 24 = 5.1 deg per step, so this is wander's own
        // smoothness, not the vehicle's limit.
        const float limitRad = glm::radians(1.5f);
        QVERIFY2(run.maxTurnPerStepRad < limitRad,
                 qPrintable(QString("turned %1 deg in one step").arg(glm::degrees(run.maxTurnPerStepRad))));
        QVERIFY2(run.headingSpreadRad > glm::radians(90.0f), "wander hardly wandered");

        const WanderRun again = runWander(42, 24 * 60);
        QVERIFY(run.positions == again.positions);
        const WanderRun other = runWander(43, 24 * 60);
        QVERIFY(run.positions != other.positions);
    }

    void pathFollowerStaysOnPath_data()
    {
        QTest::addColumn<bool>("closed");
        QTest::addColumn<bool>("reverse");
        QTest::newRow("zig-zag") << false << false;
        QTest::newRow("zig-zag, reversed") << false << true;
        QTest::newRow("closed zig-zag loop") << true << false;
        QTest::newRow("closed zig-zag loop, reversed") << true << true;
    }

    void pathFollowerStaysOnPath()
    {
        QFETCH(bool, closed);
        QFETCH(bool, reverse);
        // Zig-zag: legs of 7.2 m turning by 67 degrees at every corner.
        const std::vector<glm::vec3> points{{0, 0, 0}, {6, 0, 4}, {12, 0, 0}, {18, 0, 4}, {24, 0, 0}, {30, 0, 4},
                                            {30, 0, 12}, {0, 0, 12}};
        SteeringPath path;
        path.points = closed ? std::span<const glm::vec3>(points) : std::span<const glm::vec3>(points).first(6);
        path.radius = 0.75f;
        path.closed = closed;
        PathFollowParams params;
        params.reverse = reverse;
        const glm::vec3 start = reverse && !closed ? path.points.back() : path.points.front();
        const glm::vec3 end = reverse ? path.points.front() : path.points.back();
        SteeringAgent a = walker(start);
        const int steps = 24 * 90;  // the loop is 86 m long: one lap takes 62 s at 1.4 m/s
        int inside = 0;
        float travelled = 0.0f;
        for (int step = 0; step < steps; ++step) {
            const glm::vec3 before = a.position;
            a = advance(a, followPath(a, path, params));
            travelled += glm::distance(before, a.position);
            inside += glm::distance(a.position, projectOntoPath(path, a.position).point) <= path.radius;
        }
        QVERIFY2(inside >= steps * 99 / 100, qPrintable(QString("inside on %1 of %2 steps").arg(inside).arg(steps)));
        if (closed) {
            QVERIFY2(travelled > pathLength(path), "did not complete a lap in 90 s");
        } else {
            QVERIFY2(glm::distance(a.position, end) < 0.1f, "did not stop at the end of the open path");
            QVERIFY(a.speed() < 0.05f);
        }
    }

    void pathFollowerMovesInItsDirection()
    {
        const std::vector<glm::vec3> points{{0, 0, 0}, {10, 0, 0}};
        const SteeringPath path{points, 1.0f, false};
        SteeringAgent a = walker({5, 0, 0});
        PathFollowParams params;
        for (int step = 0; step < 48; ++step)
            a = advance(a, followPath(a, path, params));
        QVERIFY(a.velocity.x > 0.5f);
        params.reverse = true;
        SteeringAgent b = walker({5, 0, 0});
        for (int step = 0; step < 48; ++step)
            b = advance(b, followPath(b, path, params));
        QVERIFY(b.velocity.x < -0.5f);
        // On the path and moving its way, the follower has nothing to say.
        const SteeringAgent cruising = walker({5, 0, 0.2f}, {1.4f, 0, 0});
        QCOMPARE(followPath(cruising, path, PathFollowParams{}), glm::vec3(0.0f));
    }

    void flowFollowerTravelsAlongTheField()
    {
        // A vortex around the origin: the agent should end up circling with the flow.
        auto field = [](glm::vec3 p) { return glm::vec3(-p.z, 0.0f, p.x); };
        SteeringAgent a = walker({5, 0, 0});
        for (int step = 0; step < 24 * 20; ++step)
            a = advance(a, followFlow(a, field(flowSamplePoint(a))));
        QVERIFY2(angleBetween(a.velocity, field(a.position)) < glm::radians(15.0f), "not travelling with the flow");
        QVERIFY(a.speed() > 1.0f);
        QCOMPARE(followFlow(a, glm::vec3(0.0f)), glm::vec3(0.0f));
    }
};

THRONG_REGISTER_TEST(TestSteeringBehaviours)
#include "TestSteeringBehaviours.moc"
