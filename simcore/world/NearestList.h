#pragma once
// The k nearest candidates of a neighbour search (World::gatherNeighbours, the boids
// kernel), and the view-cone test of Reynolds (1987) both apply. Keys sort nearest first:
// the squared distance's bits in the high word (an optional flag in bit 63 sorts flagged
// candidates after the others), the agent index in the low word, so ties go by index and
// the result never depends on the order the grid visits candidates in. Where the World's
// ids do not rise with the index, a search watches for candidates at equal distances
// (insertWatchingTies) and, should it meet one, searches again with the agents' ranks in
// the low word instead (TieOrder.h): ties then go by id, and the result never depends on
// the order the World stores its agents in either.

#include "simcore/world/TieOrder.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>

namespace throng::sim {

// The sort key of candidate j (its index, or its rank: TieOrder::rank) at squared distance
// d2 (>= 0); `late` sorts it after every candidate without the flag.
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
    // The keys' low words are ranks (TieOrder::rank), not indices; set by the search.
    bool byRank = false;
    // (insertWatchingTies) A candidate came at the distance of the farthest kept.
    bool tied = false;

    NearestList() { clear(); }
    void clear()
    {
        count = 0;
        tied = false;
        keys.fill(~std::uint64_t(0));
    }
    bool full() const { return count == K; }
    // The n-th nearest's index.
    std::uint32_t index(std::size_t n, const TieOrder& ties) const
    {
        return byRank ? ties.index(std::uint32_t(keys[n])) : std::uint32_t(keys[n]);
    }
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
    // insert, noting a candidate that meets the farthest kept at the same distance (and
    // flag: the same high word), whether it is turned away or pushes that one out.
    bool insertWatchingTies(std::uint64_t key)
    {
        const std::uint64_t last = keys[K - 1];
        if (!(key < last)) {
            tied |= (key >> 32) == (last >> 32);
            return false;
        }
        insert(key);
        tied |= last != ~std::uint64_t(0) && (last >> 32) == (keys[K - 1] >> 32);
        return true;
    }
    // After a search by insertWatchingTies: whether two candidates met at the same
    // distance where it decided anything, among the kept (they lie side by side) or at
    // the farthest kept (a candidate turned away or pushed out there has its distance, or
    // it would be farther than a kept one, and so turned away without a tie).
    bool sawTie() const
    {
        bool same = tied;
        for (std::size_t a = 1; a < K; ++a)  // all K, without a branch: past count, a < count masks
            same |= (a < count) & ((keys[a] >> 32) == (keys[a - 1] >> 32));
        return same;
    }
};

// The end of a k-nearest search that began within guess2, last step's bound (Sense.h's
// lastNearestBound): search(startBound, byRank) clears `best`, sets its byRank and offers
// it the candidates within startBound. Searches again within the whole perception (whole2)
// when fewer than k lay within the guess, so the result is the same either way; and, where
// ids do not rise with the index (watch), again by rank should two candidates have met at
// one distance where it decided anything (TieOrder.h). Every k-nearest search ends here.
template <std::size_t K, class Search>
[[gnu::always_inline]] inline void finishNearest(NearestList<K>& best, float guess2, float whole2, bool watch,
                                                 Search&& search)
{
    if (!best.full() && guess2 < whole2)
        search(whole2, best.byRank);
    if (watch && !best.byRank && best.sawTie()) {
        search(guess2, true);
        if (!best.full() && guess2 < whole2)
            search(whole2, true);
    }
}

}  // namespace throng::sim
