#pragma once
// Unaligned collision avoidance (Reynolds 1999): predict each neighbour's time of nearest
// approach assuming straight motion, and steer laterally away from the soonest one that will
// come too close, braking when it comes head-on. Pure; zero without a threat; no allocation.

#include "simcore/steering/Neighbour.h"
#include "simcore/steering/SteeringAgent.h"

#include <glm/vec3.hpp>

#include <span>

namespace throng::sim {

struct UnalignedAvoidanceParams {
    float horizonS = 3.0f;          // s, > 0: approaches further in the future are ignored
    float marginM = 0.1f;           // m, >= 0: clearance wanted beyond the two radii
    float headOnCosine = -0.7f;     // [-1, 1]: heading dot product below which a threat is head-on
    float brakeFraction = 0.5f;     // [0, 1]: share of the force spent braking against a head-on threat
};

// The threat is the neighbour whose nearest approach comes soonest (ties: lower id) among those
// predicted to pass nearer than the two radii plus the margin. The lateral force points away
// from the threat's predicted position; a threat dead ahead is passed on the agent's right,
// so two agents meeting exactly head-on both go right and part. Strength: maxForce *
// (1 - time / horizon), the lateral and braking parts together at most maxForce.
glm::vec3 avoidUnalignedCollisions(const SteeringAgent& agent, std::span<const Neighbour> neighbours,
                                   const UnalignedAvoidanceParams& params = {});

}  // namespace throng::sim
