#pragma once
// Tuning constants and random streams of the step's phases, in one place for the general
// path (WorldStep.cpp, Steer.cpp) and the kernels (WalkKernel.cpp, BoidKernel.cpp), and
// the two small rules both take from them (wander's draws, coming to rest). Nothing of
// the step's geometry (StepGeometry.h), so a kernel can take them alone.
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include "simcore/base/Rng.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>

namespace throng::sim::detail {

// The counter-based generator's streams a step draws (Rng.h): wander's random vector.
enum StepStream : std::uint64_t { kWanderX = 101, kWanderY, kWanderZ };

// Wander's three draws in [-1, 1] for the agent `id` in step `step` of a World seeded `seed`.
inline glm::vec3 wanderDraws(std::uint64_t seed, std::uint32_t id, std::uint64_t step)
{
    const std::uint64_t key = rngKey(seed, id, step);
    return {rngRangeOf(key, kWanderX, -1.0f, 1.0f), rngRangeOf(key, kWanderY, -1.0f, 1.0f),
            rngRangeOf(key, kWanderZ, -1.0f, 1.0f)};
}

// Most walls and obstacles one agent considers in a step.
constexpr std::size_t kMaxNearWalls = 16, kMaxNearObstacles = 8;
// How near its own spot in the goal area an agent stops for good.
constexpr float kSpotToleranceM = 0.1f;
// How quickly an agent with nowhere to go brakes to a stand, s, and the force that brakes it
// (the lowest priority of its requests, weight 1).
constexpr float kStandStillResponseS = 0.5f;
inline glm::vec3 standStillForce(glm::vec3 velocity, float mass)
{
    return -velocity * (mass / kStandStillResponseS);
}
// At the end of its path, a walker held slower than this stops where it stands.
constexpr float kSettleSpeedMps = 0.1f;
// Inside its goal, an agent this near (body to body) a stopped agent settles too.
constexpr float kSettleGapM = 0.05f;
// Overlap tolerance: touching within 1 cm is contact, not overlap.
constexpr float kOverlapToleranceM = 0.01f;
// The contact rounds after the collide pass (settleContacts, Collide.cpp): at most this many, and
// an overlap shallower than kContactSlopM is left (it is contact).
constexpr int kContactRounds = 4;
constexpr float kContactSlopM = 0.001f;

}  // namespace throng::sim::detail
