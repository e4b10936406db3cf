#pragma once
// The figures of one run, as the CLI's --stats JSON carries them (DESIGN.md).

#include "simcore/world/StepCounters.h"

#include <cstdint>
#include <string>

namespace throng::sim {

class World;

struct RunStats {
    std::uint64_t agents = 0;
    std::uint64_t frames = 0;  // recorded frames including frame 0
    std::uint64_t seed = 0;
    int threads = 1;
    double simulatedSeconds = 0.0;
    double wallSeconds = 0.0;
    double agentStepsPerSecond = 0.0;
    std::uint64_t arrived = 0;
    std::uint64_t withGoal = 0;
    StepCounters counters;

    static RunStats from(const World& world, std::uint64_t frames, double wallSeconds);
    std::string toJson() const;
};

}  // namespace throng::sim
