#pragma once
// Drops animation keys that linear interpolation between their kept neighbours reproduces
// within a tolerance (greedy, left to right, at most kMaxGap keys apart). Pure functions.
#ifndef THRONG_EXPORT_BUILD
#error "a detail/ header, private to throng::export: include the module's public headers instead"
#endif

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace throng::exporting::detail {

inline constexpr std::size_t kMaxKeyGap = 48;

// Indices of the keys to keep, first and last always among them. times: seconds, strictly
// increasing, one per key. toleranceM: largest distance between a dropped key and the
// line through its kept neighbours, m.
std::vector<std::uint32_t> keepVec3Keys(std::span<const float> times, std::span<const glm::vec3> keys, float toleranceM);
// Same for unit quaternions (neighbours in one hemisphere); toleranceRad: largest angle
// between a dropped key and the normalised interpolation of its kept neighbours.
std::vector<std::uint32_t> keepRotationKeys(std::span<const float> times, std::span<const glm::quat> keys,
                                            float toleranceRad);

}  // namespace throng::exporting::detail
