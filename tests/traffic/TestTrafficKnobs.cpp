// The crossroads' knobs as scene keys (issue 26): the car-following model per lane, per
// vehicle type and for the scene, the drivers' and walkers' start delays, the crossing
// margin, the clearance round walkers, the waiting speed and the yield horizon. Each key
// is read, written back, refused with its line when wrong, and changes what it says.
#include "TestRegistry.h"

#include "simcore/io/SceneIO.h"
#include "simcore/traffic/TrafficSystem.h"
#include "simcore/world/World.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

using namespace throng::sim;

namespace knobs_test {

Scene parseKnobs(const std::string& yaml)
{
    const LoadResult r = parseScene(yaml, "knobs.yaml", "");
    if (!r.ok()) {
        std::string all;
        for (const Diagnostic& d : r.diagnostics)
            all += d.format() + "\n";
        qFatal("%s", all.c_str());
    }
    return r.scene;
}

// The first error's text, else the first warning's (an unknown key), or "" when none.
std::string firstProblem(const std::string& yaml)
{
    const LoadResult r = parseScene(yaml, "knobs.yaml", "");
    for (const Diagnostic& d : r.diagnostics)
        if (d.severity == Severity::Error)
            return d.format();
    return r.diagnostics.empty() ? std::string() : r.diagnostics.front().format();
}

// Four straight looped lanes 30 m apart, 400 m long, each with a follower doing 12 m/s
// 30 m behind a standing leader: how each brakes is its car-following model's.
// `keys` adds a traffic section, `laneModel[k]` a lane's car_following, `busModel` the
// bus type's.
std::string fourLanes(const std::string& traffic, const char* const laneModel[4], const std::string& busModel)
{
    std::string yaml = "throng: 1\nsettings: {fps: 24, seed: 5, bounds: {min: [-250, -100], max: [250, 100]}}\n";
    yaml += traffic;
    yaml += "agent_types:\n"
            "  - {name: car, kind: vehicle, radius: 2, max_speed: 13.9}\n"
            "  - {name: bus, kind: vehicle, radius: 3, max_speed: 13.9" +
            (busModel.empty() ? std::string() : ", car_following: " + busModel) + "}\n";
    yaml += "lanes:\n";
    for (int k = 0; k < 4; ++k)
        yaml += "  - {name: l" + std::to_string(k) + ", loop: true, points: [[-200, " + std::to_string(30 * k) +
                "], [200, " + std::to_string(30 * k) + "]]" +
                (laneModel[k] ? std::string(", car_following: ") + laneModel[k] : std::string()) + "}\n";
    yaml += "vehicles:\n";
    for (int k = 0; k < 4; ++k) {
        const char* type = k % 2 ? "bus" : "car";
        yaml += "  - {id: " + std::to_string(10 + k) + ", type: " + type + ", lane: l" + std::to_string(k) +
                ", at: 10, speed: 12}\n";
        yaml += "  - {id: " + std::to_string(20 + k) + ", type: " + type + ", lane: l" + std::to_string(k) +
                ", at: 45}\n";
    }
    return yaml;
}

// Vehicle `index`'s speed over 4 s of `scene` on its own, its models overridden by
// `forced` for every type when given.
std::vector<float> speeds(const Scene& scene, std::size_t index, const FollowingModel* forced = nullptr)
{
    TrafficOptions options;
    if (forced)
        for (const char* type : {"car", "bus"}) {
            FollowingParams p;
            p.model = *forced;
            p.desiredSpeed = 13.9f;
            options.modelByType.push_back({type, p});
        }
    TrafficSystem t(scene, options);
    std::vector<float> out;
    for (int k = 0; k < 96; ++k) {
        t.step({});
        out.push_back(t.speed(index));
    }
    return out;
}

std::size_t vehicleIndex(const TrafficSystem& t, std::uint32_t id)
{
    for (std::size_t i = 0; i < t.vehicleCount(); ++i)
        if (t.id(i) == id)
            return i;
    qFatal("no vehicle %u", id);
    return 0;
}

// A road north-south (carriageway |x| <= 3.5), a crosswalk over it at z = 0 whose light
// is red for the first 10 s and then green, and 10 walkers west of it going east.
std::string kerbScene(const std::string& traffic)
{
    return "throng: 1\n"
           "settings: {fps: 24, seed: 3, bounds: {min: [-30, -60], max: [30, 60]}}\n" +
           traffic +
           "agent_types:\n"
           "  - {name: walker, radius: 0.25}\n"
           "lanes:\n"
           "  - {name: north, points: [[1.75, 50], [1.75, -50]], width: 3.5}\n"
           "  - {name: south, points: [[-1.75, -50], [-1.75, 50]], width: 3.5}\n"
           "crosswalks:\n"
           "  - {name: mid, from: [-7, 0], to: [7, 0], width: 5}\n"
           "traffic_lights:\n"
           "  - {name: walk, green: 20, yellow: 3, red: 10, offset: 23, position: [-4, 3],"
           " stop_lines: [{crosswalk: mid}]}\n"
           "goals:\n"
           "  - {name: east, position: [16, 0], radius: 2}\n"
           "groups:\n"
           "  - {name: crowd, type: walker, count: 10, rect: {min: [-12, -2], max: [-8, 2]}, goal: east}\n";
}

// Per walker, the time it first stands on the road (centre past the west kerb).
std::vector<double> stepOffTimes(const Scene& scene)
{
    World world(scene);
    std::vector<double> at(world.agentCount(), -1.0);
    for (int k = 0; k < 24 * 20; ++k) {
        world.step();
        for (std::size_t i = 0; i < world.agentCount(); ++i)
            if (at[i] < 0.0 && world.positions()[i].x > -3.5f)
                at[i] = world.timeS();
    }
    return at;
}

}  // namespace knobs_test

using namespace knobs_test;

class TestTrafficKnobs : public QObject {
    Q_OBJECT
private slots:
    void keysAreReadAndWritten()
    {
        const char* lanes[4] = {nullptr, "idm", "fuzzy", "inherit"};
        const Scene s = parseKnobs(fourLanes("traffic:\n"
                                             "  car_following: gap_time\n"
                                             "  driver_start_delay: [0.5, 0.75]\n"
                                             "  walker_start_delay: [1, 4]\n"
                                             "  crossing_margin: 1.5\n"
                                             "  walker_clearance: 0.8\n"
                                             "  waiting_speed: 0.2\n"
                                             "  yield_horizon: 5\n",
                                             lanes, "fuzzy"));
        QVERIFY(s.traffic.carFollowing == CarFollowing::GapTime);
        QCOMPARE(s.traffic.driverStartDelayS, glm::vec2(0.5f, 0.75f));
        QCOMPARE(s.traffic.walkerStartDelayS, glm::vec2(1.0f, 4.0f));
        QCOMPARE(s.traffic.crossingMarginM, 1.5f);
        QCOMPARE(s.traffic.walkerClearanceM, 0.8f);
        QCOMPARE(s.traffic.waitingSpeed, 0.2f);
        QCOMPARE(s.traffic.yieldHorizonS, 5.0f);
        QVERIFY(s.lanes[0].carFollowing == CarFollowing::Inherit);
        QVERIFY(s.lanes[1].carFollowing == CarFollowing::Idm);
        QVERIFY(s.lanes[2].carFollowing == CarFollowing::Fuzzy);
        QVERIFY(s.agentTypes[0].carFollowing == CarFollowing::Inherit);
        QVERIFY(s.agentTypes[1].carFollowing == CarFollowing::Fuzzy);
        // Written and read back the same; a scene that sets none writes no traffic section.
        const std::string text = sceneToYaml(s);
        QVERIFY(text.find("yield_horizon: 5") != std::string::npos);
        QVERIFY(parseKnobs(text) == s);
        const Scene plain = parseKnobs(fourLanes("", lanes, ""));
        QVERIFY(plain.traffic == TrafficSettings{});
        QVERIFY(sceneToYaml(plain).find("traffic:") == std::string::npos);
        QVERIFY(parseKnobs(sceneToYaml(plain)) == plain);
    }

    void wrongValuesAreRefusedWithTheirLine()
    {
        const char* none[4] = {};
        struct Case {
            std::string yaml, where, what;
        } cases[] = {
            {fourLanes("traffic: {car_following: idn}\n", none, ""), "knobs.yaml:3:",
             "error: traffic.car_following: must be idm, gap_time or fuzzy, got 'idn'"},
            {fourLanes("traffic: {car_following: inherit}\n", none, ""), "knobs.yaml:3:", "got 'inherit'"},
            {fourLanes("traffic:\n  walker_start_delay: [3, 1]\n", none, ""), "knobs.yaml:4:",
             "error: traffic.walker_start_delay: the minimum (first) must not exceed the maximum"},
            {fourLanes("traffic:\n  crossing_margin: -1\n", none, ""), "knobs.yaml:4:", "traffic.crossing_margin"},
            {fourLanes("traffic:\n  yield_horizon: 0\n", none, ""), "knobs.yaml:4:", "traffic.yield_horizon"},
            {fourLanes("traffic:\n  waiting_sped: 0.1\n", none, ""), "knobs.yaml:4:", "warning: traffic.waiting_sped: unknown key 'waiting_sped' is ignored"},
            {fourLanes("", none, "slow"), "knobs.yaml:5:",
             "agent_types[1].car_following: must be inherit, idm, gap_time or fuzzy, got 'slow'"},
        };
        for (const Case& c : cases) {
            const std::string error = firstProblem(c.yaml);
            QVERIFY2(error.rfind(c.where, 0) == 0 && error.find(c.what) != std::string::npos,
                     qPrintable(QString::fromStdString(c.what + " <- " + error)));
        }
        const char* bad[4] = {"idm", "jam", nullptr, nullptr};
        QVERIFY(firstProblem(fourLanes("", bad, "")).find("lanes[1].car_following: must be inherit, idm") !=
                std::string::npos);
        // On a walker's type the key is a warning (the editor may have set it before the
        // type became a walker): the scene loads.
        const LoadResult walker = parseScene("throng: 1\nagent_types:\n  - {name: w, car_following: idm}\n", "knobs.yaml", "");
        QVERIFY(walker.ok());
        QCOMPARE(walker.diagnostics.size(), std::size_t(1));
        QVERIFY2(walker.diagnostics[0].format().rfind("knobs.yaml:3:", 0) == 0 &&
                     walker.diagnostics[0].format().find("warning: agent_types[0].car_following: only vehicle types "
                                                         "follow cars; ignored here") != std::string::npos,
                 walker.diagnostics[0].format().c_str());
    }

    // The lane's model, else the type's, else the scene's: each follower brakes exactly as
    // the model it should have, and the three models brake differently.
    void eachVehicleFollowsTheModelItsLaneTypeOrSceneSays()
    {
        // l0 car: scene's gap_time; l1 bus: lane's idm over the type's fuzzy; l2 car: lane's
        // fuzzy; l3 bus: type's fuzzy (lane inherits).
        const char* lanes[4] = {nullptr, "idm", "fuzzy", "inherit"};
        const Scene s = parseKnobs(fourLanes("traffic: {car_following: gap_time}\n", lanes, "fuzzy"));
        const FollowingModel expected[4] = {FollowingModel::GapTime, FollowingModel::Idm, FollowingModel::Fuzzy,
                                            FollowingModel::Fuzzy};
        const TrafficSystem t(s);
        std::vector<float> byModel[3];
        for (const FollowingModel m : {FollowingModel::Idm, FollowingModel::GapTime, FollowingModel::Fuzzy})
            byModel[int(m)] = speeds(s, vehicleIndex(t, 10), &m);
        QVERIFY2(byModel[0] != byModel[1] && byModel[1] != byModel[2] && byModel[0] != byModel[2],
                 "the three models brake alike: the test could not tell them apart");
        for (int k = 0; k < 4; ++k) {
            const std::size_t follower = vehicleIndex(t, std::uint32_t(10 + k));
            QVERIFY2(t.params(follower).model == expected[k], qPrintable(QString("lane %1").arg(k)));
            const std::vector<float> seen = speeds(s, follower);
            const std::vector<float> want = speeds(s, follower, &expected[k]);
            QVERIFY2(seen == want, qPrintable(QString("lane %1 follows %2").arg(k).arg(toString(expected[k]))));
            QVERIFY(*std::min_element(seen.begin(), seen.end()) < 11.0f);  // it braked for the leader
        }
        // Without any key every vehicle follows the IDM, as before the keys existed.
        const char* none[4] = {};
        const Scene plain = parseKnobs(fourLanes("", none, ""));
        const TrafficSystem p(plain);
        for (std::size_t i = 0; i < p.vehicleCount(); ++i)
            QVERIFY(p.params(i).model == FollowingModel::Idm);
    }

    // A standing driver moves off its start delay after it may: a leader standing free
    // from the start moves off between the delay's bounds.
    void driversMoveOffAfterTheirStartDelay()
    {
        const char* none[4] = {};
        for (const auto& [range, lo, hi] : {std::tuple{"[2, 2.5]", 2.0, 2.5}, std::tuple{"[0.3, 1.5]", 0.3, 1.5}}) {
            const Scene s = parseKnobs(fourLanes("traffic: {driver_start_delay: " + std::string(range) + "}\n", none, ""));
            TrafficSystem t(s);
            std::vector<double> moved(4, -1.0);
            for (int k = 0; k < 24 * 4; ++k) {
                t.step({});
                for (int lane = 0; lane < 4; ++lane) {
                    const std::size_t leader = vehicleIndex(t, std::uint32_t(20 + lane));
                    if (moved[std::size_t(lane)] < 0.0 && t.speed(leader) > 0.0f)
                        moved[std::size_t(lane)] = t.timeS();
                }
            }
            for (const double at : moved) {
                qInfo("delay %s: moved off at %.3f s", range, at);
                QVERIFY2(at >= lo && at <= hi + 2.0 / 24.0, qPrintable(QString("moved off at %1 s").arg(at)));
            }
        }
    }

    // Walkers held at the kerb by the red step off the green's start plus their delay.
    void walkersStepOffAfterTheirStartDelay()
    {
        const std::vector<double> late = stepOffTimes(parseKnobs(kerbScene("traffic: {walker_start_delay: [3, 3.5]}\n")));
        const std::vector<double> usual = stepOffTimes(parseKnobs(kerbScene("")));
        const double green = 10.0;
        for (const std::vector<double>* run : {&late, &usual})
            QVERIFY2(std::all_of(run->begin(), run->end(), [](double t) { return t > 0.0; }),
                     "a walker never reached the road");
        const double lateFirst = *std::min_element(late.begin(), late.end());
        const double usualFirst = *std::min_element(usual.begin(), usual.end());
        qInfo("first on the road after green: %.2f s with [3, 3.5], %.2f s by default", lateFirst - green,
              usualFirst - green);
        QVERIFY(lateFirst >= green + 3.0);
        QVERIFY(lateFirst <= green + 3.5 + 1.0);  // the kerb is a few tenths of a metre ahead
        QVERIFY(usualFirst >= green);
        QVERIFY(usualFirst < green + 2.5);
    }

    // The margins and the yield rules, as a vehicle and a walker see them.
    void marginsAndYieldRulesChangeWhatTheyName()
    {
        auto system = [&](const std::string& traffic) {
            std::string yaml = kerbScene(traffic);
            yaml += "vehicles:\n  - {id: 100, type: car, lane: south, at: 40, speed: 10}\n";
            yaml.insert(yaml.find("agent_types:\n") + 13, "  - {name: car, kind: vehicle, radius: 2}\n");
            return parseKnobs(yaml);
        };
        // crossing_margin: a car standing with its front 1 m short of the strip holds the
        // walkers at the kerb only when the margin reaches it.
        for (const auto& [margin, holds] : {std::pair{0.5f, false}, std::pair{1.5f, true}}) {
            Scene s = system("traffic: {crossing_margin: " + std::to_string(margin) + "}\n");
            // The strip spans z in [-2.5, 2.5]; the south lane runs north (+z): front at -3.5.
            s.vehicles[0].atM = 50.0f - 3.5f - 2.0f;
            s.vehicles[0].speed = 0.0f;
            TrafficSystem t(s);
            t.step({});
            const PedestrianSignal sig = t.pedestrianSignal({-4.0f, 0.0f}, {1.0f, 0.0f}, 0.0f, 0.25f, 1);
            QCOMPARE(sig.crosswalk, 0);
            QVERIFY2(sig.vehicleCrossing == holds, qPrintable(QString("margin %1").arg(margin)));
        }
        // waiting_speed and yield_horizon: a car at 10 m/s, 20 m before the strip, on green,
        // and a walker 1.5 m clear of its corridor edging toward it at 0.1 m/s.
        auto brakes = [&](const std::string& traffic) {
            Scene s = system(traffic);
            s.trafficLights[0].offsetS = 0.0f;  // green
            s.vehicles[0].atM = 50.0f - 2.5f - 2.0f - 20.0f;
            TrafficSystem t(s);
            const PedestrianView walker{{-6.0f, 0.0f}, {0.1f, 0.0f}, 0.25f};
            t.step(std::span<const PedestrianView>(&walker, 1));
            return t.speed(0) < 10.0f - 0.5f / 24.0f;  // more than a coasting car loses
        };
        QVERIFY2(brakes("traffic: {waiting_speed: 0.05, yield_horizon: 30}\n"), "0.1 m/s is coming at 0.05");
        QVERIFY2(!brakes("traffic: {waiting_speed: 0.2, yield_horizon: 30}\n"), "0.1 m/s is waiting at 0.2");
        QVERIFY2(!brakes("traffic: {waiting_speed: 0.05, yield_horizon: 3}\n"), "1.5 m takes 15 s at 0.1 m/s");
        // walker_clearance: a walker standing on the lane 1 m beside the car's path; the
        // car passes it at the default clearance and stops for it at 1.5 m.
        auto stopsFor = [&](float clearance) {
            Scene s = system("traffic: {walker_clearance: " + std::to_string(clearance) + "}\n");
            s.trafficLights[0].offsetS = 0.0f;
            s.vehicles[0].atM = 20.0f;
            TrafficSystem t(s);
            const PedestrianView walker{{-1.75f + 2.0f + 0.25f + 1.0f, -10.0f}, {0.0f, 0.0f}, 0.25f};
            for (int k = 0; k < 24 * 6; ++k)
                t.step(std::span<const PedestrianView>(&walker, 1));
            return t.position(0).y < -10.0f;
        };
        QVERIFY(!stopsFor(0.5f));
        QVERIFY(stopsFor(1.5f));
    }
};

THRONG_REGISTER_TEST(TestTrafficKnobs)
#include "TestTrafficKnobs.moc"
