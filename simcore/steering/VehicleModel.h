#pragma once
// The simple vehicle model (Reynolds 1999): one explicit Euler step from a steering force to
// a new position, velocity and local frame. Pure: returns the next state, never reads or
// writes anything else, and never produces NaN or infinity whatever its inputs.

#include "simcore/steering/SteeringAgent.h"

#include <glm/vec3.hpp>

namespace throng::sim {

struct VehicleParams {
    bool flying = false;              // false: ground agent, y velocity 0 and up = +y
    float minSpeed = 0.0f;            // m/s, >= 0: fliers never go slower (stall speed); ignored on the ground
    float bankingGainS2PerM = 0.0f;   // s^2/m, >= 0: how far up leans per m/s^2 of lateral acceleration (fliers)
    float bankingResponseS = 0.5f;    // s, > 0: smoothing time of the up vector (fliers)
};

// truncate force to maxForce; a = F / mass; v += a dt; truncate v to maxSpeed (and raise it to
// minSpeed for fliers); position += v dt; rebuild forward/side/up from the velocity. Below
// 1 mm/s the previous forward is kept. Zero or negative mass counts as 1 g, negative or
// non-finite limits as 0, non-finite state or force components as 0; dt <= 0 changes nothing.
SteeringAgent integrateVehicle(const SteeringAgent& state, glm::vec3 force, float dt, const VehicleParams& params = {});

}  // namespace throng::sim
