#pragma once
// The k nearest candidates of a neighbour search (World::gatherNeighbours, the boids
// kernel), and the view-cone test of Reynolds (1987) both apply. Keys sort nearest first:
// the squared distance's bits in the high word (an optional flag in bit 63 sorts flagged
// candidates after the others), the agent index in the low word, so ties go by index and
// the result never depends on the order the grid visits candidates in.

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>

namespace throng::sim {

// The sort key of candidate j at squared distance d2 (>= 0); `late` sorts it after every
// candidate without the flag.
inline std::uint64_t nearestKey(float d2, std::uint32_t j, bool late = false)
{
    const std::uint64_t flag = late ? std::uint64_t(1) << 63 : 0;
    return flag | (std::uint64_t(std::bit_cast<std::uint32_t>(d2 + 0.0f)) << 32) | j;
}

// Whether offset d (squared length d2) lies outside the view cone around the unit forward
// axis fwd whose half angle has cosine c (c <= -1: all round). Done on squares, so no
// square root per candidate: dot(d, fwd) < c |d|.
inline bool outsideViewCone(const glm::vec3& d, float d2, const glm::vec3& fwd, float c)
{
    if (c <= -1.0f)
        return false;
    const float dot = glm::dot(d, fwd);
    const float c2d2 = c * c * d2;
    return c >= 0.0f ? (dot < 0.0f || dot * dot < c2d2) : (dot < 0.0f && dot * dot > c2d2);
}

template <std::size_t K>
struct NearestList {
    std::array<std::uint64_t, K> keys;  // the first `count` are valid, ascending; the rest all ones
    std::size_t count = 0;

    NearestList() { clear(); }
    void clear()
    {
        count = 0;
        keys.fill(~std::uint64_t(0));
    }
    bool full() const { return count == K; }
    std::uint32_t index(std::size_t n) const { return std::uint32_t(keys[n]); }
    // The squared distance of the farthest kept candidate (its flag masked off).
    float worstDistance2() const { return std::bit_cast<float>(std::uint32_t(keys[K - 1] >> 32) & 0x7fffffffu); }

    // Keeps `key` (never all ones) if it is among the K smallest so far; returns whether
    // it was kept. Without branches on where it goes (each slot takes the larger of its
    // key and the new one, or its left neighbour's key): the place of a near neighbour
    // among the others is what a branch cannot predict.
    bool insert(std::uint64_t key)
    {
        if (!(key < keys[K - 1]))
            return false;
        for (std::size_t a = K - 1; a > 0; --a) {
            const std::uint64_t left = keys[a - 1], here = keys[a];
            keys[a] = key < left ? left : (key < here ? key : here);
        }
        keys[0] = key < keys[0] ? key : keys[0];
        count += count < K ? 1 : 0;
        return true;
    }
};

}  // namespace throng::sim
