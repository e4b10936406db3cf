#pragma once
// Local crowd density, persons per m²: at a pedestrian's centre, the pedestrians' centres
// (its own included) summed with a Gaussian kernel of kDensitySigmaM, cut off at
// kDensityReachM = 3 sigma and scaled so the kernel still holds one person. Over a crowd
// of even density it gives that density (a touching hexagonal packing of discs of radius r
// gives 1 / (2 sqrt(3) r²): 3.21 for r = 0.3 m, 4.62 for r = 0.25 m); no count in a
// circle jumps as a ring of neighbours crosses its edge. Pure, no state.

#include <cmath>

namespace throng::sim {

inline constexpr float kDensitySigmaM = 0.5f;
inline constexpr float kDensityReachM = 3.0f * kDensitySigmaM;
// The peak is looked for at this interval of simulated time (the first step at or after
// each multiple of it), the same instants at any frame rate.
inline constexpr double kDensitySampleS = 0.5;

// One person at squared distance d2 (m²) adds this to the density, persons/m².
inline float densityWeight(float d2)
{
    constexpr float twoSigma2 = 2.0f * kDensitySigmaM * kDensitySigmaM;
    // exp(-4.5): the share of the kernel beyond 3 sigma, left out and made up for.
    static const float norm = 1.0f / (3.14159265f * twoSigma2 * (1.0f - std::exp(-4.5f)));
    return d2 < kDensityReachM * kDensityReachM ? std::exp(-d2 / twoSigma2) * norm : 0.0f;
}

// Whether the step that ends at step index `step` (of `dtS` each) is a density sample.
inline bool densitySampleDue(unsigned long long step, double dtS)
{
    if (step == 0 || !(dtS > 0.0))
        return false;
    auto sample = [&](unsigned long long s) { return std::floor(double(s) * dtS / kDensitySampleS + 1e-6); };
    return sample(step) > sample(step - 1);
}

}  // namespace throng::sim
