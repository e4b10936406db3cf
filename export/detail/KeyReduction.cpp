#include "export/detail/KeyReduction.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::exporting::detail {

namespace {

template <typename Fits>
std::vector<std::uint32_t> greedy(std::size_t n, Fits&& fits)
{
    std::vector<std::uint32_t> keep;
    if (n == 0)
        return keep;
    keep.push_back(0);
    std::size_t a = 0;
    while (a + 1 < n) {
        std::size_t b = a + 1;
        while (b + 1 < n && b + 1 - a <= kMaxKeyGap && fits(a, b + 1))
            ++b;
        keep.push_back(static_cast<std::uint32_t>(b));
        a = b;
    }
    return keep;
}

}  // namespace

// A channel that holds still needs its ends only; checked in one pass, since the greedy
// search costs a window's square on long still stretches.
std::vector<std::uint32_t> endsOnly(std::size_t n)
{
    if (n <= 1)
        return std::vector<std::uint32_t>(n, 0);
    return {0, static_cast<std::uint32_t>(n - 1)};
}

std::vector<std::uint32_t> keepVec3Keys(std::span<const float> times, std::span<const glm::vec3> keys, float toleranceM)
{
    const float tol2 = toleranceM * toleranceM;
    // Within half the tolerance of the first key, every key is within it of the line between the ends.
    if (std::all_of(keys.begin(), keys.end(), [&](const glm::vec3& k) { return glm::dot(k - keys[0], k - keys[0]) <= 0.25f * tol2; }))
        return endsOnly(keys.size());
    return greedy(keys.size(), [&](std::size_t a, std::size_t c) {
        const float span = times[c] - times[a];
        for (std::size_t k = a + 1; k < c; ++k) {
            const float t = (times[k] - times[a]) / span;
            const glm::vec3 d = keys[a] + (keys[c] - keys[a]) * t - keys[k];
            if (glm::dot(d, d) > tol2)
                return false;
        }
        return true;
    });
}

std::vector<std::uint32_t> keepRotationKeys(std::span<const float> times, std::span<const glm::quat> keys,
                                            float toleranceRad)
{
    // |dot| of unit quaternions is the cosine of half the angle between them.
    const float minDot = std::cos(0.5f * toleranceRad);
    const float stillDot = std::cos(0.25f * toleranceRad);
    if (std::all_of(keys.begin(), keys.end(), [&](const glm::quat& k) { return std::abs(glm::dot(k, keys[0])) >= stillDot; }))
        return endsOnly(keys.size());
    return greedy(keys.size(), [&](std::size_t a, std::size_t c) {
        const float span = times[c] - times[a];
        glm::quat end = keys[c];
        if (glm::dot(keys[a], end) < 0.0f)
            end = -end;
        for (std::size_t k = a + 1; k < c; ++k) {
            const float t = (times[k] - times[a]) / span;
            const glm::quat q = glm::normalize(glm::quat(keys[a].w + (end.w - keys[a].w) * t, keys[a].x + (end.x - keys[a].x) * t,
                                                         keys[a].y + (end.y - keys[a].y) * t, keys[a].z + (end.z - keys[a].z) * t));
            if (std::abs(glm::dot(q, keys[k])) < minDot)
                return false;
        }
        return true;
    });
}

}  // namespace throng::exporting::detail
