#include "export/character/AgentVariation.h"

#include "simcore/base/Rng.h"

#include <algorithm>

namespace throng::exporting {

namespace {

// World::addAgent's streams for the speed factor and the phase offset (World.cpp).
constexpr std::uint64_t kSimSpeedFactorStream = 4, kSimPhaseOffsetStream = 5;
// Streams of our own, far from the simulation's small integers.
constexpr std::uint64_t kLookStream = 0x4c4f4f4b, kTintStream = 0x54494e54, kHeightStream = 0x48454947;

std::size_t pick(std::uint64_t seed, std::uint32_t id, std::uint64_t stream, std::size_t count)
{
    const auto i = static_cast<std::size_t>(sim::rngUniform(seed, id, 0, stream) * static_cast<float>(count));
    return std::min(i, count - 1);
}

}  // namespace

AgentVariation drawVariation(const sim::Variation& v, std::uint64_t seed, std::uint32_t agentId, std::size_t lookCount)
{
    AgentVariation out;
    out.look = lookCount > 1 ? pick(seed, agentId, kLookStream, lookCount) : 0;
    out.tint = v.tints.empty() ? -1 : static_cast<int>(pick(seed, agentId, kTintStream, v.tints.size()));
    out.heightScale = sim::rngRange(seed, agentId, 0, kHeightStream, v.heightScale.x, v.heightScale.y);
    out.speedFactor = sim::rngRange(seed, agentId, 0, kSimSpeedFactorStream, v.speedFactor.x, v.speedFactor.y);
    out.phaseOffset = sim::rngRange(seed, agentId, 0, kSimPhaseOffsetStream, v.phaseOffset.x, v.phaseOffset.y);
    return out;
}

void applyHandSetVariation(AgentVariation& variation, const sim::Agent& agent, std::size_t lookCount,
                           std::size_t tintCount)
{
    if (agent.look >= 0 && std::size_t(agent.look) < std::max<std::size_t>(1, lookCount))
        variation.look = std::size_t(agent.look);
    if (agent.tint >= 0 && std::size_t(agent.tint) < tintCount)
        variation.tint = agent.tint;
    if (agent.heightScale > 0.0f)
        variation.heightScale = agent.heightScale;
}

}  // namespace throng::exporting
