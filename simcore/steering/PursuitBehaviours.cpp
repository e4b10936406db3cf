// Pursuit, evasion and offset pursuit (Reynolds 1999, "Pursuit and Evasion", "Offset Pursuit").
#include "simcore/steering/PursuitBehaviours.h"

#include "simcore/steering/TargetBehaviours.h"
#include "simcore/steering/detail/BehaviourMath.h"
#include "simcore/steering/detail/SteeringMath.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace throng::sim {

using namespace detail;

namespace {

// Reynolds 1999: T = distance / speed, a cheap estimate of the time to close the gap.
float predictionInterval(float distanceM, float speed, float maxPredictionS)
{
    const float cap = nonNegative(maxPredictionS);
    if (!(speed > kTiny))
        return cap;
    return std::min(distanceM / speed, cap);
}

glm::vec3 predictedPosition(const Neighbour& other, float t)
{
    return finiteOrZero(other.position) + finiteOrZero(other.velocity) * t;
}

}  // namespace

glm::vec3 pursue(const SteeringAgent& agent, const Neighbour& quarry, const PursuitParams& params)
{
    const glm::vec3 desired =
        behave::pursuitVelocity(agent.position, finiteOrZero(quarry.position), finiteOrZero(quarry.velocity),
                                nonNegative(agent.maxSpeed), nonNegative(params.maxPredictionS));
    return steerTowards(agent, desired, params.responseTimeS);
}

glm::vec3 evade(const SteeringAgent& agent, const Neighbour& threat, const EvasionParams& params)
{
    const float dist = glm::length(finiteOrZero(threat.position - agent.position));
    const float panic = nonNegative(params.panicDistanceM);
    if (panic > 0.0f && dist >= panic)
        return glm::vec3(0.0f);
    const float t = predictionInterval(dist, glm::length(finiteOrZero(threat.velocity)), params.maxPredictionS);
    return flee(agent, predictedPosition(threat, t), FleeParams{0.0f, params.responseTimeS});
}

glm::vec3 pointInFrameOf(const Neighbour& quarry, glm::vec3 localOffset)
{
    const glm::vec3 fwd = normalizeOr(quarry.forward, normalizeOr(quarry.velocity, glm::vec3(0.0f, 0.0f, 1.0f)));
    const glm::vec3 right = rightOfForward(fwd);
    const glm::vec3 up = glm::cross(right, fwd);
    const glm::vec3 o = finiteOrZero(localOffset);
    return finiteOrZero(quarry.position) + right * o.x + up * o.y + fwd * o.z;
}

glm::vec3 pursueOffset(const SteeringAgent& agent, const Neighbour& quarry, const OffsetPursuitParams& params)
{
    // Feeding the quarry's velocity forward removes the steady lag a pure arrival would leave.
    const glm::vec3 point = pointInFrameOf(quarry, params.offsetM);
    const glm::vec3 desired = finiteOrZero(quarry.velocity) +
                              arrivalVelocity(agent, point, params.slowingDistanceM, params.toleranceM);
    return steerTowards(agent, truncate(desired, agent.maxSpeed), params.responseTimeS);
}

}  // namespace throng::sim
