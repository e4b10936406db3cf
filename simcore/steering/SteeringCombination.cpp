// Weighted blending and prioritised acceleration allocation (Reynolds 1987, "Flocks, Herds,
// and Schools", section on arbitrating independent behaviours).
#include "simcore/steering/SteeringCombination.h"

#include "simcore/steering/detail/SteeringMath.h"
#include "simcore/steering/detail/WeightedBlend.h"

#include <glm/geometric.hpp>

namespace throng::sim {

using namespace detail;

namespace {

// A request counts when its weighted force is finite (as WeightedBlend::add).
bool usable(const SteeringRequest& r, glm::vec3& weighted)
{
    weighted = r.force * r.weight;
    return isFinite(weighted);
}

}  // namespace

glm::vec3 blendWeighted(std::span<const SteeringRequest> requests, float maxForce)
{
    WeightedBlend blend;
    for (const SteeringRequest& r : requests)
        blend.add(r.force, r.weight);
    return blend.total(maxForce);
}

glm::vec3 allocateByPriority(std::span<const SteeringRequest> requests, float maxForce)
{
    const float budget = nonNegative(maxForce);
    glm::vec3 total(0.0f);
    float used = 0.0f;
    for (const SteeringRequest& r : requests) {
        glm::vec3 f(0.0f);
        if (!usable(r, f))
            continue;
        const float magnitude = glm::length(f);
        if (!(magnitude > 0.0f))
            continue;
        if (used + magnitude <= budget) {
            total += f;
            used += magnitude;
            continue;
        }
        total += f * ((budget - used) / magnitude);
        break;
    }
    return total;
}

}  // namespace throng::sim
