#pragma once
// What the viewport marks of the selection: the selected items' outlines, the rings of
// the selected agents and vehicles, the focused agent (the one the user clicked, a
// group's member too) and the brain editor's inspected agent, and the ground all of it
// covers in the shown frame, for framing. Plain data; never touches GL or edits the scene.

#include "editor/SceneItem.h"
#include "editor/viewport/GroundBox.h"
#include "editor/viewport/SelectionHighlight.h"
#include "editor/viewport/ShapeMesh.h"
#include "editor/viewport/ShownAgents.h"
#include "simcore/layout/LayoutCheck.h"
#include "simcore/world/FrameCache.h"

#include <utility>
#include <vector>

namespace throng::editor {

class SelectionMarks {
public:
    // Drops the focused agent when its item (placed agent, group, vehicle or hero) is no
    // longer selected.
    void setSelection(const sim::Scene& scene, const Selection& selection);
    void setFocusedAgent(sim::AgentId id) { m_focused = id; }
    sim::AgentId focusedAgent() const { return m_focused; }
    void setInspectedAgent(sim::AgentId id) { m_inspected = id; }
    sim::AgentId inspectedAgent() const { return m_inspected; }
    // The agents the layout check flags (sim::LayoutCheck), frame by frame; showFrame picks
    // the shown frame's, which get a ring of their own colour.
    void setLayoutClashes(const sim::LayoutCheck& check);
    void showFrame(std::size_t frame);
    // How many agents the shown frame flags.
    std::size_t flaggedCount() const { return m_flagged.size(); }
    // Whether some mark rings an agent, and so moves from frame to frame.
    bool followsAgents() const
    {
        return !m_rings.empty() || m_focused != 0 || m_inspected != 0 || !m_clashes.empty();
    }

    // The outlines, and the rings where `shown` has their agents.
    void build(const ShownAgents& shown, ShapeMesh& mesh) const;
    // The ground of the selected items, and of the selected agents, the focused one and the
    // selected groups' members where `shown` draws them (with `roomM` round each agent);
    // empty when nothing selected has a place.
    GroundBox extent(const ShownAgents& shown, float roomM) const;

    // The agents whose steering the user watches: the focused one, the inspected one and
    // the selected agents and vehicles, in that order, without repeats.
    std::vector<sim::AgentId> watchedIds() const;
    // Indices in `shown` of the agents trails follow: the watched ones and the selected
    // groups' members, at most `max`.
    std::vector<std::size_t> followed(const ShownAgents& shown, std::size_t max) const;

private:
    ShapeMesh m_items;  // the selection but its agents and vehicles
    GroundBox m_itemsBox;
    std::vector<SelectionHighlight::AgentRing> m_rings;
    std::vector<std::pair<sim::AgentId, sim::AgentId>> m_groupIds;  // selected groups' member ids
    sim::AgentId m_focused = 0, m_inspected = 0;
    std::vector<std::pair<std::size_t, sim::AgentId>> m_clashes;  // (frame, agent), sorted, without repeats
    std::vector<sim::AgentId> m_flagged;                          // the shown frame's
};

}  // namespace throng::editor
