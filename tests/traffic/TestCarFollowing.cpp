// The car-following models as a traffic engineer would check them: a follower keeps a
// safe gap behind a hard-braking leader, never collides behind random leaders over long
// runs, stops before a standing obstacle, and no input ever gives NaN or a reversing car.
#include "TestRegistry.h"

#include "simcore/traffic/CarFollowing.h"

#include <QTest>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace throng::sim;

namespace {
struct PairRun {
    float minGap = 1e9f;
    float maxDecel = 0.0f;
    bool finite = true;
    bool reversed = false;
};

// A follower behind a leader whose acceleration the caller scripts; ballistic update.
template <class LeaderAccel>
PairRun followLeader(const FollowingParams& p, float gap0, float v0, float vl0, double seconds, float dt,
                    LeaderAccel leaderAccel)
{
    PairRun run;
    float xl = gap0, vl = vl0, x = 0.0f, v = v0;
    const int steps = int(seconds / dt);
    for (int k = 0; k < steps; ++k) {
        const float a = followingAcceleration(p, v, xl - x, vl);
        run.maxDecel = std::max(run.maxDecel, -a);
        const SpeedStep me = advanceSpeed(v, a, dt);
        const SpeedStep lead = advanceSpeed(vl, leaderAccel(k * dt, vl), dt);
        x += me.distanceM;
        v = me.speed;
        xl += lead.distanceM;
        vl = lead.speed;
        run.finite = run.finite && std::isfinite(x) && std::isfinite(v);
        run.reversed = run.reversed || v < 0.0f || me.distanceM < 0.0f;
        run.minGap = std::min(run.minGap, xl - x);
    }
    return run;
}

FollowingParams modelParams(FollowingModel m)
{
    FollowingParams p;
    p.model = m;
    return p;
}
}  // namespace

class TestCarFollowing : public QObject {
    Q_OBJECT
private slots:
    void idmKeepsSafeGapBehindEmergencyBraking()
    {
        // Leader and follower at 50 km/h, 25 m apart (about the IDM's equilibrium gap);
        // at t = 5 s the leader brakes at 6 m/s^2, three times the comfortable rate, to a stop.
        const FollowingParams p = modelParams(FollowingModel::Idm);
        const PairRun run = followLeader(p, 25.0f, 13.9f, 13.9f, 40.0, 1.0f / 24.0f,
                                         [](float t, float) { return t < 5.0f ? 0.0f : -6.0f; });
        qInfo("IDM behind a 6 m/s^2 stop: min gap %.2f m, hardest braking %.2f m/s^2", run.minGap, run.maxDecel);
        QVERIFY(run.finite && !run.reversed);
        QVERIFY2(run.minGap > 0.5f * p.minGapM, "the follower must stay well clear of the leader");
        QVERIFY(run.maxDecel <= p.maxDecel + 1e-4f);
    }

    void idmNeverCollidesBehindRandomLeaders()
    {
        // 200 leaders, each 10 minutes of random piecewise-constant acceleration in
        // [-5, 2] m/s^2 held 1 to 5 s, speed in [0, 20] m/s (faster than the follower's v0).
        const FollowingParams p = modelParams(FollowingModel::Idm);
        std::mt19937 gen(11);
        float worst = 1e9f;
        for (int trial = 0; trial < 200; ++trial) {
            std::uniform_real_distribution<float> acc(-5.0f, 2.0f), hold(1.0f, 5.0f), gap(5.0f, 60.0f), sp(0.0f, 14.0f);
            float current = acc(gen), until = hold(gen);
            const float v0 = sp(gen);
            const PairRun run = followLeader(p, gap(gen), v0, v0, 600.0, 1.0f / 24.0f, [&](float t, float vl) {
                if (t >= until) {
                    current = acc(gen);
                    until = t + hold(gen);
                }
                return vl >= 20.0f ? std::min(current, 0.0f) : current;
            });
            QVERIFY(run.finite && !run.reversed);
            worst = std::min(worst, run.minGap);
        }
        qInfo("IDM, 200 random leaders x 10 min: smallest bumper gap %.2f m", worst);
        QVERIFY2(worst > 0.5f, "IDM must never close to a collision");
    }

    void everyModelStopsBeforeAStandingObstacle()
    {
        for (FollowingModel m : {FollowingModel::Idm, FollowingModel::GapTime, FollowingModel::Fuzzy}) {
            const FollowingParams p = modelParams(m);
            // A stop line 80 m ahead (a standing leader at 80 m + minGap), arriving at 50 km/h.
            const PairRun run = followLeader(p, 80.0f + p.minGapM, 13.9f, 0.0f, 60.0, 1.0f / 24.0f,
                                             [](float, float) { return -1.0f; });
            qInfo("%s: stops %.2f m short of its waiting point (negative: past it; hardest braking %.2f m/s^2)", toString(m), run.minGap - p.minGapM,
                  run.maxDecel);
            QVERIFY(run.finite && !run.reversed);
            QVERIFY2(run.minGap > p.minGapM - 0.5f, toString(m));   // at most 0.5 m past the waiting point
            QVERIFY2(run.minGap < p.minGapM + 3.0f, toString(m));   // and it does drive up to it
        }
    }

    void everyModelFollowsWithoutCollisionInAPlatoon()
    {
        // Ten cars behind a leader that stops and starts every 20 s, for an hour.
        for (FollowingModel m : {FollowingModel::Idm, FollowingModel::GapTime, FollowingModel::Fuzzy}) {
            const FollowingParams p = modelParams(m);
            const float dt = 1.0f / 24.0f;
            std::vector<float> x(11), v(11, 10.0f);
            for (int k = 0; k < 11; ++k)
                x[std::size_t(k)] = float(10 - k) * 25.0f;
            float minGap = 1e9f;
            bool ok = true;
            for (int step = 0; step < int(3600.0f / dt); ++step) {
                const float t = float(step) * dt;
                std::vector<float> a(11);
                a[0] = std::fmod(t, 40.0f) < 20.0f ? 1.0f : -3.0f;
                for (std::size_t k = 1; k < 11; ++k)
                    a[k] = followingAcceleration(p, v[k], x[k - 1] - x[k] - 4.4f, v[k - 1]);
                for (std::size_t k = 0; k < 11; ++k) {
                    const SpeedStep s = advanceSpeed(v[k], k == 0 && v[0] >= 13.9f ? std::min(a[0], 0.0f) : a[k], dt);
                    x[k] += s.distanceM;
                    v[k] = s.speed;
                    ok = ok && std::isfinite(x[k]) && v[k] >= 0.0f;
                }
                for (std::size_t k = 1; k < 11; ++k)
                    minGap = std::min(minGap, x[k - 1] - x[k] - 4.4f);
            }
            qInfo("%s platoon, 1 h stop-and-go: smallest bumper gap %.2f m", toString(m), minGap);
            QVERIFY2(ok, toString(m));
            QVERIFY2(minGap > 0.0f, toString(m));
        }
    }

    void noInputGivesNanOrReversing()
    {
        const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
        const std::vector<float> speeds{0.0f, 1e-9f, 5.0f, 13.9f, 40.0f, 1e6f, -3.0f, nan, inf};
        const std::vector<float> gaps{0.0f, -1.0f, 1e-9f, 0.5f, 2.0f, 30.0f, 1e30f, kFreeRoad, nan, -inf};
        const std::vector<float> leaders{0.0f, 5.0f, 30.0f, -2.0f, nan, inf};
        int cases = 0;
        for (FollowingModel m : {FollowingModel::Idm, FollowingModel::GapTime, FollowingModel::Fuzzy}) {
            const FollowingParams p = modelParams(m);
            for (float v : speeds)
                for (float g : gaps)
                    for (float vl : leaders) {
                        const float a = followingAcceleration(p, v, g, vl);
                        QVERIFY2(std::isfinite(a), toString(m));
                        QVERIFY(a >= -p.maxDecel && a <= p.maxAccel);
                        for (float dt : {1.0f / 24.0f, 0.5f}) {
                            const SpeedStep s = advanceSpeed(v, a, dt);
                            QVERIFY(std::isfinite(s.speed) && std::isfinite(s.distanceM));
                            QVERIFY(s.speed >= 0.0f && s.distanceM >= 0.0f);
                        }
                        ++cases;
                    }
            // Touching and standing: brake (or hold), never creep into the leader.
            QVERIFY(followingAcceleration(p, 0.0f, 0.0f, 0.0f) <= 0.0f);
            QCOMPARE(advanceSpeed(0.0f, followingAcceleration(p, 0.0f, 0.0f, 0.0f), 0.1f).distanceM, 0.0f);
        }
        QCOMPARE(cases, 3 * 9 * 10 * 6);
        // A braking car stops within the step instead of reversing: 2 m/s at -8 m/s^2 over 1 s.
        const SpeedStep s = advanceSpeed(2.0f, -8.0f, 1.0f);
        QCOMPARE(s.speed, 0.0f);
        QVERIFY(std::abs(s.distanceM - 0.25f) < 1e-6f);
    }
};

THRONG_REGISTER_TEST(TestCarFollowing)
#include "TestCarFollowing.moc"
