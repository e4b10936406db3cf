#pragma once
// Obstacle avoidance (Reynolds 1999) against vertical circle and box obstacles: a free
// cylinder ahead of the agent, growing with speed, must stay clear. Pure; returns exactly
// zero when no collision is imminent, and never moves the agent or allocates.

#include "simcore/steering/BehaviourKey.h"
#include "simcore/steering/SteeringAgent.h"
#include "simcore/steering/SteeringGeometry.h"

#include <glm/vec3.hpp>

#include <span>
#include <array>
#include <string_view>

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

// Obstacle avoidance's entry in the behaviour list (BehaviourTable.h): asks wherever the
// world has obstacles, with those within the cylinder's reach.
struct ObstacleAvoidanceBehaviour {
    static constexpr std::string_view kName = "obstacle_avoidance";
    struct Slot {
        ObstacleAvoidanceParams obstacles;
    };
    static constexpr auto kParams = &Slot::obstacles;
    using P = ObstacleAvoidanceParams;
    static constexpr std::array kKeys{
        ParamKey<P>{.key = "min_length", .meaning = "m, >= 0: look-ahead cylinder when standing",
                    .number = &P::minLengthM},
        ParamKey<P>{.key = "lookahead", .meaning = "s, >= 0: extra cylinder length per m/s", .number = &P::lookaheadS},
        ParamKey<P>{.key = "margin", .meaning = "m, >= 0: clearance beyond the body", .number = &P::marginM},
        ParamKey<P>{.key = "whisker_angle", .meaning = "degrees, 0..90: side feelers' angle",
                    .kind = ParamKind::AngleDeg, .hi = 90, .number = &P::whiskerAngleRad},
        ParamKey<P>{.key = "response", .meaning = "lateral or repulsive", .kind = ParamKind::Choice,
                    .choose = [](P& params, std::string_view word) {
                        if (word == "lateral")
                            params.response = AvoidanceResponse::Lateral;
                        else if (word == "repulsive")
                            params.response = AvoidanceResponse::Repulsive;
                        return word == "lateral" || word == "repulsive";
                    }},
    };
    template <class Step, class Emit>
    static void request(const Step& step, const ObstacleAvoidanceParams& p, Emit&& emit)
    {
        const float reach = p.minLengthM + p.lookaheadS * step.self.speed() + step.self.radius + p.marginM;
        step.withObstaclesNear(reach, [&](std::span<const CircleObstacle> circles, std::span<const BoxObstacle> boxes) {
            emit(avoidObstacles(step.self, circles, boxes, step.goal, p));
        });
    }
};

}  // namespace throng::sim
