// Wander (Reynolds 1999, "Wander"): a constrained random walk of the steering target.
#include "simcore/steering/Wander.h"

#include "simcore/steering/detail/BehaviourMath.h"
#include "simcore/steering/detail/SteeringMath.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace throng::sim {

using namespace detail;

WanderResult wander(const SteeringAgent& agent, const WanderState& previous, glm::vec3 random,
                    const WanderParams& params)
{
    const float radius = nonNegative(params.radiusM);
    glm::vec3 prev = normalizeOr(previous.target, glm::vec3(0.0f, 0.0f, 1.0f));
    glm::vec3 jitter =
        glm::clamp(finiteOrZero(random), glm::vec3(-1.0f), glm::vec3(1.0f)) * nonNegative(params.jitterM);
    if (!params.flying) {
        prev = normalizeOr(glm::vec3(prev.x, 0.0f, prev.z), glm::vec3(0.0f, 0.0f, 1.0f));
        jitter.y = 0.0f;
    }
    // Buckland's formulation of Reynolds' wander: jitter the point on the circle, then put it back
    // on the circle; the old point stays if the jitter cancels it exactly.
    WanderResult result;
    result.state.target = behave::wanderTarget(prev, radius, jitter);

    glm::vec3 forward, up;
    if (params.flying) {
        forward = heading(agent);
        up = normalizeOr(agent.up - forward * glm::dot(agent.up, forward), kWorldUp);
    } else {
        const glm::vec2 h = planarHeading(agent);
        forward = h == glm::vec2(0.0f) ? glm::vec3(0.0f, 0.0f, 1.0f) : fromXz(h);
        up = kWorldUp;
    }
    const glm::vec3 right = normalizeOr(glm::cross(forward, up), rightOfForward(forward));
    const glm::vec3 aim =
        behave::wanderAim(forward, right, up, result.state.target, radius, nonNegative(params.distanceM));
    result.force = steerTowards(agent, behave::seekVelocity(aim, nonNegative(agent.maxSpeed)), params.responseTimeS);
    return result;
}

}  // namespace throng::sim
