// Combining forces and integrating them, as a user checks them: blending sums by weight,
// prioritised allocation serves the urgent first, the vehicle model respects its limits and
// keeps a sane frame, and nothing produces NaN or infinity however extreme the input.
#include "SteeringHarness.h"
#include "TestRegistry.h"

#include "simcore/steering/Steering.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <cmath>
#include <limits>
#include <vector>

using namespace throng::sim;
using namespace throng::test;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

bool orthonormal(const SteeringAgent& a)
{
    auto unit = [](glm::vec3 v) { return std::abs(glm::length(v) - 1.0f) < 1e-4f; };
    return unit(a.forward) && unit(a.side) && unit(a.up) && std::abs(glm::dot(a.forward, a.side)) < 1e-4f &&
           std::abs(glm::dot(a.forward, a.up)) < 1e-4f && std::abs(glm::dot(a.side, a.up)) < 1e-4f;
}

// Every behaviour once for the agent, with the given surroundings; all must be finite.
bool allBehavioursFinite(const SteeringAgent& a, std::span<const Neighbour> neighbours,
                         std::span<const WallSegment> walls, const SteeringPath& path)
{
    const Neighbour other = neighbours.empty() ? Neighbour{} : neighbours[0];
    const std::vector<CircleObstacle> circles{{a.position, 0.0f}, {{1, 0, 0}, 1.0f}};
    const std::vector<BoxObstacle> boxes{{a.position, {0, 0, 0}, {0, 0}}, {{0, 0, 2}, {1, 0, 0}, {1, 1}}};
    const std::vector<glm::vec3> square{{-5, 0, -5}, {5, 0, -5}, {5, 0, 5}, {-5, 0, 5}};
    ObstacleAvoidanceParams repulsive;
    repulsive.response = AvoidanceResponse::Repulsive;
    const glm::vec3 forces[] = {
        seek(a, a.position), seek(a, other.position), flee(a, a.position), arrive(a, a.position),
        arrive(a, {3, 0, 3}), pursue(a, other), evade(a, other), pursueOffset(a, other),
        avoidObstacles(a, circles, boxes, a.position), avoidObstacles(a, circles, boxes, {0, 0, 9}, repulsive),
        wander(a, WanderState{{0, 0, 0}}, {1, 1, 1}).force, wander(a, WanderState{}, {kNaN, 0, 0}).force,
        followPath(a, path), avoidWalls(a, walls), stayInside(a, WalkableBox{{0, 0, 0}, {0, 0, 0}}),
        stayInside(a, WalkablePolygon{square}), followFlow(a, {0, 0, 0}), followFlow(a, {1, 0, 0}),
        separate(a, neighbours), align(a, neighbours), cohere(a, neighbours), followLeader(a, other),
        avoidUnalignedCollisions(a, neighbours)};
    for (const glm::vec3& f : forces)
        if (!isFinite(f))
            return false;
    return true;
}

}  // namespace

class TestSteeringCombination : public QObject {
    Q_OBJECT
private slots:
    void blendingSumsByWeight()
    {
        SteeringRequestList requests;
        requests.add({1, 0, 0}, 2.0f);
        requests.add({0, 0, 3}, 1.0f);
        requests.add({-1, 0, 0}, 0.5f);
        requests.add({5, 5, 5}, 0.0f);
        QCOMPARE(blendWeighted(requests, 100.0f), glm::vec3(1.5f, 0.0f, 3.0f));
        // Truncated to the budget, direction kept.
        const glm::vec3 capped = blendWeighted(requests, 1.0f);
        QVERIFY(std::abs(glm::length(capped) - 1.0f) < 1e-6f);
        QVERIFY(angleBetween(capped, {1.5f, 0.0f, 3.0f}) < 1e-6f);
        // A broken request is skipped rather than poisoning the sum.
        requests.add({kNaN, 0, 0}, 1.0f);
        requests.add({1, 0, 0}, kInf);
        QCOMPARE(blendWeighted(requests, 100.0f), glm::vec3(1.5f, 0.0f, 3.0f));
    }

    void priorityServesTheUrgentFirst()
    {
        // Budget 3 N: the first request (2.5 N) is served whole, the second (2 N) gets the 0.5 N left,
        // the third is dropped. The requests point along different axes, so each share shows.
        SteeringRequestList requests;
        requests.add({2.5f, 0, 0});
        requests.add({0, 0, 2.0f});
        requests.add({0, 1.0f, 0});
        const glm::vec3 f = allocateByPriority(requests, 3.0f);
        QCOMPARE(f.x, 2.5f);
        QCOMPARE(f.z, 0.5f);
        QCOMPARE(f.y, 0.0f);
        // A request bigger than the whole budget is scaled down to it, and nothing else gets any.
        SteeringRequestList big;
        big.add({0, 0, 0});  // nothing to say: takes nothing
        big.add({6, 0, 0});
        big.add({0, 0, 1});
        QCOMPARE(allocateByPriority(big, 3.0f), glm::vec3(3, 0, 0));
        // Weights scale a request before it is allocated.
        SteeringRequestList weighted;
        weighted.add({1, 0, 0}, 2.0f);
        weighted.add({0, 0, 4}, 0.25f);
        QCOMPARE(allocateByPriority(weighted, 10.0f), glm::vec3(2, 0, 1));
    }

    void requestListHasFixedCapacity()
    {
        SteeringRequestList requests;
        for (std::size_t i = 0; i < SteeringRequestList::kCapacity; ++i)
            QVERIFY(requests.add({1, 0, 0}));
        QVERIFY(!requests.add({1, 0, 0}));
        QCOMPARE(requests.size(), SteeringRequestList::kCapacity);
        requests.clear();
        QVERIFY(requests.empty());
    }

    void vehicleModelRespectsItsLimits()
    {
        SteeringAgent a = walker({0, 0, 0}, {0, 0, 1.0f});
        const SteeringAgent next = advance(a, {100, 50, 0});
        // Force truncated to 3 N on 1 kg: the velocity changes by at most 3 m/s^2 * dt.
        QVERIFY(glm::length(next.velocity - a.velocity) <= 3.0f * kDt + 1e-5f);
        QCOMPARE(next.velocity.y, 0.0f);
        QCOMPARE(next.up, glm::vec3(0, 1, 0));
        QVERIFY(orthonormal(next));
        for (int step = 0; step < 100; ++step)
            a = advance(a, {0, 0, 3});
        QVERIFY(a.speed() <= a.maxSpeed + 1e-6f);
        QVERIFY(std::abs(a.position.x) < 1e-6f);
        // Nearly stopped, it keeps facing where it was going.
        SteeringAgent stopping = walker({0, 0, 0}, {0.0005f, 0, 0.0001f});
        stopping.forward = {0, 0, -1};
        stopping.side = glm::cross(stopping.forward, stopping.up);
        QCOMPARE(advance(stopping, {0, 0, 0}).forward, glm::vec3(0, 0, -1));
        // dt = 0 changes nothing.
        QCOMPARE(integrateVehicle(a, {1, 0, 0}, 0.0f).position, a.position);
    }

    void fliersKeepFlyingAndBankIntoTurns()
    {
        VehicleParams flier;
        flier.flying = true;
        flier.minSpeed = 1.0f;
        flier.bankingGainS2PerM = 0.2f;
        flier.bankingResponseS = 0.5f;
        SteeringAgent bird = walker({0, 10, 0}, {0, 0, 0.2f});
        bird.maxSpeed = 5.0f;
        bird = advance(bird, {0, 0, 0}, flier);
        QVERIFY(std::abs(bird.speed() - 1.0f) < 1e-5f);  // raised to the stall speed
        // A steady level turn to the right: up leans toward the turn, easing in.
        float lastLean = 0.0f, maxLeanStep = 0.0f;
        for (int step = 0; step < 24; ++step) {
            const glm::vec3 levelRight = glm::normalize(glm::cross(glm::vec3(bird.forward.x, 0, bird.forward.z), {0, 1, 0}));
            bird = advance(bird, levelRight * 3.0f, flier);
            QVERIFY(orthonormal(bird));
            const float lean = glm::dot(bird.up, levelRight);
            maxLeanStep = std::max(maxLeanStep, std::abs(lean - lastLean));
            lastLean = lean;
        }
        QVERIFY(std::abs(bird.position.y - 10.0f) < 1e-3f);  // a level turn stays level
        // 3 m/s^2 sideways * 0.2 s^2/m leans the target up by atan(0.6) = 31 deg (sine 0.51); after 1 s
        // of smoothing with a 0.5 s time constant it has come 86 % of the way.
        QVERIFY2(lastLean > 0.35f && lastLean < 0.52f, qPrintable(QString("up leans %1 toward the turn").arg(lastLean)));
        // Unsmoothed, the first step alone would lean 0.51; smoothed, no step adds more than 0.06.
        QVERIFY2(maxLeanStep < 0.06f, "banking jumped instead of easing in");
    }

    void aFlierClimbingStraightUpKeepsItsSide()
    {
        // Heading along its up, a flier's frame cannot be made square by forward x up: it
        // keeps the side it had and takes the up square to that side and its new forward.
        VehicleParams flier;
        flier.flying = true;
        flier.minSpeed = 1.0f;
        flier.bankingGainS2PerM = 0.2f;
        SteeringAgent bird = walker({0, 10, 0}, {0, 2, 0});
        bird.maxSpeed = 5.0f;
        bird.forward = {0, 0, 1};
        bird.side = glm::cross(bird.forward, bird.up);
        const glm::vec3 side = bird.side;
        QCOMPARE(side, glm::vec3(-1, 0, 0));
        for (int step = 0; step < 12; ++step) {
            bird = advance(bird, {0, 0, 0}, flier);
            QCOMPARE(bird.forward, glm::vec3(0, 1, 0));
            QVERIFY(glm::distance(bird.side, side) < 1e-6f);
            QVERIFY(orthonormal(bird));
            QVERIFY2(glm::distance(bird.up, glm::cross(side, bird.forward)) < 1e-6f,
                     qPrintable(QString("up (%1, %2, %3)").arg(bird.up.x).arg(bird.up.y).arg(bird.up.z)));
        }
        QVERIFY(std::abs(bird.position.y - 10.0f - 12 * 2.0f * kDt) < 1e-4f);  // still climbing at 2 m/s
    }

    void nothingGoesNonFiniteWithExtremeInput()
    {
        const std::vector<WallSegment> walls{{{-2, 0, 0}, {2, 0, 0}}, {{3, 0, 3}, {3, 0, 3}}};
        const std::vector<glm::vec3> spine{{0, 0, 0}, {0, 0, 0}, {4, 0, 0}, {4, 0, 0}, {4, 0, 4}};
        const SteeringPath path{spine, 1.0f, false};
        const std::vector<glm::vec3> pointPath{{1, 0, 1}, {1, 0, 1}};
        const SteeringPath degenerate{pointPath, 0.0f, true};

        std::vector<SteeringAgent> cases;
        SteeringAgent massless = walker({0, 0, -1}, {0, 0, 1});
        massless.mass = 0.0f;
        cases.push_back(massless);
        SteeringAgent frozen = walker({1, 0, 1}, {0, 0, 0});
        frozen.maxSpeed = 0.0f;
        cases.push_back(frozen);
        SteeringAgent onWall = walker({0, 0, 0}, {0, 0, 1.4f});  // exactly on the wall's line
        cases.push_back(onWall);
        SteeringAgent onWallParallel = walker({1, 0, 0}, {1.4f, 0, 0});
        cases.push_back(onWallParallel);
        SteeringAgent broken = walker({kNaN, 0, kInf}, {kInf, kNaN, 0});
        broken.forward = {0, 0, 0};
        broken.mass = kNaN;
        broken.maxForce = kInf;
        broken.maxSpeed = kNaN;
        broken.radius = -1.0f;
        cases.push_back(broken);
        SteeringAgent negative = walker({2, 0, 2}, {1, 0, 0});
        negative.mass = -5.0f;
        negative.maxForce = -1.0f;
        negative.maxSpeed = -1.0f;
        cases.push_back(negative);
        SteeringAgent huge = walker({1e30f, 0, -1e30f}, {1e30f, 0, 1e30f});
        huge.maxForce = 1e30f;
        huge.maxSpeed = 1e30f;
        cases.push_back(huge);

        for (std::size_t c = 0; c < cases.size(); ++c) {
            SteeringAgent a = cases[c];
            // Neighbours: one coincident, one coincident with the same id, one broken.
            const std::vector<Neighbour> neighbours{{a.position, a.velocity, a.forward, a.radius, a.id + 1},
                                                    {a.position, {}, {0, 0, 0}, 0.0f, a.id},
                                                    {{kNaN, 0, 0}, {0, kInf, 0}, {kNaN, 0, 0}, kNaN, 99}};
            for (int step = 0; step < 48; ++step) {
                QVERIFY2(allBehavioursFinite(a, neighbours, walls, path), qPrintable(QString("case %1").arg(c)));
                QVERIFY(allBehavioursFinite(a, neighbours, walls, degenerate));
                SteeringRequestList requests;
                requests.add(avoidWalls(a, walls));
                requests.add(followPath(a, path));
                requests.add(separate(a, neighbours));
                const glm::vec3 f = allocateByPriority(requests, a.maxForce);
                QVERIFY(isFinite(f));
                QVERIFY(isFinite(blendWeighted(requests, a.maxForce)));
                a = advance(a, f);
                QVERIFY2(isFinite(a), qPrintable(QString("case %1, step %2").arg(c).arg(step)));
                VehicleParams flier;
                flier.flying = true;
                flier.minSpeed = 2.0f;
                flier.bankingGainS2PerM = 1.0f;
                QVERIFY(isFinite(advance(a, {kInf, kNaN, 1e30f}, flier)));
            }
        }
        // A massless agent still moves, within its speed limit.
        SteeringAgent m = massless;
        for (int step = 0; step < 24; ++step)
            m = advance(m, seek(m, {0, 0, 5}));
        QVERIFY(m.speed() > 0.0f && m.speed() <= m.maxSpeed + 1e-6f);
        // A frozen agent stays put.
        QCOMPARE(advance(frozen, {3, 0, 3}).position, frozen.position);
    }
};

THRONG_REGISTER_TEST(TestSteeringCombination)
#include "TestSteeringCombination.moc"
