#pragma once
// Walking speed by age (Variation::ageYears; RiMEA test 7). Weidmann's (1993) mean walking
// speeds on level ground by age, as the RiMEA guideline's figure 2 draws them, at every
// tenth year from 10 to 80 and linear in between. An agent whose type sets an age range is
// given an age drawn uniformly from it (by the scene's seed and its id), and its speed is
// scaled by Weidmann's speed at that age over his mean for all adults, 1.34 m/s: a type
// with max_speed 1.34 and speed [1, 1] walks at exactly his speed for each age. The World
// and the exports draw the same age.

#include <glm/vec2.hpp>

#include <cstdint>

namespace throng::sim {

inline constexpr float kWalkingAgeMinYears = 10.0f, kWalkingAgeMaxYears = 80.0f;
inline constexpr float kWeidmannMeanSpeedMps = 1.34f;
// World::addAgent's random stream for the age (World.cpp checks it is its own).
inline constexpr std::uint64_t kAgeStream = 13;

// Weidmann's mean walking speed at `years` of age, m/s (clamped to 10 to 80 years).
float weidmannSpeedAtAge(float years);
// Whether a variation's age range is set ([0, 0]: no age).
inline bool hasAge(glm::vec2 ageRange) { return ageRange.y > 0.0f; }
// The age drawn for agent `id` from the range, years; 0 without one.
float agentAgeYears(glm::vec2 ageRange, std::uint64_t seed, std::uint64_t id);
// The factor the age puts on the agent's speed: weidmannSpeedAtAge / 1.34; 1 without one.
float ageSpeedFactor(glm::vec2 ageRange, std::uint64_t seed, std::uint64_t id);

}  // namespace throng::sim
