// Edits of the road network resume from the edit frame (issue 6): a lane added, removed
// or moved, a vehicle added or removed, a crosswalk added, a light moved. The traffic
// system is the edited scene's; kept vehicles carry their lane state over by id (exactly
// on an unchanged lane, re-projected onto a moved one), new ones start from their scene
// state, removed ones (and those on a removed lane) are gone; no vehicle collides or runs
// a red light in the 600 frames after; the resumed run is the same on 1 and 2 threads and
// the same again from its own checkpoint.
#include "ResumeChecks.h"
#include "StateScenes.h"
#include "TestRegistry.h"

#include "simcore/world/WorldState.h"

#include <glm/geometric.hpp>

#include <QTest>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

using namespace throng::sim;
using namespace throng::test::state;

namespace {

constexpr std::size_t kEditStep = 48;

enum Edit { kLaneAdded, kLaneRemoved, kLaneMoved, kVehicleAdded, kVehicleRemoved, kCrosswalkAdded, kLightMoved };

std::uint32_t nextId(const Scene& scene)
{
    std::uint32_t id = 1;
    for (const Agent& a : scene.agents) id = std::max(id, a.id + 1);
    for (const Vehicle& v : scene.vehicles) id = std::max(id, v.id + 1);
    for (const Hero& h : scene.heroes) id = std::max(id, h.id + 1);
    return id;
}

// Where a standing car fits on `lane` now, away from the junction (which a car standing
// in would block for the crossing lanes): the point of s in [5, 25] m farthest from every
// vehicle on the lane.
float freeSpot(const TrafficSystem& ts, int lane)
{
    const float length = ts.lanes().length(lane);
    float best = -1.0f, spot = 5.0f;
    for (float at = 5.0f; at <= 25.0f; at += 0.5f) {
        float nearest = 1e9f;
        for (std::size_t i = 0; i < ts.vehicleCount(); ++i)
            if (ts.lane(i) == lane) {
                const float d = std::abs(ts.s(i) - at);
                nearest = std::min({nearest, d, length - d});
            }
        if (nearest > best) {
            best = nearest;
            spot = at;
        }
    }
    return spot;
}

Scene edited(const Scene& scene, Edit edit, const TrafficSystem& atEdit)
{
    Scene e = scene;
    switch (edit) {
    case kLaneAdded:  // a ring road in the north-east block, behind the buildings' walls, with a car on it
        e.lanes.push_back({"ring", {{20.0f, -40.0f}, {40.0f, -40.0f}, {40.0f, -20.0f}, {20.0f, -20.0f}}, 3.5f, 10.0f, true});
        e.vehicles.push_back({nextId(scene), "car", "ring", 12.0f, 3.0f});
        break;
    case kLaneRemoved:  // the scene still names it for its four cars: they go with it
        e.lanes.erase(std::find_if(e.lanes.begin(), e.lanes.end(), [](const Lane& l) { return l.name == "southbound"; }));
        for (TrafficLight& l : e.trafficLights)
            std::erase_if(l.stopLines, [](const StopLine& s) { return s.lane == "southbound"; });
        break;
    case kLaneMoved:  // eastbound starts 10 m further west; its stop line stays where it stood
        e.lanes[0].points.front().x -= 10.0f;
        for (TrafficLight& l : e.trafficLights)
            for (StopLine& s : l.stopLines)
                if (s.lane == "eastbound")
                    s.atM += 10.0f;
        break;
    case kVehicleAdded:
        e.vehicles.push_back({nextId(scene), "car", "westbound", freeSpot(atEdit, 1), 0.0f});
        break;
    case kVehicleRemoved:
        e.vehicles.erase(e.vehicles.begin() + 2);
        break;
    case kCrosswalkAdded:  // an uncontrolled one over eastbound and westbound, west of the junction
        e.crosswalks.push_back({"cw_far_west", {-30.0f, -5.0f}, {-30.0f, 5.0f}, 3.0f});
        break;
    case kLightMoved:
        e.trafficLights[0].position += glm::vec2(1.0f, 0.5f);
        break;
    }
    return e;
}

}  // namespace

class TestWorldStateTraffic : public QObject {
    Q_OBJECT

private slots:
    void networkEditsResume_data()
    {
        QTest::addColumn<int>("edit");
        QTest::newRow("lane added") << int(kLaneAdded);
        QTest::newRow("lane removed") << int(kLaneRemoved);
        QTest::newRow("lane moved") << int(kLaneMoved);
        QTest::newRow("vehicle added") << int(kVehicleAdded);
        QTest::newRow("vehicle removed") << int(kVehicleRemoved);
        QTest::newRow("crosswalk added") << int(kCrosswalkAdded);
        QTest::newRow("light moved") << int(kLightMoved);
    }

    void networkEditsResume()
    {
        QFETCH(int, edit);
        const Scene scene = crossroads();
        WorldOptions one;  // 600 frames a row: one thread (the thread counts are compared below)
        one.threads = 1;
        World straight(scene, one);
        for (std::size_t s = 0; s < kEditStep; ++s)
            straight.step();
        const WorldState state = straight.saveState();
        const TrafficSystem& old = *straight.trafficSystem();
        const Scene after = edited(scene, Edit(edit), old);
        QVERIFY(!sameTrafficSet(scene, after));

        World resumed(after, one);
        QVERIFY(resumed.adoptState(state, scene, after));
        QCOMPARE(resumed.stepIndex(), std::uint64_t(kEditStep));
        const TrafficSystem& now = *resumed.trafficSystem();
        QCOMPARE(now.stepIndex(), std::uint64_t(kEditStep));  // the signals keep their clock
        QCOMPARE(now.counters().vehicleSteps, old.counters().vehicleSteps);

        std::map<std::uint32_t, std::size_t> oldIndex;
        for (std::size_t k = 0; k < old.vehicleCount(); ++k)
            oldIndex[old.id(k)] = k;
        std::set<std::uint32_t> sceneIds;
        for (const Vehicle& v : after.vehicles)
            if (now.lanes().findLane(v.lane) >= 0)
                sceneIds.insert(v.id);
        QCOMPARE(now.vehicleCount(), sceneIds.size());
        std::size_t kept = 0, reprojected = 0;
        for (std::size_t i = 0; i < now.vehicleCount(); ++i) {
            const auto it = oldIndex.find(now.id(i));
            if (it == oldIndex.end()) {  // new: its scene state
                const Vehicle& v = after.vehicles.back();
                QCOMPARE(now.id(i), v.id);
                QCOMPARE(now.s(i), v.atM);
                QCOMPARE(now.speed(i), v.speed);
                continue;
            }
            const std::size_t k = it->second;
            ++kept;
            QCOMPARE(now.speed(i), old.speed(k));
            QCOMPARE(now.active(i), old.active(k));
            QCOMPARE(now.respawns(i), old.respawns(k));
            if (edit == kLaneMoved && now.lanes().laneName(now.lane(i)) == "eastbound") {
                // Re-projected: the nearest point of the longer lane, where it stood.
                QVERIFY(std::abs(now.s(i) - old.s(k) - 10.0f) < 1e-3f);
                QVERIFY(glm::distance(now.position(i), old.position(k)) < 1e-3f);
                ++reprojected;
            } else {
                QCOMPARE(now.s(i), old.s(k));
                QCOMPARE(now.position(i), old.position(k));
            }
        }
        const std::size_t expectedKept = edit == kLaneRemoved || edit == kVehicleRemoved ? old.vehicleCount() - (edit == kLaneRemoved ? 4 : 1)
                                                                                         : old.vehicleCount();
        QCOMPARE(kept, expectedKept);
        QCOMPARE(reprojected, edit == kLaneMoved ? std::size_t(4) : std::size_t(0));
        // The World's vehicle agents stand where the traffic puts them; removed ones are gone.
        for (std::size_t v = 0; v < now.vehicleCount(); ++v) {
            const std::size_t i = resumed.traffic().vehicleAgent[v];
            QCOMPARE(resumed.id(i), now.id(v));
            QCOMPARE(glm::vec2(resumed.positions()[i].x, resumed.positions()[i].z), now.position(v));
        }
        QCOMPARE(resumed.agentCount(), state.agents.size() - old.vehicleCount() + now.vehicleCount());

        // 600 frames on: no vehicle collision and no red light run, by the run's counters.
        const TrafficCounters at = now.counters();
        for (int s = 0; s < 600; ++s)
            resumed.step();
        QCOMPARE(now.counters().vehicleCollisions, at.vehicleCollisions);
        QCOMPARE(now.counters().vehicleRedLightViolations, at.vehicleRedLightViolations);
        QCOMPARE(now.counters().nonFiniteValues, std::uint64_t(0));
        QCOMPARE(at.vehicleCollisions, std::uint64_t(0));
        QCOMPARE(at.vehicleRedLightViolations, std::uint64_t(0));
        QVERIFY(now.counters().vehicleSteps > at.vehicleSteps + 600 * (now.vehicleCount() - 1));
        // And every vehicle, the added one too, still stands where the traffic drove it:
        // driven, never steered or pushed by the walkers.
        for (std::size_t v = 0; v < now.vehicleCount(); ++v) {
            const std::size_t i = resumed.traffic().vehicleAgent[v];
            const glm::vec2 at(resumed.positions()[i].x, resumed.positions()[i].z);
            QVERIFY2(glm::distance(at, now.position(v)) < 1e-3f,
                     qPrintable(QString("vehicle %1 stands %2 m from its lane state")
                                    .arg(now.id(v)).arg(glm::distance(at, now.position(v)))));
        }
    }

    void networkEditsAreTheSameOnOneAndTwoThreads()
    {
        const Scene scene = crossroads();
        for (Edit edit : {kLaneMoved, kVehicleAdded, kLaneRemoved}) {
            checkResumeIsDeterministic(
                scene, [&](const World& a) { return edited(scene, edit, *a.trafficSystem()); }, 24);
            if (QTest::currentTestFailed())
                return;
        }
    }
};

THRONG_REGISTER_TEST(TestWorldStateTraffic)
#include "TestWorldStateTraffic.moc"
