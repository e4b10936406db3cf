#pragma once
// Obstacle avoidance (Reynolds 1999) against vertical circle and box obstacles: a free
// cylinder ahead of the agent, growing with speed, must stay clear. Pure; returns exactly
// zero when no collision is imminent, and never moves the agent or allocates.

#include "simcore/steering/SteeringAgent.h"
#include "simcore/steering/SteeringGeometry.h"

#include <glm/vec3.hpp>

#include <span>

namespace throng::sim {

enum class AvoidanceResponse {
    Lateral,    // perpendicular to the velocity, toward the side that passes nearer the target
    Repulsive,  // away from the obstacle's centre
};

struct ObstacleAvoidanceParams {
    float minLengthM = 1.0f;        // m, >= 0: cylinder length when standing still
    float lookaheadS = 1.5f;        // s, >= 0: extra cylinder length per m/s of speed
    float marginM = 0.2f;           // m, >= 0: clearance kept beyond the agent's radius
    float whiskerAngleRad = 0.6f;   // rad, [0, pi/2]: angle of the two half-length side feelers
    AvoidanceResponse response = AvoidanceResponse::Lateral;
};

// Feelers: the cylinder along the heading at full length (half width = radius + margin) and two
// side feelers at half length. The nearest hit decides; the force grows linearly from zero at the
// end of its feeler to maxForce at the agent. An agent already overlapping an obstacle is pushed
// straight out at maxForce. `target` is where the agent is going (its goal, or position +
// forward when it has none). The side to pass on: the side of the line agent-target away from
// the obstacle's centre (dead on the line: away from it as seen along the heading, then the
// agent's right), blended with straight away from the obstacle; the lateral answer turns toward
// that side, the repulsive one leans toward it only as much as the obstacle is dead ahead. The
// choice changes only when the agent crosses the line obstacle-target, which it is pushed away
// from, so agent, obstacle and target in a line never make it flip sides.
glm::vec3 avoidObstacles(const SteeringAgent& agent, std::span<const CircleObstacle> circles,
                         std::span<const BoxObstacle> boxes, glm::vec3 target,
                         const ObstacleAvoidanceParams& params = {});

}  // namespace throng::sim
