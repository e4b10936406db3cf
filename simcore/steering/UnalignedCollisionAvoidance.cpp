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

glm::vec3 avoidUnalignedCollisions(const SteeringAgent& agent, std::span<const Neighbour> neighbours,
                                   const UnalignedAvoidanceParams& params)
{
    const behave::UnalignedGains gains = behave::unalignedGains(params);
    const float horizon = gains.horizonS;
    if (!(horizon > kTiny))
        return glm::vec3(0.0f);
    const glm::vec3 p = finiteOrZero(agent.position), v = finiteOrZero(agent.velocity);
    behave::SoonestApproach threat;
    const float margin = gains.marginM;
    for (std::size_t k = 0; k < neighbours.size(); ++k) {
        const Neighbour& n = neighbours[k];
        threat.consider(finiteOrZero(n.position) - p, finiteOrZero(n.velocity) - v, horizon,
                        nonNegative(agent.radius) + nonNegative(n.radius) + margin, n.id, std::uint32_t(k));
    }
    if (!threat.found())
        return glm::vec3(0.0f);
    const Neighbour& n = neighbours[threat.who];
    return behave::avoidSoonest(agent.velocity, agent.forward, agent.up, threat, n.velocity, n.forward, horizon,
                                params.headOnCosine, gains.brake,
                                nonNegative(agent.maxForce));
}

}  // namespace throng::sim
