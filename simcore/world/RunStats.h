#pragma once
// The figures of one run, as the CLI's --stats JSON carries them (DESIGN.md).

#include "simcore/world/NavStats.h"
#include "simcore/world/PhaseTimes.h"
#include "simcore/world/StepCounters.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace throng::sim {

class World;

// Crossings of one stop line per green phase of its light: vehicles over a lane's stop
// line, or pedestrians stepping onto a controlled crosswalk.
struct StopLineFlow {
    std::string light, lane, crosswalk;  // lane or crosswalk is empty
    std::uint64_t crossings = 0;
    std::uint64_t greenPhases = 0;
    double perGreen = 0.0;
};

struct RunStats {
    std::uint64_t agents = 0;
    std::uint64_t frames = 0;  // recorded frames including frame 0
    int subSteps = 1;          // steps per frame (StepRate.h): 1 from 24 fps up
    std::uint64_t seed = 0;
    int threads = 1;
    std::vector<std::uint64_t> chunksPerThread;  // work chunks each thread ran (thread 0: the caller)
    double simulatedSeconds = 0.0;
    double wallSeconds = 0.0;
    double agentStepsPerSecond = 0.0;
    // Wall-clock seconds the steps spent in each phase (World::phaseTimes, PhaseTimes.h).
    std::array<double, kStepPhaseCount> phaseSeconds{};
    std::uint64_t arrived = 0;
    std::uint64_t withGoal = 0;
    StepCounters counters;  // counters.redLightViolations: pedestrians only
    // Traffic (zero without lanes, vehicles or heroes).
    std::uint64_t vehicles = 0, heroes = 0;
    std::uint64_t vehicleRedLightViolations = 0;
    std::uint64_t carPedestrianCollisions = 0;  // vehicle-pedestrian pairs in contact, summed over steps
    std::uint64_t vehicleCollisions = 0;        // vehicle pairs in contact, summed over steps
    std::uint64_t vehicleCrossings = 0, pedestrianCrossings = 0;  // over all stop lines
    std::vector<StopLineFlow> throughput;
    // Fliers at the last step (FlockFigures.h); zero without fliers.
    std::uint64_t fliers = 0;
    double flierPolarisation = 0.0;    // |mean unit velocity|: 1 = all fly one way, ~0 = random
    double flierSpreadM = 0.0;         // RMS distance from the fliers' centre, m
    double flierCentreToLeaderM = 0.0; // followers' centre to their leaders' mean position, m
    NavStats nav;  // exits, shortest-path walkers, plans
    // Sources (Sources.h): the agents they let in over the run, those still off stage at
    // its end; and the agents in the scene (neither off stage nor out) at the end.
    std::uint64_t sourceAgents = 0, offstage = 0, inScene = 0;
    // Agents in the scene at 0 s, 1 s, 2 s, ... of the run: filled by whoever steps the
    // World (sampleInScene after each step); empty if nobody did.
    std::vector<std::uint64_t> inSceneEachSecond;
    // Adds the count of agents in the scene when the World has passed a whole second
    // since the last sample (the first call samples 0 s... as the World stands).
    static void sampleInScene(const World& world, std::vector<std::uint64_t>& series);

    static RunStats from(const World& world, std::uint64_t frames, double wallSeconds);
    std::string toJson() const;
};

}  // namespace throng::sim
