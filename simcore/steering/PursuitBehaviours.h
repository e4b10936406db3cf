#pragma once
// Pursuit, evasion and offset pursuit (Reynolds 1999): steering relative to a moving agent
// by predicting where it will be. Pure functions returning a force (N, at most maxForce);
// they never integrate, allocate or look at anything but their arguments.

#include "simcore/steering/Neighbour.h"
#include "simcore/steering/SteeringAgent.h"

#include <glm/vec3.hpp>

namespace throng::sim {

struct PursuitParams {
    float maxPredictionS = 2.0f;  // s, >= 0: the prediction interval never exceeds this
    float responseTimeS = 0.25f;  // s, > 0: time to reach the desired velocity
};

struct EvasionParams {
    float maxPredictionS = 2.0f;  // s, >= 0
    float panicDistanceM = 0.0f;  // m, >= 0: evade only when nearer than this; 0 = at any distance
    float responseTimeS = 0.25f;  // s, > 0
};

struct OffsetPursuitParams {
    glm::vec3 offsetM{0.0f, 0.0f, -1.5f};  // m, in the quarry's frame: x right, y up, z forward
    float slowingDistanceM = 2.0f;         // m, > 0: arrival ramp toward the offset point
    float toleranceM = 0.02f;              // m, >= 0: no correction nearer than this
    float responseTimeS = 0.25f;           // s, > 0
};

// Seeks the quarry's position predicted T = distance / maxSpeed ahead (clamped to maxPredictionS).
glm::vec3 pursue(const SteeringAgent& agent, const Neighbour& quarry, const PursuitParams& params = {});

// Flees from the threat's position predicted T = distance / threat speed ahead (clamped).
glm::vec3 evade(const SteeringAgent& agent, const Neighbour& threat, const EvasionParams& params = {});

// Holds a point fixed in the quarry's frame: the quarry's velocity fed forward plus arrival at the
// offset point, so a steady offset is held without lag. Zero once the offset is held exactly.
glm::vec3 pursueOffset(const SteeringAgent& agent, const Neighbour& quarry, const OffsetPursuitParams& params = {});

// The world position of a point given in the quarry's frame (x right, y up, z forward).
glm::vec3 pointInFrameOf(const Neighbour& quarry, glm::vec3 localOffset);

}  // namespace throng::sim
