// Avoidance behaviours as a user checks them: obstacle avoidance gets round circles and boxes
// without touching or dithering, walls are never crossed, containment keeps a wanderer inside,
// and two agents meeting head-on both get past.
#include "SteeringHarness.h"
#include "TestRegistry.h"

#include "simcore/steering/Containment.h"
#include "simcore/steering/FlockingBehaviours.h"
#include "simcore/steering/ObstacleAvoidance.h"
#include "simcore/steering/SteeringCombination.h"
#include "simcore/steering/TargetBehaviours.h"
#include "simcore/steering/UnalignedCollisionAvoidance.h"
#include "simcore/steering/VehicleModel.h"
#include "simcore/steering/WallAvoidance.h"
#include "simcore/steering/Wander.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <QTest>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace throng::sim;
using namespace throng::test;

Q_DECLARE_METATYPE(throng::sim::AvoidanceResponse)

namespace {

// The gap between the agent's body and the obstacle's surface (negative = overlapping).
float gapTo(const SteeringAgent& a, const CircleObstacle& c) { return planarDistance(a.position, c.centre) - c.radius - a.radius; }

float gapTo(const SteeringAgent& a, const BoxObstacle& b)
{
    const glm::vec2 rel(a.position.x - b.centre.x, a.position.z - b.centre.z);
    const glm::vec2 u(b.axis.x, b.axis.z), w(-b.axis.z, b.axis.x);
    const glm::vec2 local(glm::dot(rel, u), glm::dot(rel, w));
    const glm::vec2 out = glm::max(glm::abs(local) - b.halfSize, glm::vec2(0.0f));
    return glm::length(out) - a.radius;  // the agent never gets inside, where this would be wrong
}

float distanceToSegment(glm::vec3 p, const WallSegment& w)
{
    const glm::vec2 a(w.a.x, w.a.z), b(w.b.x, w.b.z), q(p.x, p.z);
    const float t = glm::clamp(glm::dot(q - a, b - a) / glm::dot(b - a, b - a), 0.0f, 1.0f);
    return glm::distance(q, a + (b - a) * t);
}

}  // namespace

class TestSteeringAvoidance : public QObject {
    Q_OBJECT
private slots:
    void obstacleAvoidanceSilentWhenNothingAhead()
    {
        const SteeringAgent a = walker({0, 0, 0}, {0, 0, 1.4f});
        // Cylinder: 1 m + 1.5 s * 1.4 m/s = 3.1 m long, 0.5 m half width.
        const std::vector<CircleObstacle> circles{{{0, 0, -3}, 1.0f},  // behind
                                                  {{3, 0, 1}, 1.0f},   // beside, 1.5 m clear
                                                  {{0, 0, 5}, 1.0f}};  // ahead, beyond the cylinder
        const std::vector<BoxObstacle> boxes{{{-3, 0, 2}, {1, 0, 0}, {1.0f, 1.0f}}};
        for (AvoidanceResponse mode : {AvoidanceResponse::Lateral, AvoidanceResponse::Repulsive}) {
            ObstacleAvoidanceParams params;
            params.response = mode;
            QCOMPARE(avoidObstacles(a, circles, boxes, {0, 0, 20}, params), glm::vec3(0.0f));
        }
    }

    void obstacleAvoidanceTurnsAwayFromWhatIsInTheCylinder_data()
    {
        QTest::addColumn<AvoidanceResponse>("mode");
        QTest::addColumn<bool>("box");
        QTest::newRow("lateral, circle") << AvoidanceResponse::Lateral << false;
        QTest::newRow("repulsive, circle") << AvoidanceResponse::Repulsive << false;
        QTest::newRow("lateral, box") << AvoidanceResponse::Lateral << true;
        QTest::newRow("repulsive, box") << AvoidanceResponse::Repulsive << true;
    }

    void obstacleAvoidanceTurnsAwayFromWhatIsInTheCylinder()
    {
        QFETCH(AvoidanceResponse, mode);
        QFETCH(bool, box);
        // Heading +z; the obstacle sits 0.4 m to the left (+x) of the heading line, 2 m ahead.
        const SteeringAgent a = walker({0, 0, 0}, {0, 0, 1.4f});
        const glm::vec3 centre(0.4f, 0, 2.5f);
        std::vector<CircleObstacle> circles;
        std::vector<BoxObstacle> boxes;
        if (box)
            boxes.push_back({centre, glm::normalize(glm::vec3(1, 0, 1)), {0.5f, 0.5f}});
        else
            circles.push_back({centre, 0.5f});
        ObstacleAvoidanceParams params;
        params.response = mode;
        const glm::vec3 f = avoidObstacles(a, circles, boxes, {0, 0, 20}, params);
        QVERIFY(glm::length(f) > 0.0f);
        QVERIFY2(f.x < 0.0f, "does not push away from the obstacle's side");
        QVERIFY(glm::length(f) <= a.maxForce + 1e-5f);
        if (mode == AvoidanceResponse::Lateral)
            QVERIFY(std::abs(glm::dot(f, glm::normalize(a.velocity))) < 1e-4f);
    }

    void obstacleAvoidancePushesStraightOutWhenOverlapping()
    {
        const SteeringAgent a = walker({1.0f, 0, 0}, {0, 0, 1.4f});
        const std::vector<CircleObstacle> circles{{{0, 0, 0}, 1.0f}};
        const glm::vec3 f = avoidObstacles(a, circles, {}, {0, 0, 20});
        QVERIFY(angleBetween(f, glm::vec3(1, 0, 0)) < 1e-4f);
        QCOMPARE(glm::length(f), a.maxForce);
    }

    void agentPassesObstacleHeadOn_data()
    {
        QTest::addColumn<AvoidanceResponse>("mode");
        QTest::addColumn<bool>("box");
        QTest::addColumn<float>("goalZ");
        for (float goalZ : {16.0f, 9.5f}) {
            const QString far = goalZ > 10.0f ? "goal far behind" : "goal just behind";
            QTest::newRow(qPrintable("lateral, circle, " + far)) << AvoidanceResponse::Lateral << false << goalZ;
            QTest::newRow(qPrintable("repulsive, circle, " + far)) << AvoidanceResponse::Repulsive << false << goalZ;
            QTest::newRow(qPrintable("lateral, box, " + far)) << AvoidanceResponse::Lateral << true << goalZ;
            QTest::newRow(qPrintable("repulsive, box, " + far)) << AvoidanceResponse::Repulsive << true << goalZ;
        }
    }

    void agentPassesObstacleHeadOn()
    {
        QFETCH(AvoidanceResponse, mode);
        QFETCH(bool, box);
        QFETCH(float, goalZ);
        // Agent, obstacle centre and goal exactly in a line along +z, at top speed.
        const glm::vec3 goal(0, 0, goalZ);
        std::vector<CircleObstacle> circles;
        std::vector<BoxObstacle> boxes;
        if (box)
            boxes.push_back({{0, 0, 7}, {1, 0, 0}, {1.2f, 0.6f}});
        else
            circles.push_back({{0, 0, 7}, 1.0f});
        ObstacleAvoidanceParams params;
        params.response = mode;
        SteeringAgent a = walker({0, 0, 0}, {0, 0, 1.4f});
        float minGap = 1e9f;
        int arrivedAt = -1;
        int lateralFlips = 0;
        float lastSide = 0.0f;
        for (int step = 0; step < 24 * 40 && arrivedAt < 0; ++step) {
            const glm::vec3 avoid = avoidObstacles(a, circles, boxes, goal, params);
            const float side = glm::dot(avoid, a.side);
            if (side != 0.0f) {
                if (lastSide != 0.0f && (side > 0.0f) != (lastSide > 0.0f))
                    ++lateralFlips;
                lastSide = side;
            }
            SteeringRequestList requests;
            requests.add(avoid);
            requests.add(arrive(a, goal));
            a = advance(a, allocateByPriority(requests, a.maxForce));
            minGap = std::min(minGap, box ? gapTo(a, boxes[0]) : gapTo(a, circles[0]));
            if (planarDistance(a.position, goal) < 0.1f)
                arrivedAt = step;
        }
        QVERIFY2(minGap > 0.0f, qPrintable(QString("touched the obstacle: gap %1 m").arg(minGap)));
        QVERIFY2(arrivedAt > 0, "never got past the obstacle to its goal");
        if (mode == AvoidanceResponse::Lateral)
            QCOMPARE(lateralFlips, 0);
    }

    void lateralAvoidancePassesOnTheGoalSide_data()
    {
        QTest::addColumn<float>("goalX");
        QTest::newRow("goal to the left") << 3.0f;
        QTest::newRow("goal to the right") << -3.0f;
    }

    void lateralAvoidancePassesOnTheGoalSide()
    {
        // At top speed, an obstacle already in the cylinder sits 10 cm off the heading line on the
        // goal's side: steering away from its centre alone would pass it away from the goal.
        // Passing on the goal's side is the shorter way.
        QFETCH(float, goalX);
        const float side = goalX > 0.0f ? 1.0f : -1.0f;
        const glm::vec3 goal(goalX, 0, 8);
        const std::vector<CircleObstacle> circles{{{0.1f * side, 0, 2.5f}, 0.5f}};
        SteeringAgent a = walker({0, 0, 0}, {0, 0, 1.4f});
        float xWhenLevel = 0.0f;
        for (int step = 0; step < 24 * 15 && a.position.z < 2.5f; ++step) {
            SteeringRequestList requests;
            requests.add(avoidObstacles(a, circles, {}, goal));
            requests.add(seek(a, goal));
            a = advance(a, allocateByPriority(requests, a.maxForce));
            xWhenLevel = a.position.x;
            QVERIFY(gapTo(a, circles[0]) > 0.0f);
        }
        QVERIFY2(xWhenLevel * side > 0.1f, qPrintable(QString("passed at x = %1, goal at x = %2").arg(xWhenLevel).arg(goalX)));
    }

    void lateralAvoidanceDoesNotDitherWhenNearlyCollinear_data()
    {
        QTest::addColumn<glm::vec3>("obstacleShift");
        QTest::addColumn<glm::vec3>("goalShift");
        QTest::newRow("exactly collinear") << glm::vec3(0.0f) << glm::vec3(0.0f);
        QTest::newRow("obstacle 1 mm left") << glm::vec3(0.001f, 0, 0) << glm::vec3(0.0f);
        QTest::newRow("obstacle 1 mm right") << glm::vec3(-0.001f, 0, 0) << glm::vec3(0.0f);
        QTest::newRow("goal 1 mm left") << glm::vec3(0.0f) << glm::vec3(0.001f, 0, 0);
        QTest::newRow("goal 1 cm right") << glm::vec3(0.0f) << glm::vec3(-0.01f, 0, 0);
        QTest::newRow("both off by 1e-6 m") << glm::vec3(1e-6f, 0, 0) << glm::vec3(-1e-6f, 0, 0);
    }

    void lateralAvoidanceDoesNotDitherWhenNearlyCollinear()
    {
        QFETCH(glm::vec3, obstacleShift);
        QFETCH(glm::vec3, goalShift);
        const glm::vec3 goal = glm::vec3(0, 0, 16) + goalShift;
        const std::vector<CircleObstacle> circles{{glm::vec3(0, 0, 7) + obstacleShift, 1.0f}};
        SteeringAgent a = walker({0, 0, 0}, {0, 0, 1.4f});
        int flips = 0;
        float lastSide = 0.0f, lastX = 0.0f;
        int xReversals = 0;
        for (int step = 0; step < 24 * 12; ++step) {
            const glm::vec3 avoid = avoidObstacles(a, circles, {}, goal);
            const float side = glm::dot(avoid, a.side);
            if (side != 0.0f) {
                if (lastSide != 0.0f && (side > 0.0f) != (lastSide > 0.0f))
                    ++flips;
                lastSide = side;
            }
            SteeringRequestList requests;
            requests.add(avoid);
            requests.add(seek(a, goal));
            a = advance(a, allocateByPriority(requests, a.maxForce));
            // Until it is level with the obstacle, the sideways drift never changes direction.
            if (a.position.z < 7.0f) {
                const float dx = a.position.x - lastX;
                if (std::abs(dx) > 1e-4f && std::abs(lastX) > 1e-4f && (dx > 0.0f) != (lastX > 0.0f))
                    ++xReversals;
            }
            lastX = a.position.x;
        }
        QCOMPARE(flips, 0);
        QCOMPARE(xReversals, 0);
    }

    void wallIsNeverCrossed()
    {
        // Eight agents at top speed, at angles from -70 to +60 degrees off the wall's normal, each
        // seeking the mirror of its start behind an 8 m wall: 8 x 1250 = 10,000 agent-steps.
        const std::vector<WallSegment> walls{{{-4, 0, 0}, {4, 0, 0}}};
        int agentSteps = 0, crossings = 0;
        float minGap = 1e9f;
        std::uint32_t id = 0;
        for (float angleDeg : {-70.0f, -50.0f, -30.0f, -10.0f, 0.0f, 10.0f, 30.0f, 60.0f}) {
            const float t = glm::radians(angleDeg);
            const glm::vec3 dir(std::sin(t), 0.0f, std::cos(t));
            const glm::vec3 start = -dir * 5.0f;
            const glm::vec3 target = dir * 5.0f;
            SteeringAgent a = walker(start, dir * 1.4f, id++);
            for (int step = 0; step < 1250; ++step, ++agentSteps) {
                SteeringRequestList requests;
                requests.add(avoidWalls(a, walls));
                requests.add(seek(a, target));
                const SteeringAgent next = advance(a, blendWeighted(requests, a.maxForce));
                crossings += crossesSegment(a.position, next.position, walls[0].a, walls[0].b);
                a = next;
                minGap = std::min(minGap, distanceToSegment(a.position, walls[0]) - a.radius);
            }
        }
        QCOMPARE(agentSteps, 10000);
        QCOMPARE(crossings, 0);
        // Stronger still: no body ever touched the wall.
        QVERIFY2(minGap > 0.0f, qPrintable(QString("a body came %1 m into the wall").arg(-minGap)));
    }

    void wallStandoffHoldsAgainstAPush()
    {
        // Another behaviour pushes the agent straight at the wall with the whole force budget; the
        // standoff term still stops it before its body reaches the wall.
        const std::vector<WallSegment> walls{{{-5, 0, 0}, {5, 0, 0}}};
        SteeringAgent a = walker({0, 0, -3}, {0, 0, 1.4f});
        const glm::vec3 push(0.0f, 0.0f, a.maxForce);
        for (int step = 0; step < 24 * 20; ++step) {
            SteeringRequestList requests;
            requests.add(avoidWalls(a, walls));
            requests.add(push);
            a = advance(a, blendWeighted(requests, a.maxForce));
            QVERIFY2(-a.position.z - a.radius > 0.0f, qPrintable(QString("body reached the wall at step %1").arg(step)));
        }
        QVERIFY(a.speed() < 0.01f);
        // With nothing near, the wall has nothing to say.
        QCOMPARE(avoidWalls(walker({0, 0, -5}, {1.4f, 0, 0}), walls), glm::vec3(0.0f));
    }

    // The mouth of a passage: a room's wall (x = 10) meets the passage's walls at joints
    // (10, -0.5) and (10, 0.5). A walker in front of it, heading in, is never pushed back
    // out by the standoff of those two corners (with the room's corners treated so, 3 of 150
    // walkers stood in front of an empty 1 m passage for good); sideways is still allowed.
    // A room's own corner, seen from inside, still pushes back along the way.
    void aPassagesMouthDoesNotPushBack()
    {
        const std::vector<WallSegment> walls{{{10, 0, -5}, {10, 0, -0.5f}}, {{10, 0, -0.5f}, {12, 0, -0.5f}},
                                             {{10, 0, 5}, {10, 0, 0.5f}}, {{10, 0, 0.5f}, {12, 0, 0.5f}}};
        const glm::vec3 target(20.0f, 0.0f, 0.0f);
        for (const float z : {0.0f, 0.1f, -0.15f})
            for (const float x : {9.6f, 9.72f, 9.85f}) {
                const SteeringAgent a = walker({x, 0, z}, {0, 0, 0});
                const glm::vec3 f = avoidWalls(a, walls, {}, &target);
                const float back = -glm::dot(f, glm::normalize(target - a.position));
                QVERIFY2(back <= 1e-4f, qPrintable(QString("pushed back with %1 N at (%2, %3)").arg(back).arg(x).arg(z)));
            }
        // A room's corner (the walls meet at (0, 0); the walker is inside, the way into it).
        const std::vector<WallSegment> corner{{{0, 0, 0}, {5, 0, 0}}, {{0, 0, 0}, {0, 0, 5}}};
        const glm::vec3 intoCorner(-5.0f, 0.0f, -5.0f);
        const glm::vec3 f = avoidWalls(walker({0.4f, 0, 0.4f}, {0, 0, 0}), corner, {}, &intoCorner);
        QVERIFY2(f.x > 0.0f && f.z > 0.0f, "a room's corner no longer holds a walker off");
    }

    // The outer wall of a corridor's bend, drawn as a straight wall and then segments
    // turning 7.5 degrees each (a half circle of 4.4 m radius in 24). A walker near the
    // straight's end, walking along it 0.22 m off, is not braked by the joints ahead:
    // braked for along the line to each joint, walkers stood at the start of such a bend
    // for good. A room's corner (90 degrees) still holds a walker off, as tested above.
    void aBendDrawnAsSegmentsDoesNotBrakeAWalkerAlongIt()
    {
        std::vector<WallSegment> walls{{{0, 0, -4.4f}, {20, 0, -4.4f}}};
        glm::vec3 last(20.0f, 0.0f, -4.4f);
        for (int k = 1; k <= 12; ++k) {
            const float a = -1.5707963f + 3.14159265f * float(k) / 24.0f;
            const glm::vec3 next(20.0f + 4.4f * std::cos(a), 0.0f, 4.4f * std::sin(a));
            walls.push_back({last, next});
            last = next;
        }
        for (const float x : {18.0f, 19.0f, 19.6f, 19.9f}) {
            SteeringAgent a = walker({x, 0, -4.0f}, {1.32f, 0, 0});
            a.radius = 0.18f;
            const glm::vec3 ahead(x + 2.0f, 0.0f, -3.9f);
            const glm::vec3 f = avoidWalls(a, walls, {}, &ahead);
            QVERIFY2(f.x > -0.05f, qPrintable(QString("braked with %1 N at x = %2").arg(-f.x).arg(x)));
        }
    }

    void containmentKeepsAWandererInside_data()
    {
        QTest::addColumn<bool>("polygon");
        QTest::newRow("box") << false;
        QTest::newRow("polygon") << true;
    }

    void containmentKeepsAWandererInside()
    {
        QFETCH(bool, polygon);
        // A 10 m square either way; the wanderer is lively (1 m jitter circle, 0.3 m jitter).
        const WalkableBox box{{-5, -1, -5}, {5, 1, 5}};
        const std::vector<glm::vec3> square{{-5, 0, -5}, {5, 0, -5}, {5, 0, 5}, {-5, 0, 5}};
        const WalkablePolygon poly{square};
        WanderParams wanderParams;
        wanderParams.radiusM = 1.0f;
        wanderParams.jitterM = 0.3f;
        SteeringAgent a = walker({0, 0, 0}, {1.4f, 0, 0}, 5);
        WanderState state;
        int quadrants[4] = {0, 0, 0, 0};
        for (int step = 0; step < 24 * 120; ++step) {
            const WanderResult w = wander(a, state, signedRandom3(9, a.id, std::uint64_t(step)), wanderParams);
            state = w.state;
            SteeringRequestList requests;
            requests.add(polygon ? stayInside(a, poly) : stayInside(a, box));
            requests.add(w.force);
            a = advance(a, allocateByPriority(requests, a.maxForce));
            QVERIFY2(std::abs(a.position.x) < 5.0f && std::abs(a.position.z) < 5.0f,
                     qPrintable(QString("left the region at step %1").arg(step)));
            ++quadrants[(a.position.x > 0.0f ? 1 : 0) + (a.position.z > 0.0f ? 2 : 0)];
        }
        for (int q : quadrants)
            QVERIFY2(q > 0, "the wanderer never visited one quarter of the region");
        QCOMPARE(stayInside(walker({0, 0, 0}, {1.4f, 0, 0}), box), glm::vec3(0.0f));
    }

    void headOnAgentsPassEachOther_data()
    {
        QTest::addColumn<float>("offsetM");
        QTest::addColumn<float>("speedB");
        QTest::newRow("exactly head-on") << 0.0f << 1.4f;
        QTest::newRow("0.5 mm apart") << 0.0005f << 1.4f;
        QTest::newRow("5 cm apart") << 0.05f << 1.4f;
        QTest::newRow("exactly head-on, unequal speeds") << 0.0f << 1.0f;
    }

    void headOnAgentsPassEachOther()
    {
        QFETCH(float, offsetM);
        QFETCH(float, speedB);
        SteeringAgent a = walker({0, 0, -8}, {0, 0, 1.4f}, 1);
        SteeringAgent b = walker({offsetM, 0, 8}, {0, 0, -speedB}, 2);
        b.maxSpeed = speedB;
        const glm::vec3 goalA(0, 0, 8), goalB(offsetM, 0, -8);
        float minDistance = 1e9f;
        int doneAt = -1;
        for (int step = 0; step < 24 * 40 && doneAt < 0; ++step) {
            // Both decide from the same previous state.
            const Neighbour na = asNeighbour(a), nb = asNeighbour(b);
            SteeringRequestList ra, rb;
            ra.add(avoidUnalignedCollisions(a, std::span<const Neighbour>(&nb, 1)));
            ra.add(arrive(a, goalA));
            rb.add(avoidUnalignedCollisions(b, std::span<const Neighbour>(&na, 1)));
            rb.add(arrive(b, goalB));
            a = advance(a, allocateByPriority(ra, a.maxForce));
            b = advance(b, allocateByPriority(rb, b.maxForce));
            minDistance = std::min(minDistance, planarDistance(a.position, b.position));
            if (planarDistance(a.position, goalA) < 0.1f && planarDistance(b.position, goalB) < 0.1f)
                doneAt = step;
        }
        QVERIFY2(doneAt > 0, "the two never both reached their goals");
        QVERIFY2(minDistance > a.radius + b.radius, qPrintable(QString("bodies overlapped: %1 m").arg(minDistance)));
    }

    // Unaligned collision avoidance dodges the soonest threat, and of two that come at the
    // same moment the one of the lower id, whatever the order the neighbours come in (the
    // walker kernel meets them in another order than the general path, and takes the same
    // choice, behave::SoonestApproach). Two walkers come head on, 0.2 m to the agent's left
    // and right: it steps away from the one it dodges, so the force's side tells which.
    void unalignedDodgesTheSoonestThreatTiesById()
    {
        const SteeringAgent a = walker({0, 0, 0}, {0, 0, 1.4f}, 1);
        auto oncoming = [](float x, float z, std::uint32_t id) {
            return Neighbour{{x, 0.0f, z}, {0.0f, 0.0f, -1.4f}, {0.0f, 0.0f, -1.0f}, 0.3f, id};
        };
        // The agent's right is -x (heading +z): dodging the walker on its left (x < 0) is a
        // push to +x, dodging the one on its right a push to -x.
        auto sideOf = [&](std::vector<Neighbour> near) {
            const glm::vec3 f = avoidUnalignedCollisions(a, near);
            return f.x > 0.0f ? +1 : f.x < 0.0f ? -1 : 0;
        };
        const Neighbour left7 = oncoming(-0.2f, 4.0f, 7), right3 = oncoming(0.2f, 4.0f, 3);
        QCOMPARE(sideOf({left7, right3}), -1);  // the same moment: id 3, on the right
        QCOMPARE(sideOf({right3, left7}), -1);
        const Neighbour left2 = oncoming(-0.2f, 4.0f, 2);
        QCOMPARE(sideOf({left2, right3}), +1);  // now the left one has the lower id
        QCOMPARE(sideOf({right3, left2}), +1);
        const Neighbour left9Sooner = oncoming(-0.2f, 3.0f, 9);
        QCOMPARE(sideOf({right3, left9Sooner}), +1);  // sooner beats a lower id
        QCOMPARE(sideOf({left9Sooner, right3}), +1);
        // One that passes wide of the body and margin is no threat.
        QCOMPARE(sideOf({oncoming(2.0f, 4.0f, 1)}), 0);
    }

    // Out-of-range parameters are read the same way on every path (separationGains,
    // unalignedGains, bankingBlend, which the kernels share with these functions): a
    // negative range as none, a damping time below 1 ms as 1 ms, a banking time that is not
    // a number as 1 ms, a brake share that is not a number as 0 and one above 1 as 1.
    void parametersOutOfRangeReadAsTheirLimits()
    {
        const SteeringAgent a = walker({0, 0, 0}, {0, 0, 1.0f}, 1);
        const Neighbour near{{0.0f, 0.0f, 0.7f}, {0.0f, 0.0f, -0.5f}, {0.0f, 0.0f, -1.0f}, 0.3f, 2};  // 0.1 m apart
        auto push = [&](float range, float damping) {
            SeparationParams p;
            p.rangeM = range;
            p.dampingTimeS = damping;
            return separate(a, std::vector<Neighbour>{near}, p);
        };
        QVERIFY(push(0.5f, 0.5f) != glm::vec3(0.0f));  // in range: pushed
        QCOMPARE(push(-1.0f, 0.5f), glm::vec3(0.0f));   // no range: not touching, no push
        QCOMPARE(push(-1.0f, 0.5f), push(0.0f, 0.5f));
        QVERIFY(push(0.5f, 0.0f) == push(0.5f, 1e-3f));
        QVERIFY(push(0.5f, -2.0f) == push(0.5f, 1e-3f));
        QVERIFY(push(0.5f, 0.0f) != push(0.5f, 0.5f));  // the damping does count

        const Neighbour headOn{{0.0f, 0.0f, 3.0f}, {0.0f, 0.0f, -1.0f}, {0.0f, 0.0f, -1.0f}, 0.3f, 3};
        auto dodge = [&](float brake) {
            UnalignedAvoidanceParams p;
            p.brakeFraction = brake;
            return avoidUnalignedCollisions(a, std::vector<Neighbour>{headOn}, p);
        };
        QVERIFY(dodge(0.0f) != dodge(0.5f));  // the brake share does count
        QVERIFY(dodge(NAN) == dodge(0.0f));
        QVERIFY(dodge(2.0f) == dodge(1.0f));

        SteeringAgent bird = walker({0, 10, 0}, {5.0f, 0.0f, 0.0f}, 4);
        auto banked = [&](float response) {
            VehicleParams p;
            p.flying = true;
            p.bankingGainS2PerM = 0.1f;
            p.bankingResponseS = response;
            return integrateVehicle(bird, {0.0f, 0.0f, 3.0f}, 1.0f / 24.0f, p).up;  // a turn: it banks
        };
        QVERIFY(banked(0.5f) != banked(0.05f));  // the response does count
        QVERIFY(banked(NAN) == banked(1e-3f));  // (below 1 ms any time levels up in one step)
    }

    // Containment asks only where a probe can reach the bounds: from 0.5 m plus 1 m per m/s
    // plus the body (0.3 m) from a face. The walker kernel takes the same test.
    void containmentAsksOnlyWhereAProbeReachesTheBounds()
    {
        const WalkableBox box{{-10.0f, 0.0f, -10.0f}, {10.0f, 5.0f, 10.0f}};
        const ContainmentParams p;
        QVERIFY(!ContainmentBehaviour::probesReach({0, 0, 0}, 1.4f, 0.3f, box, p, false));
        QVERIFY(!ContainmentBehaviour::probesReach({7.7f, 0, 0}, 1.4f, 0.3f, box, p, false));  // 2.3 m from the face
        QVERIFY(ContainmentBehaviour::probesReach({7.9f, 0, 0}, 1.4f, 0.3f, box, p, false));   // 2.1 m
        QVERIFY(!ContainmentBehaviour::probesReach({9.0f, 0, 0}, 0.0f, 0.3f, box, p, false));  // standing: 0.8 m
        QVERIFY(ContainmentBehaviour::probesReach({0, 0, -9.5f}, 0.0f, 0.3f, box, p, false));
        // A walker ignores the height; a flier 0.5 m under the ceiling reaches it.
        QVERIFY(!ContainmentBehaviour::probesReach({0, 4.5f, 0}, 0.0f, 0.3f, box, p, false));
        QVERIFY(ContainmentBehaviour::probesReach({0, 4.5f, 0}, 0.0f, 0.3f, box, p, true));
        // And where it asks, a walker probing past the face is pushed back in.
        SteeringAgent w = walker({9.0f, 0, 0}, {1.4f, 0, 0}, 1);
        w.forward = {1, 0, 0};
        QVERIFY(stayInside(w, box, p).x < 0.0f);
    }
};

THRONG_REGISTER_TEST(TestSteeringAvoidance)
#include "TestSteeringAvoidance.moc"
