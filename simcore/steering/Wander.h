#pragma once
// Wander (Reynolds 1999): a target on a circle (sphere for fliers) ahead of the agent drifts by
// small random steps and the agent steers toward it. Pure: the caller passes the previous state
// and counter-RNG numbers and keeps the returned state; it never draws random numbers itself.

#include "simcore/steering/SteeringAgent.h"

#include <glm/vec3.hpp>

namespace throng::sim {

struct WanderParams {
    float distanceM = 2.0f;       // m, >= 0: distance of the circle's centre ahead of the agent
    float radiusM = 0.5f;         // m, >= 0: circle radius, the wander strength
    float jitterM = 0.1f;         // m per call, >= 0: most the target moves in one step, the rate
    bool flying = false;          // false: the target stays in the agent's horizontal plane
    float responseTimeS = 0.5f;   // s, > 0: time to reach the desired velocity
};

struct WanderState {
    glm::vec3 target{0.0f, 0.0f, 1.0f};  // unit: on the circle, in the agent's frame (x right, y up, z forward)
};

struct WanderResult {
    glm::vec3 force{0.0f};  // N, at most maxForce
    WanderState state;      // pass it back next step
};

// random: three numbers in [-1, 1] (y ignored unless flying). The same inputs give the same result.
// The desired direction never leaves the cone of half-angle asin(radius / distance) around forward
// (when radius < distance), so the agent keeps moving ahead while it turns.
WanderResult wander(const SteeringAgent& agent, const WanderState& previous, glm::vec3 random,
                    const WanderParams& params = {});

}  // namespace throng::sim
