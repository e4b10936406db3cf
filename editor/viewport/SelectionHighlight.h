#pragma once
// Outlines the selected items in the selection colour: rings around agents, vehicles,
// obstacles, goals and lights, bands along paths, walls, lanes and flow strokes, a hero's
// way and a group's area; and the ring of the agent the brain editor inspects. Rings of
// agents and vehicles follow the shown frame. Builds ShapeMesh triangles from plain
// scene data and frames; never touches GL.

#include "editor/SceneItem.h"
#include "editor/viewport/ShapeMesh.h"
#include "editor/viewport/ShownAgents.h"
#include "simcore/world/FrameCache.h"

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include <cstddef>
#include <span>
#include <vector>

namespace throng::editor {

class SelectionHighlight {
public:
    // The inspected agent's ring: apart from the selection's yellow and every type colour.
    static constexpr glm::vec4 kInspectedColour{0.950f, 0.300f, 0.950f, 1.0f};

    // A ring round one World agent, drawn where the shown frame has it.
    struct AgentRing {
        std::size_t hint = ShownAgents::kNone;  // its likely World index (a placed agent's scene index)
        sim::AgentId id = 0;
        glm::vec2 start{0.0f};  // (x, z) in the scene: the ring's place while the frame lacks the agent
        float radiusM = 0.0f;   // 0: the shown body's radius plus the margin and `extraM` (no start)
        float extraM = 0.0f;
        glm::vec4 colour{1.0f};
    };

    // Everything selected but agents and vehicles.
    static void addItems(const sim::Scene& scene, const Selection& selection, ShapeMesh& mesh);
    // The rings of the selected placed agents and vehicles, and of the agents selected layout
    // operations name by id.
    static std::vector<AgentRing> agentRings(const sim::Scene& scene, const Selection& selection);
    // The ring that marks the agent the user clicked (a group's member too).
    static AgentRing focusRing(sim::AgentId id);
    // The ring of the brain editor's inspected agent, just outside a selection ring.
    static AgentRing inspectedRing(sim::AgentId id);
    // The ring of an agent the layout check flags on the shown frame, outside the others.
    static AgentRing clashRing(sim::AgentId id);
    // Each ring where `shown` draws its agent; an agent held but not drawn there has none
    // (it left or is absent); one the frame does not hold (no World, or a frame from
    // before the edit that added it) is ringed at its start.
    static void addAgentRings(std::span<const AgentRing> rings, const ShownAgents& shown, ShapeMesh& mesh);
};

}  // namespace throng::editor
