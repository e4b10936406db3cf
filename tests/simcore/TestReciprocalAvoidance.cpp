// Reciprocal velocity obstacles (ORCA) as a pure function, as RVO2's users check it: a
// symmetric circle swaps without contact, and a boxed-in body stands still. And the force
// a walker steers by from it (reciprocalForce), with its turn right of oncoming walkers.
#include "TestRegistry.h"

#include "simcore/steering/ReciprocalAvoidance.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

using namespace throng::sim;

class TestReciprocalAvoidance : public QObject {
    Q_OBJECT
private slots:
    void reciprocalAvoidanceSwapsACircleWithoutContact()
    {
        // 24 bodies (radius 0.3 m) on a 10 m circle walk to the antipodal point, every one
        // choosing its velocity by ORCA from its preferred one (straight to the goal at
        // 1.4 m/s), as RVO2's circle example does. Nobody may touch anybody, everyone
        // must arrive, and the crossing must not take more than twice the straight walk.
        constexpr int n = 24;
        constexpr float dt = 1.0f / 24.0f, radius = 0.3f, speed = 1.4f;
        ReciprocalAvoidanceParams horizon;
        horizon.timeHorizonS = 2.0f;  // RVO2's example looks further ahead than a walker in a crowd
        std::vector<glm::vec2> pos(n), vel(n, glm::vec2(0.0f)), goal(n);
        for (int i = 0; i < n; ++i) {
            const float a = 6.2831853f * float(i) / float(n);
            pos[i] = 10.0f * glm::vec2(std::cos(a), std::sin(a));
            goal[i] = -pos[i];
        }
        float closest = INFINITY;
        int arrivedAt = -1;
        for (int step = 0; step < 24 * 60 && arrivedAt < 0; ++step) {
            std::vector<glm::vec2> next(n);
            for (int i = 0; i < n; ++i) {
                std::vector<PlanarNeighbour> near;
                for (int j = 0; j < n; ++j)
                    if (j != i && glm::distance(pos[i], pos[j]) < 4.0f)
                        near.push_back({pos[j], vel[j], radius, 0.5f});
                std::sort(near.begin(), near.end(), [&](const PlanarNeighbour& a, const PlanarNeighbour& b) {
                    return glm::distance(a.position, pos[i]) < glm::distance(b.position, pos[i]);
                });
                glm::vec2 want = goal[i] - pos[i];
                const float d = glm::length(want);
                want = d > 1e-4f ? want * (std::min(speed, d / dt) / d) : glm::vec2(0.0f);
                // As in RVO2's circle example: a tiny turn, different per agent and step,
                // so a perfectly symmetric start cannot hold everyone in balance.
                const float jitter = 0.1f * std::sin(float(i * 7919 + step * 104729));
                want = glm::vec2(want.x - jitter * want.y, want.y + jitter * want.x);
                next[i] = avoidReciprocally({pos[i], vel[i], radius, speed}, want, near, dt, horizon);
                QVERIFY(glm::length(next[i]) <= speed * 1.0001f);
            }
            bool all = true;
            for (int i = 0; i < n; ++i) {
                vel[i] = next[i];
                pos[i] += vel[i] * dt;
                all = all && glm::distance(pos[i], goal[i]) < 0.05f;
            }
            for (int i = 0; i < n; ++i)
                for (int j = i + 1; j < n; ++j)
                    closest = std::min(closest, glm::distance(pos[i], pos[j]));
            if (all)
                arrivedAt = step;
        }
        int arrived = 0;
        for (int i = 0; i < n; ++i)
            arrived += glm::distance(pos[i], goal[i]) < 0.05f;
        qInfo("ORCA circle: %d of %d arrived at %.2f s (straight: %.2f s), closest centres %.3f m (contact %.2f m)", arrived, n,
              double(arrivedAt) * double(dt), 20.0 / double(speed), double(closest), double(2 * radius));
        QVERIFY2(arrivedAt >= 0, "not everyone arrived within 60 s");
        // Measured: all arrive at 22.6-23.2 s; everyone meets in the middle at once and
        // turns round it, so twice the straight walk is the bound.
        QVERIFY2(float(arrivedAt) * dt < 2.0f * 20.0f / speed, "the crossing took more than twice the straight walk");
        QVERIFY2(closest >= 2.0f * radius - 0.01f, qPrintable(QString("bodies overlapped: %1 m apart").arg(closest)));
    }

    void reciprocalAvoidanceStandsStillWhenItMustAndNeverExceedsMaxSpeed()
    {
        // Boxed in by four standing bodies that each take no share: the velocity that
        // least violates the constraints is (near) zero, finite, within max speed.
        const PlanarBody self{{0.0f, 0.0f}, {1.0f, 0.0f}, 0.3f, 1.4f};
        const std::vector<PlanarNeighbour> ring{{{0.61f, 0.0f}, {}, 0.3f, 1.0f},
                                                {{-0.61f, 0.0f}, {}, 0.3f, 1.0f},
                                                {{0.0f, 0.61f}, {}, 0.3f, 1.0f},
                                                {{0.0f, -0.61f}, {}, 0.3f, 1.0f}};
        const glm::vec2 v = avoidReciprocally(self, {1.4f, 0.0f}, ring, 1.0f / 24.0f);
        QVERIFY(std::isfinite(v.x) && std::isfinite(v.y));
        QVERIFY2(glm::length(v) < 0.3f, qPrintable(QString("boxed in, yet moves at %1 m/s").arg(glm::length(v))));
        // Nobody near: the preferred velocity, cut to max speed.
        const glm::vec2 free = avoidReciprocally(self, {3.0f, 0.0f}, {}, 1.0f / 24.0f);
        QCOMPARE(free.x, 1.4f);
        QCOMPARE(free.y, 0.0f);
    }

    // reciprocalForce, which the general path and the walker kernel both steer by: with
    // nobody about, the force takes the walker in one decision to the velocity its steering
    // asks for, capped at its top speed; with walkers coming the other way, that velocity
    // turns right by the type's turn for one, two, or three and more of them, and keeps
    // its speed; with keep_right off, no turn.
    void reciprocalForceReachesThePreferredVelocityTurnedRightOfOncomingWalkers()
    {
        const float mass = 70.0f, decideDt = 1.0f / 24.0f;
        const PlanarBody body{{0.0f, 0.0f}, {1.0f, 0.0f}, 0.3f, 1.4f};
        float upward = 0.0f;  // the largest |y| of a force: a walker is never lifted
        auto chosen = [&](glm::vec3 force, std::size_t oncoming, const std::array<glm::vec2, 3>& turns,
                          const ReciprocalAvoidanceParams& params) {
            const glm::vec3 f = reciprocalForce(body, mass, force, {}, oncoming, turns, decideDt, params);
            upward = std::max(upward, std::fabs(f.y));
            return body.velocity + glm::vec2(f.x, f.z) * (decideDt / mass);
        };
        const ReciprocalAvoidanceParams params;  // keep_right 0.5 rad
        std::array<glm::vec2, 3> turns;  // as TypeSteering.cpp makes them
        for (std::size_t n = 0; n < 3; ++n) {
            const float angle = params.keepRightRad * float(n + 1) / 3.0f;
            turns[n] = {std::cos(angle), std::sin(angle)};
        }
        // 0.2 m/s more along x: 1.2 m/s, within the top speed.
        const glm::vec3 gentle(0.2f * mass / decideDt, 0.0f, 0.0f);
        glm::vec2 v = chosen(gentle, 0, turns, params);
        QVERIFY2(glm::distance(v, glm::vec2(1.2f, 0.0f)) < 1e-4f, qPrintable(QString("%1 %2").arg(v.x).arg(v.y)));
        // Pushed far harder: capped at 1.4 m/s, still along x.
        v = chosen(gentle * 10.0f, 0, turns, params);
        QVERIFY(std::fabs(glm::length(v) - 1.4f) < 1e-4f && std::fabs(v.y) < 1e-5f);
        // Walkers coming the other way: turned right (toward +y here, (-v.y, v.x) is right
        // in the planar frame), more for more of them, the speed kept.
        float last = 0.0f;
        for (std::size_t oncoming = 1; oncoming <= 4; ++oncoming) {
            v = chosen(gentle, oncoming, turns, params);
            const float angle = std::atan2(v.y, v.x);
            const float expected = params.keepRightRad * float(std::min<std::size_t>(oncoming, 3)) / 3.0f;
            QVERIFY2(std::fabs(angle - expected) < 1e-4f,
                     qPrintable(QString("%1 walkers: %2 rad").arg(oncoming).arg(angle)));
            QVERIFY(std::fabs(glm::length(v) - 1.2f) < 1e-4f);
            QVERIFY(angle >= last);
            last = angle;
        }
        // keep_right off: no turn, whoever comes.
        ReciprocalAvoidanceParams straight;
        straight.keepRightRad = 0.0f;
        v = chosen(gentle, 3, turns, straight);
        QVERIFY(std::fabs(v.y) < 1e-5f);
        QCOMPARE(upward, 0.0f);
    }

    // comesTheOtherWay: a walker ahead facing back at this one counts; one behind, one
    // walking the same way, one crossing at right angles or one that has stopped does not.
    void comesTheOtherWayCountsOnlyWalkersAheadFacingBack()
    {
        const glm::vec2 p(0.0f), f(1.0f, 0.0f);
        QVERIFY(comesTheOtherWay(p, f, {2.0f, 0.5f}, {-1.0f, 0.0f}, false));
        QVERIFY(!comesTheOtherWay(p, f, {2.0f, 0.5f}, {-1.0f, 0.0f}, true));   // stopped
        QVERIFY(!comesTheOtherWay(p, f, {-2.0f, 0.0f}, {-1.0f, 0.0f}, false));  // behind
        QVERIFY(!comesTheOtherWay(p, f, {2.0f, 0.0f}, {1.0f, 0.0f}, false));    // the same way
        QVERIFY(!comesTheOtherWay(p, f, {2.0f, 0.0f}, {0.0f, 1.0f}, false));    // crossing
    }
};

THRONG_REGISTER_TEST(TestReciprocalAvoidance)
#include "TestReciprocalAvoidance.moc"
