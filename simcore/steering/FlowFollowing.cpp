// Flow-field following (Reynolds 1999, "Flow Field Following").
#include "simcore/steering/FlowFollowing.h"

#include "simcore/steering/detail/BehaviourMath.h"
#include "simcore/steering/detail/SteeringMath.h"

namespace throng::sim {

using namespace detail;

glm::vec3 flowSamplePoint(const SteeringAgent& agent, const FlowFollowParams& params)
{
    return finiteOrZero(agent.position) + finiteOrZero(agent.velocity) * nonNegative(params.predictionS);
}

glm::vec3 followFlow(const SteeringAgent& agent, glm::vec3 fieldDirection, const FlowFollowParams& params)
{
    const glm::vec3 dir = normalizeOr(fieldDirection, glm::vec3(0.0f));
    if (dir == glm::vec3(0.0f))
        return glm::vec3(0.0f);
    return steerTowards(agent, dir * nonNegative(agent.maxSpeed), params.responseTimeS);
}

}  // namespace throng::sim
