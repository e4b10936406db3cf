#pragma once
// Reads the recorded frames as a researcher's trajectory data: which cache agents are
// walkers, and each one's ground position (x, z) in scene coordinates on a frame (the
// cache's origin added back, in double). Reads a FrameCache; never changes it.

#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"

#include <glm/vec2.hpp>

#include <cstddef>
#include <vector>

namespace throng::sim {

// Where a recorded agent stands on frame f in scene coordinates (x, z).
inline glm::dvec2 groundPosition(const FrameCache& cache, std::size_t f, std::size_t agent)
{
    const glm::vec3 p = cache.at(f, agent).position;
    return {double(p.x) + cache.origin().x, double(p.z) + cache.origin().z};
}

// Whether the agent exists on frame f and has not left through an exit.
inline bool inShot(const AgentFrame& a) { return a.present && !a.out; }

// Which agents are walkers (their type is a pedestrian type), frame by frame: look up a
// frame's agents once (FrameCache::agentsAt), then ask per agent.
class WalkerTypes {
public:
    explicit WalkerTypes(const Scene& scene)
    {
        for (const AgentType& t : scene.agentTypes)
            m_walker.push_back(t.kind == AgentKind::Pedestrian ? 1 : 0);
    }
    bool operator()(const std::vector<AgentInfo>& agentsOnFrame, std::size_t agent) const
    {
        const std::uint16_t type = agentsOnFrame[agent].typeIndex;
        return type < m_walker.size() && m_walker[type] != 0;
    }

private:
    std::vector<char> m_walker;
};

}  // namespace throng::sim
