// Seek, flee and arrival (Reynolds 1999, "Seek and Flee", "Arrival").
#include "simcore/steering/TargetBehaviours.h"

#include "simcore/steering/detail/BehaviourMath.h"
#include "simcore/steering/detail/SteeringMath.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace throng::sim {

using namespace detail;

glm::vec3 seek(const SteeringAgent& agent, glm::vec3 target, const SeekParams& params)
{
    return steerTowards(agent, behave::seekVelocity(finiteOrZero(target - agent.position), nonNegative(agent.maxSpeed)),
                        params.responseTimeS);
}

glm::vec3 flee(const SteeringAgent& agent, glm::vec3 threat, const FleeParams& params)
{
    const glm::vec3 away = finiteOrZero(agent.position - threat);
    const float panic = nonNegative(params.panicDistanceM);
    if (panic > 0.0f && glm::length(away) >= panic)
        return glm::vec3(0.0f);
    const glm::vec3 dir = normalizeOr(away, heading(agent));
    return steerTowards(agent, behave::seekVelocity(dir, nonNegative(agent.maxSpeed)), params.responseTimeS);
}

glm::vec3 arrivalVelocity(const SteeringAgent& agent, glm::vec3 target, float slowingDistanceM, float toleranceM)
{
    return behave::arrivalDesired(target - agent.position, agent.maxSpeed, slowingDistanceM, toleranceM);
}

glm::vec3 arrive(const SteeringAgent& agent, glm::vec3 target, const ArrivalParams& params)
{
    return steerTowards(agent, arrivalVelocity(agent, target, params.slowingDistanceM, params.toleranceM),
                        params.responseTimeS);
}

}  // namespace throng::sim
