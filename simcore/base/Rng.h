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

// rng in two parts: the key of (seed, agent, step), then one stream of it, so several
// streams of one agent's step hash the key once. rngOf(rngKey(a, b, c), s) == rng(a, b, c, s).
inline std::uint64_t rngKey(std::uint64_t seed, std::uint64_t agentId, std::uint64_t step)
{
    std::uint64_t h = mix64(seed + 0x9e3779b97f4a7c15ull);
    h = mix64(h ^ (agentId + 0x632be59bd9b4e019ull));
    return mix64(h ^ (step + 0x85157af5ull));
}

inline std::uint64_t rngOf(std::uint64_t key, std::uint64_t stream)
{
    return mix64(key ^ (stream * 0xd6e8feb86659fd93ull));
}

inline std::uint64_t rng(std::uint64_t seed, std::uint64_t agentId, std::uint64_t step, std::uint64_t stream)
{
    return rngOf(rngKey(seed, agentId, step), stream);
}

// Uniform float in [lo, hi) from one stream of a key (the same number rngRange gives).
inline float rngRangeOf(std::uint64_t key, std::uint64_t stream, float lo, float hi)
{
    return lo + (hi - lo) * (float(rngOf(key, stream) >> 40) * (1.0f / 16777216.0f));
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
