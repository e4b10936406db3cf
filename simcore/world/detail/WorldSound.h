#pragma once
// Hearing for brains (internal to simcore/world): which channels a scene's brains listen
// to, who is heard on them, and what one agent hears on one channel. Reads the World's
// arrays and grid; writes only the caller's buffer.
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include "simcore/brain/NodeCatalogue.h"
#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"
#include "simcore/world/NeighbourGrid.h"
#include "simcore/world/detail/WorldBrains.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <span>

namespace throng::sim::detail {

// One source as a listener hears it.
struct Heard {
    float strength = 0.0f;  // 0..1: the source's strength × (1 - distance / its radius)
    float distanceM = 0.0f; // on the ground
    float bearingDeg = 0.0f;// from the listener's heading, + = left
};
constexpr std::size_t kMaxHeard = std::size_t(kBrainNeighbours);
using HeardList = std::array<Heard, kMaxHeard>;

// Fills wb.channels (beacons, the reach of emitting types, the emitting agents when few)
// for the channels in wb.channels' names, and wb.typeEmits / typeEmitStrength /
// typeEmitRadiusM. info: every agent of the World, by index.
void buildSoundChannels(WorldBrains& wb, const Scene& scene, std::span<const AgentInfo> info);

// The index of `name` in wb.channels, added when new.
std::uint32_t channelIndex(WorldBrains& wb, const std::string& name);

// The loudest sources (at most kMaxHeard, loudest first; ties: nearer first, then
// beacons in scene order before agents in index order) that agent `self` at p, heading f
// (unit), hears on channel c. Never hears itself, nor an agent that left (gone[j] != 0;
// an empty span: nobody left). positions: where the grid has the agents. Returns how many.
std::size_t hearChannel(const WorldBrains& wb, std::uint32_t c, const NeighbourGrid& grid,
                        std::span<const AgentInfo> info, std::span<const glm::vec3> positions,
                        std::span<const std::uint8_t> gone, std::size_t self, glm::vec2 p, glm::vec2 f,
                        HeardList& out);

}  // namespace throng::sim::detail
