#include "editor/tools/SelectTool.h"

#include "editor/commands/ChangeValueCommand.h"
#include "editor/tools/BrushOverlay.h"
#include "editor/viewport/Viewport.h"

#include <QPainter>

#include <algorithm>
#include <cmath>

namespace throng::editor {

namespace {

std::optional<glm::vec2> itemPosition(const sim::Scene& s, SceneItem item)
{
    switch (item.kind) {
    case ItemKind::Agent: return glm::vec2(s.agents[item.index].position.x, s.agents[item.index].position.z);
    case ItemKind::Obstacle: return s.obstacles[item.index].center;
    case ItemKind::Goal: return s.goals[item.index].position;
    case ItemKind::TrafficLight: return s.trafficLights[item.index].position;
    default: return std::nullopt;
    }
}

}  // namespace

std::optional<SceneItem> SelectTool::pick(QPointF pixel) const
{
    const sim::Scene& s = document().scene();
    std::optional<SceneItem> best;
    double bestPx = kPickPx;
    for (ItemKind kind : {ItemKind::Agent, ItemKind::Obstacle, ItemKind::Goal, ItemKind::TrafficLight}) {
        for (std::size_t i = 0; i < itemCount(s, kind); ++i) {
            const glm::vec2 p = *itemPosition(s, {kind, i});
            const QPointF at = viewport().worldToPixel({p.x, 0.0f, p.y});
            const double d = std::hypot(at.x() - pixel.x(), at.y() - pixel.y());
            if (d < bestPx) {
                bestPx = d;
                best = SceneItem{kind, i};
            }
        }
    }
    return best;
}

void SelectTool::mousePressed(const ToolMouse& mouse)
{
    const std::optional<SceneItem> hit = pick(mouse.pixel);
    Selection selection = (mouse.modifiers & Qt::ShiftModifier) ? document().selection() : Selection{};
    if (hit && std::find(selection.begin(), selection.end(), *hit) == selection.end())
        selection.push_back(*hit);
    document().setSelection(selection);
    m_dragged = hit;
    if (hit && mouse.ground) {
        m_grabOffset = *itemPosition(document().scene(), *hit) - glm::vec2(mouse.ground->x, mouse.ground->z);
        ++m_dragSerial;
        setState(State::Dragging);
    }
    emit overlayChanged();
}

void SelectTool::mouseMoved(const ToolMouse& mouse)
{
    if (state() == State::Dragging && m_dragged && mouse.ground)
        moveTo(glm::vec2(mouse.ground->x, mouse.ground->z) + m_grabOffset);
}

void SelectTool::mouseReleased(const ToolMouse& mouse)
{
    mouseMoved(mouse);
    m_dragged.reset();
    setState(State::Idle);
}

void SelectTool::cancel()
{
    m_dragged.reset();
    setState(State::Idle);
}

void SelectTool::moveTo(glm::vec2 to)
{
    const SceneItem item = *m_dragged;
    const std::size_t i = item.index;
    // One key per drag: the moves of one drag merge into a single undo step.
    const QString key = QStringLiteral("move/%1/%2/%3").arg(int(item.kind)).arg(i).arg(m_dragSerial);
    const QString text = tr("Move %1").arg(itemLabel(document().scene(), item));
    QUndoStack* stack = document().undoStack();
    if (item.kind == ItemKind::Agent) {
        const glm::vec3 old = document().scene().agents[i].position;
        stack->push(new ChangeValueCommand<glm::vec3>(
            document(), key, [i](sim::Scene& s) -> glm::vec3& { return s.agents[i].position; },
            glm::vec3(to.x, old.y, to.y), text));
        return;
    }
    ChangeValueCommand<glm::vec2>::Locate locate;
    if (item.kind == ItemKind::Obstacle)
        locate = [i](sim::Scene& s) -> glm::vec2& { return s.obstacles[i].center; };
    else if (item.kind == ItemKind::Goal)
        locate = [i](sim::Scene& s) -> glm::vec2& { return s.goals[i].position; };
    else
        locate = [i](sim::Scene& s) -> glm::vec2& { return s.trafficLights[i].position; };
    stack->push(new ChangeValueCommand<glm::vec2>(document(), key, locate, to, text));
}

void SelectTool::drawOverlay(QPainter& painter) const
{
    const sim::Scene& s = document().scene();
    for (const SceneItem& item : document().selection()) {
        if (item.index >= itemCount(s, item.kind))
            continue;
        if (const std::optional<glm::vec2> p = itemPosition(s, item))
            drawBrushCircle(painter, viewport(), {p->x, 0.0f, p->y}, 0.6f, QColor(255, 230, 0));
    }
}

}  // namespace throng::editor
