#pragma once
// Seek, flee and arrival (Reynolds 1999): steering toward or away from one fixed point.
// Pure functions of their arguments; they return a force (N, at most maxForce) and never
// integrate, allocate or read anything but their parameters.

#include "simcore/steering/SteeringAgent.h"

#include <glm/vec3.hpp>

namespace throng::sim {

struct SeekParams {
    float responseTimeS = 0.25f;  // s, > 0: time to reach the desired velocity (force = mass * dv / t)
};

struct FleeParams {
    float panicDistanceM = 0.0f;  // m, >= 0: flee only when nearer than this; 0 = at any distance
    float responseTimeS = 0.25f;  // s, > 0
};

struct ArrivalParams {
    float slowingDistanceM = 2.0f;  // m, > 0: the desired speed ramps down linearly inside it
    float toleranceM = 0.02f;       // m, >= 0: inside it the desired velocity is exactly zero
    float responseTimeS = 0.25f;    // s, > 0; below slowingDistanceM / (4 maxSpeed) the approach
                                    // is overdamped and never overshoots
};

// Desired velocity: toward target at maxSpeed (zero on the target, so it brakes there). Zero when
// standing still on the target.
glm::vec3 seek(const SteeringAgent& agent, glm::vec3 target, const SeekParams& params = {});

// Desired velocity: away from threat at maxSpeed. Zero outside the panic distance. An agent
// standing exactly on the threat flees along its forward.
glm::vec3 flee(const SteeringAgent& agent, glm::vec3 threat, const FleeParams& params = {});

// Seek that slows down inside the slowing distance and stops at the target. Zero once stopped
// inside the tolerance.
glm::vec3 arrive(const SteeringAgent& agent, glm::vec3 target, const ArrivalParams& params = {});

// The desired velocity of arrival alone, for behaviours that add a feed-forward velocity to it.
glm::vec3 arrivalVelocity(const SteeringAgent& agent, glm::vec3 target, float slowingDistanceM, float toleranceM);

}  // namespace throng::sim
