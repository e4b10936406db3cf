#pragma once
// Test-only helpers for the steering suites: a standard walker, a fixed-step driver at
// 24 fps, planar checks and counter-RNG jitter. Computes nothing the tests then assert.

#include "simcore/steering/Neighbour.h"
#include "simcore/steering/SteeringAgent.h"
#include "simcore/steering/VehicleModel.h"

#include <glm/vec3.hpp>

#include <cstdint>

namespace throng::test {

inline constexpr float kDt = 1.0f / 24.0f;

// A pedestrian with the scene defaults: radius 0.3 m, 1.4 m/s, 3 N, 1 kg. Heading from the
// velocity when it has one, else +z.
sim::SteeringAgent walker(glm::vec3 position, glm::vec3 velocity = glm::vec3(0.0f), std::uint32_t id = 0);

sim::Neighbour asNeighbour(const sim::SteeringAgent& agent);

// One vehicle-model step of kDt.
sim::SteeringAgent advance(const sim::SteeringAgent& agent, glm::vec3 force,
                           const sim::VehicleParams& params = {});

float planarDistance(glm::vec3 a, glm::vec3 b);
// True when the move p0-p1 crosses or touches the segment a-b in the ground plane.
bool crossesSegment(glm::vec3 p0, glm::vec3 p1, glm::vec3 a, glm::vec3 b);
// Angle in radians between two directions; 0 when either is zero.
float angleBetween(glm::vec3 a, glm::vec3 b);
bool isFinite(glm::vec3 v);
bool isFinite(const sim::SteeringAgent& a);

// Three numbers in [-1, 1] from the counter RNG, keyed like the World's (seed, id, step).
glm::vec3 signedRandom3(std::uint64_t seed, std::uint32_t id, std::uint64_t step);

}  // namespace throng::test
