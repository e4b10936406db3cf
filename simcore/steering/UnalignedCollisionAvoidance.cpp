// Unaligned collision avoidance (Reynolds 1999, "Unaligned Collision Avoidance").
#include "simcore/steering/UnalignedCollisionAvoidance.h"

#include "simcore/steering/detail/BehaviourMath.h"
#include "simcore/steering/detail/SteeringMath.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::sim {

using namespace detail;

namespace {

struct Approach {
    float timeS = -1.0f;  // < 0: none
    std::uint32_t id = 0;
    glm::vec3 offsetAtApproach{0.0f};  // threat minus agent at the time of nearest approach
    glm::vec3 forward{0.0f};
};

}  // namespace

glm::vec3 avoidUnalignedCollisions(const SteeringAgent& agent, std::span<const Neighbour> neighbours,
                                   const UnalignedAvoidanceParams& params)
{
    const float horizon = nonNegative(params.horizonS);
    if (!(horizon > kTiny))
        return glm::vec3(0.0f);
    const glm::vec3 p = finiteOrZero(agent.position), v = finiteOrZero(agent.velocity);
    Approach threat;
    const float margin = nonNegative(params.marginM);
    for (const Neighbour& n : neighbours) {
        const float clear = nonNegative(agent.radius) + nonNegative(n.radius) + margin;
        float t;
        glm::vec3 offset;
        if (!behave::approachesWithin(finiteOrZero(n.position) - p, finiteOrZero(n.velocity) - v, horizon, clear, t,
                                      offset))
            continue;
        if (threat.timeS < 0.0f || t < threat.timeS || (t == threat.timeS && n.id < threat.id)) {
            threat.timeS = t;
            threat.id = n.id;
            threat.offsetAtApproach = offset;
            threat.forward = normalizeOr(n.velocity, normalizeOr(n.forward, glm::vec3(0.0f)));
        }
    }
    if (threat.timeS < 0.0f)
        return glm::vec3(0.0f);

    const glm::vec3 h = heading(agent);
    const glm::vec3 right = normalizeOr(glm::cross(h, normalizeOr(agent.up, kWorldUp)), rightOfForward(h));
    const bool headOn = glm::dot(h, threat.forward) < params.headOnCosine;
    const float brake = std::clamp(finiteOr(params.brakeFraction, 0.0f), 0.0f, 1.0f);
    return behave::unalignedAvoidance(h, right, threat.offsetAtApproach, threat.timeS, horizon, headOn, brake,
                                      std::sqrt(1.0f - brake * brake), v != glm::vec3(0.0f),
                                      nonNegative(agent.maxForce));
}

}  // namespace throng::sim
