#pragma once
// Running totals of the quality figures a user checks after a run (penetrations,
// overlaps, red-light violations, non-finite values). Plain data, summed per step.

#include <cstdint>

namespace throng::sim {

struct StepCounters {
    std::uint64_t wallPenetrations = 0;      // steered agents' moves whose centre crossed a wall segment (kerbs and box sides too)
    std::uint64_t obstaclePenetrations = 0;  // agent-steps ending with the body > 1 cm into a circle or box obstacle (heroes, vehicles too)
    std::uint64_t overlappingPairs = 0;      // pairs closer than the sum of radii less 1 cm, summed over steps
    std::uint64_t redLightViolations = 0;    // pedestrians stepping onto a crosswalk's road part on red
    std::uint64_t nonFiniteValues = 0;       // NaN/inf positions or velocities seen
    std::uint64_t leaderOvertaken = 0;       // follower-steps ahead of a moving leader (WorldLeaders.cpp)
    std::uint64_t agentSteps = 0;
};

}  // namespace throng::sim
