// Weighted blending and prioritised acceleration allocation (Reynolds 1987, "Flocks, Herds,
// and Schools", section on arbitrating independent behaviours).
#include "simcore/steering/SteeringCombination.h"

#include "simcore/steering/detail/SteeringMath.h"

#include <glm/geometric.hpp>

namespace throng::sim {

using namespace detail;

namespace {

// A request counts when its weighted force is finite. That alone also rules out a
// non-finite weight or force: any infinity or NaN among them makes some product an
// infinity or a NaN (0 * inf is NaN), so one test does what three did.
bool usable(const SteeringRequest& r, glm::vec3& weighted)
{
    weighted = r.force * r.weight;
    return isFinite(weighted);
}

}  // namespace

glm::vec3 blendWeighted(std::span<const SteeringRequest> requests, float maxForce)
{
    glm::vec3 sum(0.0f);
    for (const SteeringRequest& r : requests) {
        glm::vec3 f(0.0f);
        if (usable(r, f))
            sum += f;
    }
    return truncate(sum, maxForce);
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
