#pragma once
// Running totals of the quality figures a user checks after a run (penetrations,
// overlaps, red-light violations, non-finite values). Plain data, summed per step.

#include <cstdint>

namespace throng::sim {

struct StepCounters {
    std::uint64_t wallPenetrations = 0;      // agent moves that crossed a wall segment
    std::uint64_t obstaclePenetrations = 0;  // agent-steps ending inside an obstacle
    std::uint64_t overlappingPairs = 0;      // pairs closer than the sum of radii, summed over steps
    std::uint64_t redLightViolations = 0;    // pedestrians stepping onto a crosswalk on red
    std::uint64_t nonFiniteValues = 0;       // NaN/inf positions or velocities seen
    std::uint64_t leaderOvertaken = 0;       // follower-steps ahead of a moving leader (WorldLeaders.cpp)
    std::uint64_t agentSteps = 0;
};

}  // namespace throng::sim
