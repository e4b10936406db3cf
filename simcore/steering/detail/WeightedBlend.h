#pragma once
// Weighted blending (Reynolds 1987), one request at a time: blendWeighted
// (SteeringCombination.h) sums a request list with it, and the walker kernel, which builds
// no list, adds each behaviour's force as it works it out. Internal to throng::simcore.
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include "simcore/steering/detail/SteeringMath.h"

#include <glm/vec3.hpp>

namespace throng::sim::detail {

class WeightedBlend {
public:
    // A request counts when its weighted force is finite. That alone also rules out a
    // non-finite weight or force: any infinity or NaN among them makes some product an
    // infinity or a NaN (0 * inf is NaN), so one test does what three would.
    [[gnu::always_inline]] void add(glm::vec3 force, float weight)
    {
        const glm::vec3 weighted = force * weight;
        if (isFinite(weighted))
            m_sum += weighted;
    }
    // The sum, truncated to maxForce (N, >= 0).
    [[gnu::always_inline]] glm::vec3 total(float maxForce) const { return truncate(m_sum, maxForce); }

private:
    glm::vec3 m_sum{0.0f};
};

}  // namespace throng::sim::detail
