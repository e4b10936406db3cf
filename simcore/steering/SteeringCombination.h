#pragma once
// Combining several behaviours' forces into one: weighted blending, and prioritised
// acceleration allocation (Reynolds 1987). Pure; never allocates; requests with a non-finite
// force or weight are skipped, so one broken behaviour cannot poison the sum.

#include "simcore/steering/SteeringRequestList.h"

#include <glm/vec3.hpp>

#include <span>

namespace throng::sim {

// Sum of weight * force over the requests, truncated to maxForce (N, >= 0).
glm::vec3 blendWeighted(std::span<const SteeringRequest> requests, float maxForce);

// Requests in priority order, each weight * force. Each takes its whole magnitude out of the budget
// maxForce while it fits; the first that does not fit is scaled down to what is left, and every
// later one is ignored. Zero requests take nothing, so a behaviour with nothing to say leaves the
// budget to the next. The result's magnitude is at most maxForce.
glm::vec3 allocateByPriority(std::span<const SteeringRequest> requests, float maxForce);

}  // namespace throng::sim
