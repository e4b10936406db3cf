#include "TrafficHarness.h"

#include "simcore/base/Rng.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace throng::sim;

namespace throng::test {

Scene crossingScene(const CrossingSetup& setup)
{
    Scene scene;
    scene.settings.fps = 24.0f;
    scene.settings.seed = setup.seed;
    scene.settings.boundsMin = glm::vec2(-setup.laneLengthM);
    scene.settings.boundsMax = glm::vec2(setup.laneLengthM);
    AgentType car;
    car.name = "car";
    car.kind = AgentKind::Vehicle;
    car.radiusM = 1.1f;
    car.maxSpeed = 13.9f;
    scene.agentTypes.push_back(car);

    const float h = 0.5f * setup.laneLengthM;
    auto lane = [&](const char* name, glm::vec2 a, glm::vec2 b) {
        Lane l;
        l.name = name;
        l.points = {a, b};
        l.loop = setup.loopLanes;
        scene.lanes.push_back(l);
    };
    lane("eastbound", {-h, 1.75f}, {h, 1.75f});
    lane("westbound", {h, -1.75f}, {-h, -1.75f});
    lane("southbound", {-1.75f, -h}, {-1.75f, h});
    lane("northbound", {1.75f, h}, {1.75f, -h});
    scene.crosswalks = {{"west", {-6, -5.5f}, {-6, 5.5f}, 3},
                        {"east", {6, 5.5f}, {6, -5.5f}, 3},
                        {"north", {-5.5f, -6}, {5.5f, -6}, 3},
                        {"south", {5.5f, 6}, {-5.5f, 6}, 3}};
    const float stopAt = h - 8.5f;
    TrafficLight ew{"ew", 20, 3, 27, 0, {-9, -9}, {}};
    ew.stopLines = {{"eastbound", stopAt, ""}, {"westbound", stopAt, ""}, {"", 0, "north"}, {"", 0, "south"}};
    TrafficLight ns{"ns", 20, 3, 27, -25, {9, 9}, {}};
    ns.stopLines = {{"southbound", stopAt, ""}, {"northbound", stopAt, ""}, {"", 0, "west"}, {"", 0, "east"}};
    scene.trafficLights = {ew, ns};

    // Cars spread over the approach with random speeds, each slow enough to stop
    // comfortably (2 m/s^2) short of where the car ahead stands: a feasible start.
    const float spacing = (stopAt - 20.0f) / float(std::max(1, setup.carsPerLane));
    const float startSpeed = std::sqrt(2.0f * 2.0f * std::max(0.0f, spacing - 2.0f * car.radiusM - 2.0f));
    std::uint32_t id = 1;
    for (const Lane& l : scene.lanes)
        for (int k = 0; k < setup.carsPerLane; ++k) {
            const float at = 5.0f + float(k) * spacing;
            const float speed = std::min(startSpeed, rngRange(setup.seed, id, 0, 11, 0.0f, 10.0f));
            scene.vehicles.push_back({id, "car", l.name, at, speed});
            ++id;
        }
    return scene;
}

WalkerStream::WalkerStream(const LaneNetwork& net, int perCrosswalk, std::uint64_t seed) : m_net(&net), m_seed(seed)
{
    std::uint32_t id = 1000;
    for (std::size_t c = 0; c < net.crosswalkCount(); ++c) {
        const CrosswalkStrip& s = net.crosswalk(int(c));
        for (int k = 0; k < perCrosswalk; ++k, ++id) {
            Walker w;
            w.crosswalk = int(c);
            w.dir = (k % 2) ? 1.0f : -1.0f;
            w.u = w.dir > 0 ? -rngRange(seed, id, 0, 1, 2.0f, 3.0f) : s.lengthM + rngRange(seed, id, 0, 1, 2.0f, 3.0f);
            w.w = rngRange(seed, id, 0, 2, -(s.halfWidthM - 0.35f), s.halfWidthM - 0.35f);
            w.speed = rngRange(seed, id, 0, 3, 1.1f, 1.5f);
            w.pause = rngRange(seed, id, 0, 4, 0.0f, 20.0f);
            w.id = id;
            w.trips = 0;
            m_walkers.push_back(w);
        }
    }
    m_views.resize(m_walkers.size());
    for (std::size_t i = 0; i < m_walkers.size(); ++i) {
        const Walker& w = m_walkers[i];
        const CrosswalkStrip& s = net.crosswalk(w.crosswalk);
        m_views[i] = {s.a + s.dir * w.u + glm::vec2(s.dir.y, -s.dir.x) * w.w, {0, 0}, 0.3f};
    }
}

void WalkerStream::step(const TrafficSystem& traffic, float dt)
{
    for (std::size_t i = 0; i < m_walkers.size(); ++i) {
        Walker& w = m_walkers[i];
        const CrosswalkStrip& s = m_net->crosswalk(w.crosswalk);
        PedestrianView& view = m_views[i];
        const glm::vec2 before = view.position;
        float du = 0.0f;
        if (w.pause > 0.0f) {
            w.pause -= dt;
        } else {
            const PedestrianSignal sig =
                traffic.pedestrianSignal(before, s.dir * w.dir, glm::length(view.velocity), view.radiusM, w.id);
            du = w.dir * w.speed * dt;
            if (sig.crosswalk == w.crosswalk && !sig.onCrosswalk && sig.mustStop) {
                // Walk up to the stop point and no further; never backwards.
                const float uStop = glm::dot(sig.stopPoint - s.a, s.dir);
                du = w.dir > 0 ? std::clamp(uStop - w.u, 0.0f, du) : std::clamp(uStop - w.u, du, 0.0f);
            }
            w.u += du;
            const float target = w.dir > 0 ? s.lengthM + 2.5f : -2.5f;
            if ((w.dir > 0 && w.u >= target) || (w.dir < 0 && w.u <= target)) {
                w.dir = -w.dir;
                ++w.trips;
                ++m_completed;
                w.pause = rngRange(m_seed, w.id, w.trips, 4, 0.0f, 15.0f);
            }
        }
        view.position = s.a + s.dir * w.u + glm::vec2(s.dir.y, -s.dir.x) * w.w;
        view.velocity = (view.position - before) / dt;
    }
}

CrossingRun runCrossing(const CrossingSetup& setup, double seconds, int threads)
{
    const Scene scene = crossingScene(setup);
    TrafficOptions opt;
    opt.threads = threads;
    FollowingParams params;
    params.model = setup.model;
    opt.modelByType.push_back({"car", params});
    TrafficSystem traffic(scene, opt);
    WalkerStream walkers(traffic.lanes(), setup.walkersPerCrosswalk, setup.seed);
    CrossingRun run;
    std::vector<PedestrianView> before;
    const auto steps = std::uint64_t(std::llround(seconds * double(scene.settings.fps)));
    for (std::uint64_t k = 0; k < steps; ++k) {
        before.assign(walkers.views().begin(), walkers.views().end());
        traffic.step(before);
        walkers.step(traffic, traffic.dt());
        traffic.observePedestrians(before, walkers.views());
        for (std::size_t i = 0; i < traffic.vehicleCount(); ++i) {
            const float s = traffic.s(i), v = traffic.speed(i);
            std::uint32_t bits[2];
            std::memcpy(&bits[0], &s, 4);
            std::memcpy(&bits[1], &v, 4);
            run.stateHash = mix64(run.stateHash ^ ((std::uint64_t(bits[0]) << 32) | bits[1]));
        }
    }
    run.counters = traffic.counters();
    run.throughput = traffic.throughput();
    run.walkerCrossings = walkers.completedCrossings();
    run.minRespawns = ~0u;
    for (std::size_t i = 0; i < traffic.vehicleCount(); ++i)
        run.minRespawns = std::min(run.minRespawns, traffic.respawns(i));
    return run;
}

}  // namespace throng::test
