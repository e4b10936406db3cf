// Unaligned collision avoidance (Reynolds 1999, "Unaligned Collision Avoidance").
#include "simcore/steering/UnalignedCollisionAvoidance.h"

#include "simcore/steering/detail/SteeringConstants.h"
#include "simcore/steering/detail/SteeringMath.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::sim {

using namespace detail;

namespace {

struct Threat {
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
    Threat threat;
    for (const Neighbour& n : neighbours) {
        const glm::vec3 dp = finiteOrZero(n.position) - p;
        const glm::vec3 dv = finiteOrZero(n.velocity) - v;
        const float dv2 = glm::dot(dv, dv);
        if (dv2 <= kTiny * kTiny)
            continue;  // moving together: the gap never closes
        const float t = -glm::dot(dp, dv) / dv2;
        if (!(t >= 0.0f && t <= horizon))
            continue;
        const glm::vec3 offset = dp + dv * t;
        const float clear = nonNegative(agent.radius) + nonNegative(n.radius) + nonNegative(params.marginM);
        if (glm::length(offset) >= clear)
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
    const float lateral = glm::dot(threat.offsetAtApproach, right);
    const float sideSign = lateral > kDeadAheadM ? -1.0f : 1.0f;
    const float urgency = 1.0f - threat.timeS / horizon;
    const float maxForce = nonNegative(agent.maxForce);

    const bool headOn = glm::dot(h, threat.forward) < params.headOnCosine;
    const float brake = headOn ? std::clamp(finiteOr(params.brakeFraction, 0.0f), 0.0f, 1.0f) : 0.0f;
    // Split the budget so lateral and braking together never exceed maxForce.
    const glm::vec3 lateralPart = right * (sideSign * std::sqrt(1.0f - brake * brake));
    const glm::vec3 brakePart = v == glm::vec3(0.0f) ? glm::vec3(0.0f) : -h * brake;
    return (lateralPart + brakePart) * (maxForce * urgency);
}

}  // namespace throng::sim
