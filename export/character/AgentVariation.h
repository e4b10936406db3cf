#pragma once
// How one agent differs from the others of its type: look, tint, colours of skin, hair,
// clothes and accessories, which accessories it wears, height, speed, gait phase.
// Drawn from a counter-based hash of (seed, agent id), so it is the same on every run and
// thread count and independent of the order agents are visited. Never stores state.

#include "export/character/Character.h"
#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"

#include <glm/vec3.hpp>

#include <array>

#include <cstddef>
#include <cstdint>
#include <span>

namespace throng::exporting {

struct AgentVariation {
    std::size_t look = 0;      // index into the type's looks (0 when it has one)
    int tint = -1;             // index into Variation::tints, -1 = untinted
    float heightScale = 1.0f;  // uniform scale of the whole character, > 0
    float speedFactor = 1.0f;  // the simulation's per-agent speed factor (with its age's), > 0
    float phaseOffset = 0.0f;  // gait cycles added at frame 0, in [0, 1]
    // Per material slot, an index into slotPalette(slot) (the top wears the tint instead).
    std::array<std::uint8_t, kMaterialSlotCount> colour{};
};

// The colours a material slot's parts come in (skin tones, hair, trousers, shoes, hats,
// bags), at least one each; the top's and the body's are the type's tints (empty here).
std::span<const glm::vec3> slotPalette(MaterialSlot slot);
// The top's colour for agents of a type with no tints: distinct per type, mid-bright.
glm::dvec3 untintedColour(std::size_t typeIndex);
// Whether the agent wears the mesh part: always for a part with wornShare 1, else drawn
// from the agent's own stream per slot (the same on every run, thread count and reader).
bool wearsPart(const MeshPart& part, std::uint64_t seed, std::uint32_t agentId);

// speedFactor and phaseOffset use the simulation's own draws (World), so the exported gait
// agrees with the recorded run; look, tint and height come from export streams.
AgentVariation drawVariation(const sim::Variation& variation, std::uint64_t seed, std::uint32_t agentId,
                             std::size_t lookCount);
// Replaces the drawn look, tint and height with those set by hand on the placed agent
// (sim::Agent::look, tint, heightScale), where they are set and in range.
void applyHandSetVariation(AgentVariation& variation, const sim::Agent& agent, std::size_t lookCount,
                           std::size_t tintCount);
// Then what a layout layer's swap shows instead (sim::AgentInfo::look, tint), where it is set
// and in range.
void applySwappedLook(AgentVariation& variation, const sim::AgentInfo& agent, std::size_t lookCount,
                      std::size_t tintCount);

}  // namespace throng::exporting
