#pragma once
// Running totals of the quality figures a user checks after a run (penetrations,
// overlaps, red-light violations, non-finite values). Plain data, summed per step.

#include <algorithm>
#include <array>
#include <cstdint>

namespace throng::sim {

// How deep overlapping bodies press into each other: per overlapping pair-step (the pairs
// overlappingPairs counts), the overlap r1 + r2 - d as a fraction of r1 + r2, in bins of
// half a percent (the last bin holds 99.5 % and deeper), and the deepest seen.
struct OverlapDepths {
    static constexpr int kBins = 200;
    static constexpr double kBinWidth = 1.0 / kBins;
    std::array<std::uint64_t, kBins> bins{};
    float deepest = 0.0f;

    void add(float fraction)
    {
        bins[std::size_t(std::clamp(int(fraction * float(kBins)), 0, kBins - 1))] += 1;
        deepest = std::max(deepest, fraction);
    }
    void add(const OverlapDepths& other)
    {
        for (int b = 0; b < kBins; ++b)
            bins[std::size_t(b)] += other.bins[std::size_t(b)];
        deepest = std::max(deepest, other.deepest);
    }
    // The upper edge of the bin that holds the q-quantile (0 < q <= 1); 0 without overlaps.
    double quantile(double q) const
    {
        std::uint64_t total = 0;
        for (const std::uint64_t n : bins)
            total += n;
        if (total == 0)
            return 0.0;
        const double rank = q * double(total);
        std::uint64_t seen = 0;
        for (int b = 0; b < kBins; ++b) {
            seen += bins[std::size_t(b)];
            if (double(seen) >= rank)
                return double(b + 1) * kBinWidth;
        }
        return 1.0;
    }
};

struct StepCounters {
    std::uint64_t wallPenetrations =
        0; // steered agents' moves whose centre crossed a wall segment (kerbs and box sides too)
    std::uint64_t obstaclePenetrations =
        0; // agent-steps ending with the body > 1 cm into a circle or box obstacle (heroes, vehicles too)
    std::uint64_t overlappingPairs = 0;      // pairs closer than the sum of radii less 1 cm, summed over steps
    std::uint64_t redLightViolations = 0;    // pedestrians stepping onto a crosswalk's road part on red
    std::uint64_t nonFiniteValues = 0;       // NaN/inf positions or velocities seen
    std::uint64_t leaderOvertaken = 0;       // follower-steps ahead of a moving leader (CountLeaders.cpp)
    std::uint64_t agentSteps = 0;
    OverlapDepths overlapDepths;             // how deep the overlapping pairs press in
    float peakDensity = 0.0f;                // persons/m², the highest local density sampled (LocalDensity.h)
    double peakDensityTimeS = -1.0;          // when it was seen; < 0 = never sampled
};

}  // namespace throng::sim
