#pragma once
// Scenes and a scripted pedestrian stream for the traffic tests: a four-lane signalised
// crossroads built in code, walkers that cross its crosswalks obeying the signal answer,
// and a run that returns the counters and a hash of every vehicle state.

#include "simcore/scene/Scene.h"
#include "simcore/traffic/TrafficSystem.h"

#include <cstdint>
#include <vector>

namespace throng::test {

struct CrossingSetup {
    int carsPerLane = 6;
    int walkersPerCrosswalk = 10;
    float laneLengthM = 200.0f;  // each arm is laneLength / 2 long
    bool loopLanes = false;      // false: vehicles leave at the far end and re-enter (random arrivals)
    std::uint64_t seed = 7;
    sim::FollowingModel model = sim::FollowingModel::Idm;  // every car's car-following model
};

// Two roads crossing at the origin, one lane each way (east, west, south, north bound),
// a crosswalk on each arm 6 m from the centre, stop lines 8.5 m before the centre.
// Light "ew" (green 20, yellow 3, red 27) runs the east-west lanes and the crosswalks
// over the north-south road; light "ns" the others, its green 2 s after "ew" turns red.
sim::Scene crossingScene(const CrossingSetup& setup);

// Walkers going back and forth over one crosswalk each, stopping where the signal
// answer says, then pausing at the far kerb.
class WalkerStream {
public:
    WalkerStream(const sim::LaneNetwork& net, int perCrosswalk, std::uint64_t seed);
    std::span<const sim::PedestrianView> views() const { return m_views; }
    // Moves every walker one step of dt by the traffic's signal answers.
    void step(const sim::TrafficSystem& traffic, float dt);
    std::size_t size() const { return m_walkers.size(); }
    std::uint64_t completedCrossings() const { return m_completed; }

private:
    struct Walker {
        int crosswalk;
        float u, w, speed, dir, pause;
        std::uint32_t id, trips;
    };
    const sim::LaneNetwork* m_net;
    std::vector<Walker> m_walkers;
    std::vector<sim::PedestrianView> m_views;
    std::uint64_t m_seed;
    std::uint64_t m_completed = 0;
};

struct CrossingRun {
    sim::TrafficCounters counters;
    std::vector<sim::StopLineThroughput> throughput;
    std::uint64_t stateHash = 0;    // over every vehicle's s and speed bits, every step
    std::uint64_t walkerCrossings = 0;
    std::uint32_t minRespawns = 0;  // over all vehicles
};
CrossingRun runCrossing(const CrossingSetup& setup, double seconds, int threads);

}  // namespace throng::test
