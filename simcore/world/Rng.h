#pragma once
// Counter-based random numbers: a pure hash of (seed, agent id, step, stream), so any
// agent's numbers are the same whatever the thread count or order of evaluation.

#include <cstdint>

namespace throng::sim {

// SplitMix64 finaliser (Steele et al. 2014), applied to a combination of the keys.
inline std::uint64_t mix64(std::uint64_t z)
{
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

inline std::uint64_t rng(std::uint64_t seed, std::uint64_t agentId, std::uint64_t step, std::uint64_t stream)
{
    std::uint64_t h = mix64(seed + 0x9e3779b97f4a7c15ull);
    h = mix64(h ^ (agentId + 0x632be59bd9b4e019ull));
    h = mix64(h ^ (step + 0x85157af5ull));
    return mix64(h ^ (stream * 0xd6e8feb86659fd93ull));
}

// Uniform float in [0, 1) from the top 24 bits.
inline float rngUniform(std::uint64_t seed, std::uint64_t agentId, std::uint64_t step, std::uint64_t stream)
{
    return float(rng(seed, agentId, step, stream) >> 40) * (1.0f / 16777216.0f);
}

inline float rngRange(std::uint64_t seed, std::uint64_t agentId, std::uint64_t step, std::uint64_t stream,
                      float lo, float hi)
{
    return lo + (hi - lo) * rngUniform(seed, agentId, step, stream);
}

}  // namespace throng::sim
