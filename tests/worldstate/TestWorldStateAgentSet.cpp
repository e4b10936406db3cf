// Edits that add or remove agents, change an agent's type or retime a light resume from
// the edit frame (issue 6): agents are matched by key, kept ones carry their state over
// exactly, new ones start from their scene state, removed ones are gone; the resumed run
// is the same on 1 and 2 threads and the same again from its own checkpoint.
#include "ResumeChecks.h"
#include "StateScenes.h"
#include "TestRegistry.h"

#include "simcore/hero/HeroTrack.h"
#include "simcore/traffic/LightPhase.h"
#include "simcore/world/WorldState.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <algorithm>
#include <set>

using namespace throng::sim;
using namespace throng::test::state;

namespace {

constexpr std::size_t kEditStep = 48;

// Placed agents as the crowd brush adds them: ids after every id the scene uses (which
// moves the ids of every group member), on the north-east sidewalk, walking ne_back.
Scene withPainted(const Scene& scene, std::size_t count)
{
    Scene edited = scene;
    std::uint32_t id = 1;
    for (const Agent& a : scene.agents) id = std::max(id, a.id + 1);
    for (const Vehicle& v : scene.vehicles) id = std::max(id, v.id + 1);
    for (const Hero& h : scene.heroes) id = std::max(id, h.id + 1);
    for (std::size_t k = 0; k < count; ++k) {
        Agent a;
        a.id = id++;
        a.type = "pedestrian";
        a.position = {36.0f + 1.2f * float(k % 4), 0.0f, -7.9f + 0.6f * float(k / 4)};
        a.path = "ne_back";
        edited.agents.push_back(a);
    }
    return edited;
}

float nearestDistance(glm::vec3 p, const std::vector<Agent>& agents)
{
    float best = 1e9f;
    for (const Agent& a : agents)
        best = std::min(best, glm::distance(glm::vec2(p.x, p.z), glm::vec2(a.position.x, a.position.z)));
    return best;
}

}  // namespace

class TestWorldStateAgentSet : public QObject {
    Q_OBJECT

private slots:
    void paintedAgentsJoinAtTheEditFrame()
    {
        const Scene scene = crossroadsWithBrains();
        World straight(scene);
        for (std::size_t s = 0; s < kEditStep; ++s)
            straight.step();
        const WorldState state = straight.saveState();
        const FrameCache reference = record(straight, 24);

        const Scene edited = withPainted(scene, 6);
        World resumed(edited);
        std::vector<std::int32_t> previous;
        QVERIFY(resumed.adoptState(state, scene, edited, &previous));
        QCOMPARE(resumed.stepIndex(), std::uint64_t(kEditStep));
        QCOMPARE(resumed.agentCount(), state.agents.size() + 6);
        // Placed agents come first in a World: the six new ones, then everyone kept, once.
        std::set<std::int32_t> kept;
        for (std::size_t i = 0; i < previous.size(); ++i) {
            QCOMPARE(previous[i] < 0, i < 6);
            if (previous[i] >= 0)
                kept.insert(previous[i]);
        }
        QCOMPARE(kept.size(), state.agents.size());
        const FrameCache after = record(resumed, 24);
        std::size_t far = 0, farSame = 0;
        for (std::size_t i = 6; i < after.agentCount(); ++i) {
            const std::size_t was = std::size_t(previous[i]);
            // The kept agent's state at the edit frame, exactly, and its id.
            QCOMPARE(after.at(0, i).position, reference.at(0, was).position);
            QCOMPARE(after.at(0, i).headingRad, reference.at(0, was).headingRad);
            QCOMPARE(after.agents()[i].id, state.agents[was].id);
            if (nearestDistance(reference.at(0, was).position, edited.agents) > 12.0f) {
                ++far;
                farSame += glm::distance(after.at(4, i).position, reference.at(4, was).position) < 1e-3f ? 1 : 0;
            }
        }
        QVERIFY(far > 200);
        QVERIFY2(farSame * 20 >= far * 19, qPrintable(QString("%1 of %2 far agents kept their way").arg(farSame).arg(far)));
        // New agents start where they were painted and walk on.
        for (std::size_t i = 0; i < 6; ++i) {
            QCOMPARE(after.at(0, i).position.x, edited.agents[i].position.x);
            QCOMPARE(after.at(0, i).position.z, edited.agents[i].position.z);
            QVERIFY(glm::distance(after.at(24, i).position, after.at(0, i).position) > 0.5f);
        }

        // Bit-identical on 1 and 2 threads, and again from the resumed run's own checkpoint.
        checkResumeIsDeterministic(scene, [&](const World&) { return edited; }, 12);
    }

    void aHeroAddedMidRunWalksItsKeyframes()
    {
        // A hero drawn at the edit frame goes where its keyframes say from there on (its
        // keyframes count from the start of the shot, like every hero's).
        const Scene scene = crossroads();
        World straight(scene);
        for (std::size_t s = 0; s < kEditStep; ++s)
            straight.step();
        Scene edited = scene;
        Hero hero;
        hero.name = "late";
        hero.type = "hero";
        hero.id = 1;
        for (const Agent& a : scene.agents) hero.id = std::max(hero.id, a.id + 1);
        for (const Vehicle& v : scene.vehicles) hero.id = std::max(hero.id, v.id + 1);
        for (const Hero& h : scene.heroes) hero.id = std::max(hero.id, h.id + 1);
        hero.keyframes = {{0.0f, {-40, 0, -30}}, {8.0f, {-30, 0, -30}}, {16.0f, {-30, 0, -20}}};
        edited.heroes.push_back(hero);
        World resumed(edited);
        QVERIFY(resumed.adoptState(straight.saveState(), scene, edited));
        const FrameCache after = record(resumed, 24);
        std::size_t index = after.agentCount();
        for (std::size_t i = 0; i < after.agentCount(); ++i)
            if (after.agents()[i].id == hero.id)
                index = i;
        QVERIFY(index < after.agentCount());
        const HeroTrack track(hero);
        const double dt = 1.0 / double(after.fps());
        for (std::size_t f = 0; f <= 24; ++f) {
            const glm::vec3 at = after.at(f, index).position, want = track.positionAt(double(kEditStep + f) * dt);
            QVERIFY2(glm::distance(glm::vec2(at.x, at.z), glm::vec2(want.x, want.z)) < 1e-3f,
                     qPrintable(QString("frame %1 after the edit: (%2, %3), its way (%4, %5)")
                                    .arg(f).arg(at.x).arg(at.z).arg(want.x).arg(want.z)));
        }
    }

    void erasedAgentsAreGoneAndTheOthersCarryOn()
    {
        const Scene painted = withPainted(crossroads(), 8);
        World straight(painted);
        for (std::size_t s = 0; s < kEditStep; ++s)
            straight.step();
        const WorldState state = straight.saveState();
        const FrameCache reference = record(straight, 2);

        Scene erased = painted;
        erased.agents.erase(erased.agents.begin() + 2, erased.agents.begin() + 5);  // three of them
        World resumed(erased);
        std::vector<std::int32_t> previous;
        QVERIFY(resumed.adoptState(state, painted, erased, &previous));
        QCOMPARE(resumed.agentCount(), state.agents.size() - 3);
        std::set<AgentId> ids;
        for (std::size_t i = 0; i < resumed.agentCount(); ++i) {
            QVERIFY(previous[i] >= 0);
            QVERIFY(previous[i] < 2 || previous[i] >= 5);
            QCOMPARE(resumed.positions()[i], reference.at(0, std::size_t(previous[i])).position);
            ids.insert(resumed.id(i));
        }
        for (std::size_t k = 2; k < 5; ++k)
            QVERIFY(!ids.count(painted.agents[k].id));
        QCOMPARE(ids.size(), resumed.agentCount());
    }

    void aTypeChangeKeepsTheStateAndTakesTheNewType()
    {
        const Scene painted = withPainted(crossroads(), 4);
        World straight(painted);
        for (std::size_t s = 0; s < kEditStep; ++s)
            straight.step();
        const WorldState state = straight.saveState();
        Scene assigned = painted;
        assigned.agents[1].type = "errand";
        World resumed(assigned);
        std::vector<std::int32_t> previous;
        QVERIFY(resumed.adoptState(state, painted, assigned, &previous));
        for (std::size_t i = 0; i < previous.size(); ++i)
            QCOMPARE(previous[i], std::int32_t(i));
        const std::uint16_t errand = std::uint16_t(std::find_if(assigned.agentTypes.begin(), assigned.agentTypes.end(),
                                                                [](const AgentType& t) { return t.name == "errand"; }) -
                                                   assigned.agentTypes.begin());
        QCOMPARE(resumed.agentInfo()[1].typeIndex, errand);
        QVERIFY(state.agents[1].typeIndex != errand);
        QCOMPARE(resumed.positions()[1], state.pos[1]);
        QCOMPARE(resumed.velocities()[1], state.vel[1]);
        QCOMPARE(resumed.radii()[1], assigned.agentTypes[errand].radiusM);
    }

    void aLightsTimingChangeKeepsItsClock()
    {
        const Scene scene = crossroads();
        World straight(scene);
        for (std::size_t s = 0; s < kEditStep; ++s)
            straight.step();
        const WorldState state = straight.saveState();
        const FrameCache reference = record(straight, 0);
        Scene retimed = scene;
        retimed.trafficLights[0].greenS += 7.0f;
        retimed.trafficLights[0].offsetS += 20.0f;
        World resumed(retimed);
        QVERIFY(resumed.adoptState(state, scene, retimed));
        QCOMPARE(resumed.stepIndex(), std::uint64_t(kEditStep));
        QCOMPARE(record(resumed, 0).hash(), reference.hash());  // vehicles and walkers as they were
        // From there the lights run the edited timing on the same clock, for the walkers
        // and for the vehicles.
        std::size_t differs = 0;
        for (int s = 0; s < 360; ++s) {
            resumed.step();
            const double t = resumed.timeS();
            const int expected = int(lightPhaseAt(retimed.trafficLights[0], t));
            QCOMPARE(resumed.lightState(0), expected);
            QCOMPARE(int(resumed.trafficSystem()->lightPhase(0)), expected);
            differs += lightPhaseAt(scene.trafficLights[0], t) != lightPhaseAt(retimed.trafficLights[0], t) ? 1 : 0;
        }
        QVERIFY(differs > 24);
    }

    void settingsEditsStillStartOver()
    {
        // The frames before would be of another run: fps, seed and bounds start over.
        // (Lanes, vehicles and crosswalks resume: TestWorldStateTraffic.)
        const Scene scene = crossroads();
        const WorldState state = World(scene).saveState();
        Scene seeded = scene;
        seeded.settings.seed += 1;
        QVERIFY(!World(seeded).adoptState(state, scene, seeded));
        Scene faster = scene;
        faster.settings.fps = 30;
        QVERIFY(!World(faster).adoptState(state, scene, faster));
        Scene wider = scene;
        wider.settings.boundsMax.x += 10.0f;
        QVERIFY(!World(wider).adoptState(state, scene, wider));
        Scene lane = scene;
        lane.lanes[0].speedLimit += 1.0f;
        QVERIFY(World(lane).adoptState(state, scene, lane));
    }
};

THRONG_REGISTER_TEST(TestWorldStateAgentSet)
#include "TestWorldStateAgentSet.moc"
