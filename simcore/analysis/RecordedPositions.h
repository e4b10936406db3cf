#pragma once
// Reads the recorded frames as a researcher's trajectory data: which cache agents are
// walkers, and each one's ground position (x, z) in scene coordinates on a frame (the
// cache's origin added back, in double). Reads a FrameCache; never changes it.

#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"

#include <glm/vec2.hpp>

#include <cstddef>

namespace throng::sim {

// Where a recorded agent stands on frame f in scene coordinates (x, z).
inline glm::dvec2 groundPosition(const FrameCache& cache, std::size_t f, std::size_t agent)
{
    const glm::vec3 p = cache.at(f, agent).position;
    return {double(p.x) + cache.origin().x, double(p.z) + cache.origin().z};
}

// Whether the agent exists on frame f and has not left through an exit.
inline bool inShot(const AgentFrame& a) { return a.present && !a.out; }

// Whether cache agent `agent` is a walker on frame f (its type is a pedestrian type).
inline bool isWalkerAt(const Scene& scene, const FrameCache& cache, std::size_t f, std::size_t agent)
{
    const std::uint16_t type = cache.agentsAt(f)[agent].typeIndex;
    return type < scene.agentTypes.size() && scene.agentTypes[type].kind == AgentKind::Pedestrian;
}

}  // namespace throng::sim
