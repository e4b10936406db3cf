// World::describeAgent as the editor's steering overlay uses it: describing agents
// changes nothing the run does, the published forces blend to the published steering,
// the neighbours are those the agent can perceive, the feelers reach as far as its speed
// says, the planned way of an A* walker leads round the wall to its goal, and the field a
// walker follows (a flow field to its goal, or painted flow strokes) is sampled about it
// as the walker would read it.
#include "CrowdChecks.h"
#include "TestRegistry.h"

#include "simcore/world/DebugSink.h"
#include "simcore/world/World.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <cmath>
#include <cstring>

using namespace throng::sim;
using throng::test::crowd::parse;

namespace {

// Walkers from the west to a goal behind a wall with a gap, round a post; an A* walker
// (id 1) plans round the wall's north end.
const char* kScene = R"(throng: 1
settings: {fps: 24, seed: 7, bounds: {min: [-30, -30], max: [30, 30]}}
agent_types:
  - {name: walker, radius: 0.3, max_speed: 1.4, max_force: 3, perception: 4, view_angle: 270}
  - {name: planner, radius: 0.3, max_speed: 1.4, max_force: 3, navigation: astar}
goals:
  - {name: east, position: [15, 0], radius: 1}
walls:
  - {points: [[5, -20], [5, -1.5]]}
  - {points: [[5, 1.5], [5, 20]]}
  - {points: [[-2, 6], [-2, 14]]}
obstacles:
  - {shape: circle, center: [0, 0], radius: 0.8}
agents:
  - {id: 1, type: planner, position: [-8, 0, 10], goal: east}
groups:
  - {name: crowd, type: walker, count: 60, rect: {min: [-12, -5], max: [-4, 5]}, goal: east}
)";

std::vector<AgentDebug> describeAll(const World& world, std::size_t every)
{
    DebugRecorder recorder;
    for (std::size_t i = 0; i < world.agentCount(); i += every)
        world.describeAgent(i, recorder);
    return std::move(recorder.agents());
}

// Flow-field walkers to a goal east of a wall with a gap at z in [-1.5, 1.5]; walker 1 stands
// just west of the wall, north of the gap, so some of the cells about it are the wall's.
const char* kFieldScene = R"(throng: 1
settings: {fps: 24, seed: 3, bounds: {min: [-20, -20], max: [20, 20]}, nav_cell: 0.5}
agent_types:
  - {name: walker, radius: 0.3, max_speed: 1.4, navigation: flow_field}
goals:
  - {name: east, position: [15, 0], radius: 1}
walls:
  - {points: [[5, -20], [5, -1.5]]}
  - {points: [[5, 1.5], [5, 20]]}
agents:
  - {id: 1, type: walker, position: [4.2, 0, 4], goal: east}
  - {id: 2, type: walker, position: [-10, 0, -6], goal: east}
)";

// Walkers drawn east along a painted stroke (z = 0, 3 m wide); walker 2 does not follow it.
const char* kStrokeScene = R"(throng: 1
settings: {fps: 24, seed: 3, bounds: {min: [-20, -20], max: [20, 20]}}
agent_types:
  - {name: follower, radius: 0.3, max_speed: 1.4, behaviours: {flow_field_following: 1, separation: 1}}
  - {name: walker, radius: 0.3, max_speed: 1.4}
goals:
  - {name: west, position: [-15, 10], radius: 1}
flow_strokes:
  - {points: [[-15, 0], [15, 0]], width: 3}
agents:
  - {id: 1, type: follower, position: [0, 0, 0]}
  - {id: 2, type: walker, position: [0, 0, 1], goal: west}
)";

std::size_t indexOf(const World& world, AgentId id)
{
    for (std::size_t i = 0; i < world.agentCount(); ++i)
        if (world.id(i) == id)
            return i;
    return world.agentCount();
}

glm::vec3 truncated(glm::vec3 v, float length)
{
    const float l = glm::length(v);
    return l > length ? v * (length / l) : v;
}

}  // namespace

class TestWorldDebug : public QObject {
    Q_OBJECT

private slots:
    void describingChangesNothing()
    {
        const Scene scene = parse(kScene);
        World watched(scene), plain(scene);
        std::vector<AgentFrame> a, b;
        std::size_t described = 0;
        for (int step = 0; step < 120; ++step) {
            described += describeAll(watched, 3).size();
            watched.step();
            plain.step();
            watched.snapshot(a);
            plain.snapshot(b);
            QCOMPARE(a.size(), b.size());
            QVERIFY2(std::memcmp(a.data(), b.data(), a.size() * sizeof(AgentFrame)) == 0,
                     qPrintable(QString("the runs part at step %1").arg(step)));
        }
        QCOMPARE(described, std::size_t(120 * ((watched.agentCount() + 2) / 3)));
    }

    void publishedForcesBlendToTheSteering()
    {
        const Scene scene = parse(kScene);
        World world(scene);
        for (int step = 0; step < 48; ++step)
            world.step();
        const float maxForce = 3.0f;
        std::size_t checked = 0, withSeveral = 0;
        for (const AgentDebug& a : describeAll(world, 1)) {
            glm::vec3 sum(0.0f);
            for (const AgentDebug::Force& f : a.forces)
                sum += f.force * f.weight;
            const glm::vec3 expected = truncated(sum, maxForce);
            QVERIFY2(glm::length(expected - a.steering) < 1e-4f,
                     qPrintable(QString("agent %1: forces blend to %2, steering published %3")
                                    .arg(a.id)
                                    .arg(double(glm::length(expected)))
                                    .arg(double(glm::length(a.steering)))));
            QVERIFY(glm::length(a.steering) > 0.0f || a.forces.empty());
            withSeveral += a.forces.size() >= 2 ? 1 : 0;
            ++checked;
        }
        QCOMPARE(checked, world.agentCount());
        QVERIFY2(withSeveral > checked / 2, "most walkers in a crowd by a wall feel more than one behaviour");
    }

    void neighboursAreWithinPerception()
    {
        const Scene scene = parse(kScene);
        World world(scene);
        for (int step = 0; step < 24; ++step)
            world.step();
        const std::span<const glm::vec3> pos = world.positions();
        std::size_t seen = 0;
        for (const AgentDebug& a : describeAll(world, 1)) {
            QVERIFY(a.neighbours.size() <= World::kMaxNeighbours);
            QCOMPARE(a.rangeM, 4.0f);
            for (const AgentDebug::Seen& n : a.neighbours) {
                QVERIFY(n.id != a.id);
                // Sensed at the last step, where it stands now: a step moves it < 0.1 m.
                QVERIFY2(glm::distance(n.position, a.position) <= a.rangeM + 0.2f,
                         qPrintable(QString("agent %1 sees %2 at %3 m").arg(a.id).arg(n.id).arg(
                             double(glm::distance(n.position, a.position)))));
                bool found = false;
                for (std::size_t j = 0; j < world.agentCount(); ++j)
                    found = found || (world.id(j) == n.id && pos[j] == n.position);
                QVERIFY(found);
            }
            // Independent recount: someone within a metre straight ahead is seen.
            for (std::size_t j = 0; j < world.agentCount(); ++j) {
                const glm::vec3 d = pos[j] - a.position;
                const float ahead = glm::dot(d, a.forward);
                if (world.id(j) != a.id && glm::length(d) < 1.0f && ahead > 0.7f * glm::length(d)) {
                    bool sees = false;
                    for (const AgentDebug::Seen& n : a.neighbours)
                        sees = sees || n.id == world.id(j);
                    // Unless eight others are nearer.
                    QVERIFY2(sees || a.neighbours.size() == World::kMaxNeighbours,
                             qPrintable(QString("agent %1 misses %2 just ahead").arg(a.id).arg(world.id(j))));
                }
            }
            seen += a.neighbours.size();
        }
        QVERIFY2(seen > world.agentCount(), "walkers in a crowd see others");
    }

    void feelersReachAsFarAsTheSpeedSays()
    {
        const Scene scene = parse(kScene);
        World world(scene);
        for (int step = 0; step < 48; ++step)
            world.step();
        const AgentDebug a = describeAll(world, 1).back();
        QCOMPARE(a.feelers.size(), std::size_t(6));  // walls and obstacles: three each
        const float speed = glm::length(a.velocity);
        QVERIFY(speed > 0.5f);
        // Walls: 0.5 m standing plus 1 s of walking (WallAvoidanceParams' defaults).
        const float wallFeeler = glm::distance(a.feelers[0].from, a.feelers[0].to);
        QVERIFY2(std::abs(wallFeeler - (0.5f + speed)) < 1e-3f, qPrintable(QString::number(double(wallFeeler))));
        const glm::vec3 ahead = glm::normalize(a.feelers[0].to - a.feelers[0].from);
        const glm::vec3 forward = glm::normalize(glm::vec3(a.forward.x, 0.0f, a.forward.z));
        QVERIFY(glm::dot(ahead, forward) > 0.999f);
        // The side feelers are half as long.
        QVERIFY(std::abs(glm::distance(a.feelers[1].from, a.feelers[1].to) - 0.5f * wallFeeler) < 1e-3f);
    }

    void plannedWayLeadsRoundTheWallToTheGoal()
    {
        const Scene scene = parse(kScene);
        World world(scene);
        world.step();
        DebugRecorder recorder;
        std::size_t planner = world.agentCount();
        for (std::size_t i = 0; i < world.agentCount(); ++i)
            if (world.id(i) == 1)
                planner = i;
        QVERIFY(planner < world.agentCount());
        world.describeAgent(planner, recorder);
        const AgentDebug& a = recorder.agents().front();
        QVERIFY2(a.path.size() >= 3, "a plan round the wall has corners");
        QCOMPARE(a.path.front(), a.position);
        QVERIFY(glm::distance(glm::vec2(a.path.back().x, a.path.back().z), glm::vec2(15.0f, 0.0f)) < 1.0f);
        // The way passes the wall at x = -2 (z from 6 to 14) at its end, not through it.
        for (std::size_t k = 1; k < a.path.size(); ++k) {
            const glm::vec3 p = a.path[k - 1], q = a.path[k];
            if ((p.x + 2.0f) * (q.x + 2.0f) < 0.0f) {
                const float z = p.z + (q.z - p.z) * (-2.0f - p.x) / (q.x - p.x);
                QVERIFY2(z < 6.0f || z > 14.0f, qPrintable(QString("crosses the wall at z = %1").arg(double(z))));
            }
        }
        QVERIFY(a.hasTarget);
        QVERIFY(glm::distance(a.target, a.position) > 0.1f);
    }

    // A flow-field walker's field: a square of 5 x 5 samples one navigation cell apart,
    // centred on it; each a unit direction or zero; zero on the wall's cells; and where
    // it points, the walker's way to the goal gets shorter (through the gap, not into
    // the wall: north of the gap the field leads south).
    void flowFieldIsSampledAboutTheWalker()
    {
        const Scene scene = parse(kFieldScene);
        World world(scene);
        world.step();
        const std::size_t i = indexOf(world, 1);
        QVERIFY(i < world.agentCount());
        DebugRecorder recorder;
        world.describeAgent(i, recorder);
        const AgentDebug& a = recorder.agents().front();
        QCOMPARE(int(a.field.size()), kFieldSamples * kFieldSamples);
        const AgentDebug::FieldSample& centre = a.field[a.field.size() / 2];
        QVERIFY(glm::distance(centre.at, a.position) < 1e-4f);
        QVERIFY(std::abs(a.field[1].at.x - a.field[0].at.x - 0.5f) < 1e-4f);  // one cell apart
        int onWall = 0, leading = 0;
        for (const AgentDebug::FieldSample& f : a.field) {
            const float length = glm::length(f.direction);
            QVERIFY2(length == 0.0f || std::abs(length - 1.0f) < 1e-3f, "a unit direction or none");
            QCOMPARE(f.direction.y, 0.0f);
            if (std::abs(f.at.x - 5.0f) < 0.45f) {
                // The wall's cells: the wall and a body's radius (0.3 m) and 0.15 m about it.
                onWall += 1;
                QVERIFY2(length == 0.0f, qPrintable(QString("a direction on the wall at z = %1").arg(double(f.at.z))));
            } else if (f.at.x < 4.5f) {
                // West of the wall and north of the gap: the way goes south to the gap.
                QVERIFY2(f.direction.z < -0.3f, qPrintable(QString("at (%1, %2) the field leads (%3, %4)")
                                                               .arg(double(f.at.x))
                                                               .arg(double(f.at.z))
                                                               .arg(double(f.direction.x))
                                                               .arg(double(f.direction.z))));
                leading += 1;
            }
        }
        QVERIFY(onWall >= 5);
        QVERIFY(leading >= 10);
    }

    // A stroke follower's field: the stroke's direction (+x) all about it; a walker that
    // follows no field publishes none.
    void strokesAreSampledAboutAFollower()
    {
        const Scene scene = parse(kStrokeScene);
        World world(scene);
        world.step();
        DebugRecorder recorder;
        world.describeAgent(indexOf(world, 1), recorder);
        world.describeAgent(indexOf(world, 2), recorder);
        const AgentDebug& follower = recorder.agents()[0];
        QCOMPARE(int(follower.field.size()), kFieldSamples * kFieldSamples);
        QVERIFY(std::abs(follower.field[1].at.x - follower.field[0].at.x - kFlowSampleStepM) < 1e-4f);
        // The strokes' field is solved over the whole set (WorldNav.cpp), so every sample
        // within 2 m of a straight stroke leads along it.
        for (const AgentDebug::FieldSample& f : follower.field)
            QVERIFY2(glm::distance(f.direction, glm::vec3(1.0f, 0.0f, 0.0f)) < 0.05f,
                     qPrintable(QString("at (%1, %2) the field leads (%3, %4)")
                                    .arg(double(f.at.x))
                                    .arg(double(f.at.z))
                                    .arg(double(f.direction.x))
                                    .arg(double(f.direction.z))));
        QVERIFY(recorder.agents()[1].field.empty());
    }
};

THRONG_REGISTER_TEST(TestWorldDebug)
#include "TestWorldDebug.moc"
