#include "editor/commands/MoveItemsCommand.h"

#include "editor/SceneDocument.h"
#include "editor/commands/CommandIds.h"

#include <QCoreApplication>

#include <type_traits>

namespace throng::editor {

namespace {

// Every ground point of an item, in a fixed order, read or written through `visit`.
template <class Scene, class Visit>
void forEachPoint(Scene& s, SceneItem item, Visit visit)
{
    const std::size_t i = item.index;
    switch (item.kind) {
    case ItemKind::Agent: {
        glm::vec2 p(s.agents[i].position.x, s.agents[i].position.z);
        visit(p);
        if constexpr (!std::is_const_v<Scene>) {
            s.agents[i].position.x = p.x;
            s.agents[i].position.z = p.y;
        }
        return;
    }
    case ItemKind::Obstacle: visit(s.obstacles[i].center); return;
    case ItemKind::Goal: visit(s.goals[i].position); return;
    case ItemKind::ActionPoint: visit(s.actionPoints[i].position); return;
    case ItemKind::TrafficLight: visit(s.trafficLights[i].position); return;
    case ItemKind::Path: for (auto& p : s.paths[i].points) visit(p); return;
    case ItemKind::Wall: for (auto& p : s.walls[i].points) visit(p); return;
    case ItemKind::Lane: for (auto& p : s.lanes[i].points) visit(p); return;
    case ItemKind::FlowStroke: for (auto& p : s.flowStrokes[i].points) visit(p); return;
    case ItemKind::Measurement: for (auto& p : s.measurements[i].points) visit(p); return;
    case ItemKind::Crosswalk: visit(s.crosswalks[i].from); visit(s.crosswalks[i].to); return;
    case ItemKind::Source: {
        // Only the shape's own points, as for a group: the other pair is not written.
        auto& src = s.sources[i];
        if (src.shape == sim::SourceShape::Line) {
            visit(src.from);
            visit(src.to);
        } else {
            visit(src.min);
            visit(src.max);
        }
        return;
    }
    case ItemKind::Group: {
        // Only the shape's own points: the others are not written and must not drift.
        auto& g = s.groups[i];
        if (g.shape == sim::AreaShape::Rect) {
            visit(g.min);
            visit(g.max);
        } else if (g.shape == sim::AreaShape::Circle) {
            visit(g.center);
        } else {
            for (auto& p : g.points) visit(p);
        }
        return;
    }
    default: return;
    }
}

}  // namespace

bool MoveItemsCommand::movable(ItemKind kind)
{
    switch (kind) {
    case ItemKind::Agent:
    case ItemKind::Obstacle:
    case ItemKind::Goal:
    case ItemKind::ActionPoint:
    case ItemKind::TrafficLight:
    case ItemKind::Path:
    case ItemKind::Wall:
    case ItemKind::Lane:
    case ItemKind::FlowStroke:
    case ItemKind::Crosswalk:
    case ItemKind::Source:
    case ItemKind::Measurement:
    case ItemKind::Group: return true;
    default: return false;
    }
}

MoveItemsCommand::MoveItemsCommand(SceneDocument& document, Selection items, glm::vec2 offsetM, int dragId)
    : m_document(document), m_offset(offsetM), m_dragId(dragId)
{
    const sim::Scene& scene = document.scene();
    for (const SceneItem& item : items) {
        if (!movable(item.kind) || item.index >= itemCount(scene, item.kind))
            continue;
        m_items.push_back(item);
        std::vector<glm::vec2> points;
        forEachPoint(scene, item, [&points](const glm::vec2& p) { points.push_back(p); });
        m_original.push_back(std::move(points));
    }
    setText(m_items.size() == 1 ? QCoreApplication::translate("MoveItemsCommand", "Move %1").arg(itemLabel(scene, m_items[0]))
                                : QCoreApplication::translate("MoveItemsCommand", "Move %n item(s)", nullptr,
                                                              int(m_items.size())));
}

void MoveItemsCommand::place(bool moved)
{
    SceneChange change;
    for (const SceneItem& item : m_items)
        change |= SceneChange::of(item, SceneField::Position);
    m_document.modify(change, [this, moved](sim::Scene& s) {
        for (std::size_t k = 0; k < m_items.size(); ++k) {
            std::size_t n = 0;
            forEachPoint(s, m_items[k], [&](glm::vec2& p) {
                p = m_original[k][n++] + (moved ? m_offset : glm::vec2(0.0f));
            });
        }
    });
}

void MoveItemsCommand::redo()
{
    place(true);
}

void MoveItemsCommand::undo()
{
    place(false);
}

int MoveItemsCommand::id() const
{
    return kMoveItemsId;
}

bool MoveItemsCommand::mergeWith(const QUndoCommand* other)
{
    const auto* next = static_cast<const MoveItemsCommand*>(other);
    if (next->m_dragId != m_dragId || &next->m_document != &m_document || next->m_items != m_items)
        return false;
    // The next move is relative to where this one left the items.
    m_offset += next->m_offset;
    setObsolete(m_offset == glm::vec2(0.0f));
    return true;
}

}  // namespace throng::editor
