#pragma once
// Flow-field following (Reynolds 1999): the caller samples the field at the agent's
// predicted position and passes the direction; the agent steers to travel along it at top
// speed. Pure; never samples a field itself, never allocates.

#include "simcore/steering/SteeringAgent.h"

#include <glm/vec3.hpp>

namespace throng::sim {

struct FlowFollowParams {
    float predictionS = 0.5f;     // s, >= 0: the field is sampled at position + velocity * this
    float responseTimeS = 0.25f;  // s, > 0: time to reach the desired velocity
};

// Where the caller should sample the field.
glm::vec3 flowSamplePoint(const SteeringAgent& agent, const FlowFollowParams& params = {});

// fieldDirection: the field's desired direction at the sample point (any length; zero = no flow
// there, and then the force is exactly zero).
glm::vec3 followFlow(const SteeringAgent& agent, glm::vec3 fieldDirection, const FlowFollowParams& params = {});

}  // namespace throng::sim
