#include "export/character/AgentVariation.h"

#include "simcore/base/Rng.h"
#include "simcore/scene/WalkingAge.h"

#include <algorithm>

namespace throng::exporting {

namespace {

// World::addAgent's streams for the speed factor and the phase offset (World.cpp).
constexpr std::uint64_t kSimSpeedFactorStream = 4, kSimPhaseOffsetStream = 5;
// Streams of our own, far from the simulation's small integers.
constexpr std::uint64_t kLookStream = 0x4c4f4f4b, kTintStream = 0x54494e54, kHeightStream = 0x48454947;
constexpr std::uint64_t kColourStream = 0x434f4c00, kWornStream = 0x574f524e00;  // + the slot

constexpr glm::vec3 kSkin[] = {{0.95f, 0.79f, 0.68f}, {0.89f, 0.69f, 0.54f}, {0.78f, 0.57f, 0.42f},
                               {0.62f, 0.43f, 0.3f},  {0.45f, 0.3f, 0.2f},   {0.32f, 0.21f, 0.14f}};
constexpr glm::vec3 kHair[] = {{0.07f, 0.06f, 0.05f}, {0.2f, 0.13f, 0.08f}, {0.38f, 0.25f, 0.13f},
                               {0.74f, 0.6f, 0.36f},  {0.48f, 0.19f, 0.09f}};
constexpr glm::vec3 kGreyHair[] = {{0.76f, 0.76f, 0.75f}, {0.6f, 0.6f, 0.6f}, {0.88f, 0.87f, 0.85f}};
constexpr glm::vec3 kBottom[] = {{0.16f, 0.24f, 0.4f},  {0.08f, 0.08f, 0.09f}, {0.55f, 0.48f, 0.35f},
                                 {0.35f, 0.36f, 0.38f}, {0.1f, 0.12f, 0.22f},  {0.3f, 0.2f, 0.13f}};
constexpr glm::vec3 kShoes[] = {{0.05f, 0.05f, 0.05f}, {0.3f, 0.18f, 0.1f}, {0.85f, 0.85f, 0.85f}, {0.2f, 0.2f, 0.22f}};
constexpr glm::vec3 kHat[] = {{0.15f, 0.15f, 0.16f}, {0.55f, 0.45f, 0.3f}, {0.6f, 0.1f, 0.1f}, {0.2f, 0.3f, 0.5f}};
constexpr glm::vec3 kBag[] = {{0.1f, 0.25f, 0.2f}, {0.5f, 0.12f, 0.1f}, {0.15f, 0.15f, 0.15f}, {0.85f, 0.6f, 0.1f}};

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
    out.speedFactor = sim::rngRange(seed, agentId, 0, kSimSpeedFactorStream, v.speedFactor.x, v.speedFactor.y) *
                      sim::ageSpeedFactor(v.ageYears, seed, agentId);
    out.phaseOffset = sim::rngRange(seed, agentId, 0, kSimPhaseOffsetStream, v.phaseOffset.x, v.phaseOffset.y);
    for (int slot = 0; slot < kMaterialSlotCount; ++slot) {
        const std::size_t colours = slotPalette(static_cast<MaterialSlot>(slot)).size();
        const std::uint64_t stream = kColourStream + static_cast<std::uint64_t>(slot);
        if (colours > 1)
            out.colour[static_cast<std::size_t>(slot)] =
                static_cast<std::uint8_t>(pick(seed, agentId, stream, colours));
    }
    return out;
}

glm::dvec3 untintedColour(std::size_t typeIndex)
{
    static constexpr double kPalette[][3] = {{0.85, 0.33, 0.26}, {0.22, 0.55, 0.85}, {0.35, 0.72, 0.36},
                                             {0.92, 0.70, 0.20}, {0.60, 0.40, 0.78}, {0.25, 0.75, 0.75}};
    const double* rgb = kPalette[typeIndex % std::size(kPalette)];
    return {rgb[0], rgb[1], rgb[2]};
}

std::span<const glm::vec3> slotPalette(MaterialSlot slot)
{
    switch (slot) {
    case MaterialSlot::Skin: return kSkin;
    case MaterialSlot::Hair: return kHair;
    case MaterialSlot::GreyHair: return kGreyHair;
    case MaterialSlot::Bottom: return kBottom;
    case MaterialSlot::Shoes: return kShoes;
    case MaterialSlot::Hat: return kHat;
    case MaterialSlot::Bag: return kBag;
    case MaterialSlot::Body:
    case MaterialSlot::Top: break;
    }
    return {};
}

bool wearsPart(const MeshPart& part, std::uint64_t seed, std::uint32_t agentId)
{
    return part.wornShare >= 1.0f ||
           sim::rngUniform(seed, agentId, 0, kWornStream + static_cast<std::uint64_t>(part.slot)) < part.wornShare;
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

void applySwappedLook(AgentVariation& variation, const sim::AgentInfo& agent, std::size_t lookCount,
                      std::size_t tintCount)
{
    if (agent.look != sim::AgentInfo::kDrawnLook && agent.look < std::max<std::size_t>(1, lookCount))
        variation.look = agent.look;
    if (agent.tint == -1 || (agent.tint >= 0 && std::size_t(agent.tint) < tintCount))
        variation.tint = agent.tint;
}

}  // namespace throng::exporting
