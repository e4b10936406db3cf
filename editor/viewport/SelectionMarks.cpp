#include "editor/viewport/SelectionMarks.h"

#include "editor/tools/SelectionGeometry.h"

#include <algorithm>

namespace throng::editor {

void SelectionMarks::setSelection(const sim::Scene& scene, const Selection& selection)
{
    m_items.clear();
    SelectionHighlight::addItems(scene, selection, m_items);
    m_rings = SelectionHighlight::agentRings(scene, selection);
    m_itemsBox = {};
    for (const ShapeVertex& v : m_items.vertices())
        m_itemsBox.include({v.position.x, v.position.z});
    m_groupIds.clear();
    for (const SceneItem& item : selection) {
        if (item.kind == ItemKind::Group && item.index < scene.groups.size())
            m_groupIds.push_back(groupMemberIds(scene, item.index));
        // A layout operation's spawn groups: their members' trails show the edited paths.
        if (item.kind == ItemKind::LayoutOp && item.index < scene.layout.ops.size())
            for (const std::string& name : scene.layout.ops[item.index].agents.groups)
                for (std::size_t g = 0; g < scene.groups.size(); ++g)
                    if (scene.groups[g].name == name)
                        m_groupIds.push_back(groupMemberIds(scene, g));
    }
    if (m_focused != 0) {
        const std::optional<SceneItem> focused = agentItem(scene, m_focused);
        if (!focused || std::find(selection.begin(), selection.end(), *focused) == selection.end())
            m_focused = 0;
    }
}

void SelectionMarks::build(const ShownAgents& shown, ShapeMesh& mesh) const
{
    mesh = m_items;
    SelectionHighlight::addAgentRings(m_rings, shown, mesh);
    std::vector<SelectionHighlight::AgentRing> extra;
    if (m_focused != 0)
        extra.push_back(SelectionHighlight::focusRing(m_focused));
    if (m_inspected != 0)
        extra.push_back(SelectionHighlight::inspectedRing(m_inspected));
    for (const sim::AgentId id : m_flagged)
        extra.push_back(SelectionHighlight::clashRing(id));
    SelectionHighlight::addAgentRings(extra, shown, mesh);
}

void SelectionMarks::setLayoutClashes(const sim::LayoutCheck& check)
{
    m_clashes.clear();
    for (const auto* list : {&check.overlaps, &check.wallCrossings})
        for (const sim::LayoutClash& c : *list) {
            m_clashes.emplace_back(c.frame, c.agent);
            if (c.other != 0)
                m_clashes.emplace_back(c.frame, c.other);
        }
    std::sort(m_clashes.begin(), m_clashes.end());
    m_clashes.erase(std::unique(m_clashes.begin(), m_clashes.end()), m_clashes.end());
    m_flagged.clear();
}

void SelectionMarks::showFrame(std::size_t frame)
{
    m_flagged.clear();
    auto it = std::lower_bound(m_clashes.begin(), m_clashes.end(), std::make_pair(frame, sim::AgentId(0)));
    for (; it != m_clashes.end() && it->first == frame; ++it)
        m_flagged.push_back(it->second);
}

std::vector<sim::AgentId> SelectionMarks::watchedIds() const
{
    std::vector<sim::AgentId> ids;
    auto add = [&](sim::AgentId id) {
        if (id != 0 && std::find(ids.begin(), ids.end(), id) == ids.end())
            ids.push_back(id);
    };
    add(m_focused);
    add(m_inspected);
    for (const SelectionHighlight::AgentRing& r : m_rings)
        add(r.id);
    return ids;
}

std::vector<std::size_t> SelectionMarks::followed(const ShownAgents& shown, std::size_t max) const
{
    std::vector<std::size_t> indices;
    auto add = [&](std::size_t i) {
        if (i != ShownAgents::kNone && indices.size() < max && std::find(indices.begin(), indices.end(), i) == indices.end())
            indices.push_back(i);
    };
    for (const sim::AgentId id : {m_focused, m_inspected})
        if (id != 0)
            add(shown.find(id));
    for (const SelectionHighlight::AgentRing& r : m_rings)  // by their likely index first
        add(shown.find(r.id, r.hint));
    for (std::size_t i = 0; i < shown.size() && indices.size() < max && !m_groupIds.empty(); ++i) {
        const sim::AgentId id = shown.id(i);
        const bool member = std::any_of(m_groupIds.begin(), m_groupIds.end(),
                                        [id](const auto& ids) { return id >= ids.first && id < ids.second; });
        if (member)
            add(i);
    }
    return indices;
}

GroundBox SelectionMarks::extent(const ShownAgents& shown, float roomM) const
{
    GroundBox box = m_itemsBox;
    for (const SelectionHighlight::AgentRing& r : m_rings)
        if (const std::size_t i = shown.find(r.id, r.hint); i == ShownAgents::kNone)
            box.include(r.start, roomM);  // not in the frame yet: where the scene has it
        else if (shown.drawn(i))
            box.include({shown.feet(i).x, shown.feet(i).z}, roomM);
    if (m_groupIds.empty() && m_focused == 0)
        return box;
    for (std::size_t i = 0; i < shown.size(); ++i) {
        const sim::AgentId id = shown.id(i);
        const bool member = std::any_of(m_groupIds.begin(), m_groupIds.end(),
                                        [id](const auto& ids) { return id >= ids.first && id < ids.second; });
        if (shown.drawn(i) && (member || id == m_focused))
            box.include({shown.feet(i).x, shown.feet(i).z}, roomM);
    }
    return box;
}

}  // namespace throng::editor
