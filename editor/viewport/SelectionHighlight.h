#pragma once
// Outlines the selected items in the selection colour: rings around agents, obstacles,
// goals and lights, bands along paths, walls, lanes and flow strokes, a hero's way and a
// group's area. Agents' rings follow the shown frame during playback. Builds ShapeMesh
// triangles from plain scene data and frames; never touches GL.

#include "editor/SceneItem.h"
#include "editor/viewport/ShapeMesh.h"
#include "simcore/world/FrameCache.h"

#include <glm/vec2.hpp>

#include <cstddef>
#include <span>
#include <vector>

namespace throng::editor {

class SelectionHighlight {
public:
    // A selected placed agent: its World index is its scene index (placed agents come
    // first in the World, in scene order) while the shown frame's id there matches.
    struct AgentRing {
        std::size_t index = 0;
        sim::AgentId id = 0;
        glm::vec2 start{0.0f};  // (x, z) in the scene
        float radiusM = 0.0f;
    };

    // Everything selected, agents at their scene (start) positions.
    static void add(const sim::Scene& scene, const Selection& selection, ShapeMesh& mesh);
    // Everything selected but agents.
    static void addItems(const sim::Scene& scene, const Selection& selection, ShapeMesh& mesh);
    static std::vector<AgentRing> agentRings(const sim::Scene& scene, const Selection& selection);
    // Rings where the shown frame has the agents (`ids` and `positionsXZ` by World index);
    // an agent the frame does not hold keeps its start position.
    static void addAgentRings(std::span<const AgentRing> rings, std::span<const sim::AgentId> ids,
                              std::span<const glm::vec2> positionsXZ, ShapeMesh& mesh);
};

}  // namespace throng::editor
