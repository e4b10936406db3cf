// Group behaviours as a user checks them: separated agents keep apart, alignment brings
// headings together, cohesion draws a spread group in, and followers keep out of the way
// in front of their leader.
#include "SteeringHarness.h"
#include "TestRegistry.h"

#include "simcore/steering/FlockingBehaviours.h"
#include "simcore/steering/LeaderFollowing.h"
#include "simcore/steering/SteeringCombination.h"
#include "simcore/steering/TargetBehaviours.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <QTest>

#include <cmath>
#include <vector>

using namespace throng::sim;
using namespace throng::test;

namespace {

// Everyone but agent i, as the neighbour grid would hand them over.
std::vector<Neighbour> othersThan(const std::vector<SteeringAgent>& agents, std::size_t i)
{
    std::vector<Neighbour> out;
    for (std::size_t j = 0; j < agents.size(); ++j)
        if (j != i)
            out.push_back(asNeighbour(agents[j]));
    return out;
}

float minPairDistance(const std::vector<SteeringAgent>& agents)
{
    float best = 1e9f;
    for (std::size_t i = 0; i < agents.size(); ++i)
        for (std::size_t j = i + 1; j < agents.size(); ++j)
            best = std::min(best, planarDistance(agents[i].position, agents[j].position));
    return best;
}

// The largest angle between any agent's heading and the group's mean heading.
float headingSpread(const std::vector<SteeringAgent>& agents)
{
    glm::vec3 mean(0.0f);
    for (const SteeringAgent& a : agents)
        mean += a.forward;
    float worst = 0.0f;
    for (const SteeringAgent& a : agents)
        worst = std::max(worst, angleBetween(a.forward, mean));
    return worst;
}

float groupRadius(const std::vector<SteeringAgent>& agents)
{
    glm::vec3 centre(0.0f);
    for (const SteeringAgent& a : agents)
        centre += a.position;
    centre /= float(agents.size());
    float sum = 0.0f;
    for (const SteeringAgent& a : agents)
        sum += planarDistance(a.position, centre);
    return sum / float(agents.size());
}

}  // namespace

class TestSteeringGroups : public QObject {
    Q_OBJECT
private slots:
    void separationKeepsPushedAgentsApart_data()
    {
        QTest::addColumn<std::vector<glm::vec3>>("starts");
        QTest::newRow("two, coincident") << std::vector<glm::vec3>{{0, 0, 0}, {0, 0, 0}};
        QTest::newRow("two, 10 cm apart") << std::vector<glm::vec3>{{0.05f, 0, 0}, {-0.05f, 0, 0}};
        QTest::newRow("three, coincident") << std::vector<glm::vec3>{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
        QTest::newRow("three, in a 20 cm cluster") << std::vector<glm::vec3>{{0.1f, 0, 0}, {-0.1f, 0, 0}, {0, 0, 0.1f}};
    }

    void separationKeepsPushedAgentsApart()
    {
        QFETCH(std::vector<glm::vec3>, starts);
        std::vector<SteeringAgent> agents;
        for (std::size_t i = 0; i < starts.size(); ++i)
            agents.push_back(walker(starts[i], glm::vec3(0.0f), std::uint32_t(10 + i)));
        // Every agent seeks the same point (a push together with the whole force budget); separation
        // must still hold the bodies apart.
        const glm::vec3 squeeze(0, 0, 0);
        float settledMin = 1e9f;
        for (int step = 0; step < 24 * 15; ++step) {
            std::vector<SteeringAgent> next = agents;
            for (std::size_t i = 0; i < agents.size(); ++i) {
                const std::vector<Neighbour> others = othersThan(agents, i);
                SteeringRequestList requests;
                requests.add(separate(agents[i], others));
                requests.add(seek(agents[i], squeeze));
                next[i] = advance(agents[i], blendWeighted(requests, agents[i].maxForce));
                QVERIFY(isFinite(next[i]));
            }
            agents = next;
            if (step >= 24 * 5)
                settledMin = std::min(settledMin, minPairDistance(agents));
        }
        // Contact is 0.6 m centre to centre. A pair settles where separation's push (maxForce at
        // contact) balances seek's full budget, i.e. at contact; allow 5 cm of overlap.
        QVERIFY2(settledMin > 0.55f, qPrintable(QString("pushed to %1 m apart").arg(settledMin)));
    }

    void coincidentAgentsPartDeterministically()
    {
        const SteeringAgent a = walker({1, 0, 1}, glm::vec3(0.0f), 4);
        const SteeringAgent b = walker({1, 0, 1}, glm::vec3(0.0f), 9);
        const Neighbour na = asNeighbour(a), nb = asNeighbour(b);
        const glm::vec3 fa = separate(a, std::span<const Neighbour>(&nb, 1));
        const glm::vec3 fb = separate(b, std::span<const Neighbour>(&na, 1));
        QVERIFY(glm::length(fa) > 0.0f);
        QVERIFY(angleBetween(fa, -fb) < 1e-5f);
        QCOMPARE(fa.y, 0.0f);
        QCOMPARE(separate(a, std::span<const Neighbour>(&nb, 1)), fa);
        // Nobody in range: nothing to say.
        const Neighbour far{{5, 0, 5}, {}, {0, 0, 1}, 0.3f, 2};
        QCOMPARE(separate(a, std::span<const Neighbour>(&far, 1)), glm::vec3(0.0f));
    }

    void alignmentConvergesHeadings()
    {
        std::vector<SteeringAgent> agents;
        const float headingsDeg[] = {0.0f, 40.0f, 80.0f, -30.0f, 120.0f};
        for (std::size_t i = 0; i < 5; ++i) {
            const float t = glm::radians(headingsDeg[i]);
            agents.push_back(walker({3.0f * float(i), 0, 0}, glm::vec3(std::sin(t), 0, std::cos(t)), std::uint32_t(i)));
        }
        const float before = headingSpread(agents);
        for (int step = 0; step < 24 * 6; ++step) {
            std::vector<SteeringAgent> next = agents;
            for (std::size_t i = 0; i < agents.size(); ++i)
                next[i] = advance(agents[i], align(agents[i], othersThan(agents, i)));
            agents = next;
        }
        const float after = headingSpread(agents);
        QVERIFY2(after < glm::radians(2.0f) && after < 0.05f * before,
                 qPrintable(QString("spread %1 deg -> %2 deg").arg(glm::degrees(before)).arg(glm::degrees(after))));
    }

    void cohesionShrinksASpreadGroup()
    {
        std::vector<SteeringAgent> agents;
        for (std::size_t i = 0; i < 6; ++i) {
            const float t = glm::radians(60.0f * float(i));
            agents.push_back(walker({8.0f * std::cos(t), 0, 8.0f * std::sin(t)}, glm::vec3(0.0f), std::uint32_t(i)));
        }
        const float before = groupRadius(agents);
        for (int step = 0; step < 24 * 10; ++step) {
            std::vector<SteeringAgent> next = agents;
            for (std::size_t i = 0; i < agents.size(); ++i) {
                const std::vector<Neighbour> others = othersThan(agents, i);
                SteeringRequestList requests;
                requests.add(separate(agents[i], others));
                requests.add(cohere(agents[i], others));
                next[i] = advance(agents[i], blendWeighted(requests, agents[i].maxForce));
            }
            agents = next;
        }
        const float after = groupRadius(agents);
        QVERIFY2(after < 0.25f * before, qPrintable(QString("radius %1 m -> %2 m").arg(before).arg(after)));
        QCOMPARE(cohere(agents[0], {}), glm::vec3(0.0f));
    }

    void followersKeepOutOfTheLeadersWay()
    {
        // The leader walks +z at 1 m/s; six followers start around it, two of them right in its path.
        SteeringAgent leader = walker({0, 0, 0}, {0, 0, 1.0f}, 100);
        std::vector<SteeringAgent> followers;
        const glm::vec3 starts[] = {{0, 0, 1.2f}, {0.1f, 0, 2.5f}, {-2, 0, 1}, {2, 0, -1}, {-1, 0, -3}, {3, 0, 4}};
        for (std::size_t i = 0; i < 6; ++i)
            followers.push_back(walker(starts[i], glm::vec3(0.0f), std::uint32_t(i)));
        const LeaderFollowParams params;
        int inCorridorAfterSettling = 0;
        for (int step = 0; step < 24 * 30; ++step) {
            const Neighbour lead = asNeighbour(leader);
            std::vector<SteeringAgent> next = followers;
            for (std::size_t i = 0; i < followers.size(); ++i) {
                SteeringRequestList requests;
                requests.add(separate(followers[i], othersThan(followers, i)));
                requests.add(followLeader(followers[i], lead, params));
                next[i] = advance(followers[i], allocateByPriority(requests, followers[i].maxForce));
            }
            followers = next;
            leader = advance(leader, glm::vec3(0.0f));
            if (step >= 24 * 8)
                for (const SteeringAgent& f : followers)
                    inCorridorAfterSettling += inLeaderCorridor(f, asNeighbour(leader), params);
        }
        QCOMPARE(inCorridorAfterSettling, 0);
        // And they do follow: all are behind the leader and near it.
        for (const SteeringAgent& f : followers) {
            QVERIFY(f.position.z < leader.position.z);
            QVERIFY(planarDistance(f.position, leader.position) < 5.0f);
        }
    }
};

THRONG_REGISTER_TEST(TestSteeringGroups)
#include "TestSteeringGroups.moc"
