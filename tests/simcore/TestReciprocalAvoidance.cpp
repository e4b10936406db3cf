// Reciprocal velocity obstacles (ORCA) as a pure function, as RVO2's users check it: a
// symmetric circle swaps without contact, and a boxed-in body stands still.
#include "TestRegistry.h"

#include "simcore/steering/ReciprocalAvoidance.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <algorithm>
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
};

THRONG_REGISTER_TEST(TestReciprocalAvoidance)
#include "TestReciprocalAvoidance.moc"
