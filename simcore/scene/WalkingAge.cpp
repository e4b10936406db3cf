#include "simcore/scene/WalkingAge.h"

#include "simcore/base/Rng.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace throng::sim {

namespace {

// Weidmann's mean speed, m/s, at 10, 20, ..., 80 years.
constexpr std::array<float, 8> kSpeedByDecade{1.20f, 1.60f, 1.52f, 1.50f, 1.45f, 1.25f, 1.05f, 0.70f};

}  // namespace

float weidmannSpeedAtAge(float years)
{
    const float a = std::clamp(years, kWalkingAgeMinYears, kWalkingAgeMaxYears);
    const float at = (a - kWalkingAgeMinYears) / 10.0f;
    const std::size_t k = std::min(std::size_t(at), kSpeedByDecade.size() - 2);
    const float f = at - float(k);
    return kSpeedByDecade[k] + f * (kSpeedByDecade[k + 1] - kSpeedByDecade[k]);
}

float agentAgeYears(glm::vec2 ageRange, std::uint64_t seed, std::uint64_t id)
{
    return hasAge(ageRange) ? rngRange(seed, id, 0, kAgeStream, ageRange.x, ageRange.y) : 0.0f;
}

float ageSpeedFactor(glm::vec2 ageRange, std::uint64_t seed, std::uint64_t id)
{
    return hasAge(ageRange) ? weidmannSpeedAtAge(agentAgeYears(ageRange, seed, id)) / kWeidmannMeanSpeedMps
                            : 1.0f;
}

}  // namespace throng::sim
