#pragma once
// Weighted blending (Reynolds 1987), one request at a time, for one agent or for several
// in the lanes of a vector (base/Lanes.h): blendWeighted (SteeringCombination.h) sums a
// request list with it, the walker kernel adds each behaviour's force as it works it out,
// and the boids kernel adds each behaviour's forces for four or eight boids at once.
// Internal to throng::simcore.
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include "simcore/base/Lanes.h"
#include "simcore/steering/detail/SteeringMath.h"

#include <glm/vec3.hpp>

#include <type_traits>

namespace throng::sim::detail {

// F: float (one agent, glm::vec3) or a vector of floats (Lanes3 of it), as BehaviourMath.h.
template <class F>
class WeightedBlendOf {
public:
    static constexpr bool kScalar = std::is_same_v<F, float>;
    using V3 = std::conditional_t<kScalar, glm::vec3, simd::Lanes3<F>>;

    // A request counts when its weighted force is finite. That alone also rules out a
    // non-finite weight or force: any infinity or NaN among them makes some product an
    // infinity or a NaN (0 * inf is NaN), so one test does what three would.
    [[gnu::always_inline]] void add(V3 force, F weight)
    {
        const V3 weighted = force * weight;
        if constexpr (kScalar) {
            if (isFinite(weighted))
                m_sum += weighted;
        } else {
            m_sum = simd::select(simd::finite(weighted), m_sum + weighted, m_sum);
        }
    }
    // In lanes: a request only in the lanes of `asks` (the others' behaviours are off or
    // have nothing to ask).
    template <class M>
    [[gnu::always_inline]] void add(V3 force, F weight, M asks)
        requires(!kScalar)
    {
        const V3 weighted = force * weight;
        m_sum = simd::select(asks & simd::finite(weighted), m_sum + weighted, m_sum);
    }
    // The sum, truncated to maxForce (N, >= 0).
    [[gnu::always_inline]] V3 total(F maxForce) const
    {
        if constexpr (kScalar)
            return truncate(m_sum, maxForce);
        else
            return simd::truncate(m_sum, maxForce);
    }

private:
    static V3 zero()
    {
        if constexpr (kScalar)
            return glm::vec3(0.0f);
        else
            return V3{};
    }
    V3 m_sum = zero();
};

using WeightedBlend = WeightedBlendOf<float>;

}  // namespace throng::sim::detail
