#include "editor/tools/SelectTool.h"
#include "editor/SegmentDistance.h"

#include "editor/SceneDocument.h"
#include "editor/commands/ChangeValueCommand.h"
#include "editor/commands/MoveItemsCommand.h"
#include "editor/tools/BrushOverlay.h"
#include "editor/tools/SelectionGeometry.h"
#include "editor/viewport/Viewport.h"

#include <QKeyEvent>
#include <QPainter>
#include <QPolygonF>
#include <QRectF>

#include <algorithm>
#include <cmath>

namespace throng::editor {

namespace {

constexpr ItemKind kPointKinds[] = {ItemKind::Obstacle, ItemKind::Goal, ItemKind::ActionPoint, ItemKind::TrafficLight,
                                    ItemKind::Crosswalk};
// Drawn where the shown frame has them; at their scene place only while the frame lacks them.
constexpr ItemKind kMovingKinds[] = {ItemKind::Agent, ItemKind::Vehicle};
constexpr ItemKind kLineKinds[] = {ItemKind::Path, ItemKind::Wall, ItemKind::Lane, ItemKind::FlowStroke};
constexpr double kClickPx = 3.0;  // a box smaller than this is a click

double distancePx(QPointF a, QPointF b)
{
    return std::hypot(a.x() - b.x(), a.y() - b.y());
}

}  // namespace

QPointF SelectTool::pixelOf(glm::vec2 ground) const
{
    return viewport().worldToPixel({ground.x, 0.0f, ground.y});
}

sim::AgentId SelectTool::agentIdOf(SceneItem item) const
{
    const sim::Scene& s = document().scene();
    if (item.kind == ItemKind::Agent && item.index < s.agents.size())
        return s.agents[item.index].id;
    if (item.kind == ItemKind::Vehicle && item.index < s.vehicles.size())
        return s.vehicles[item.index].id;
    return 0;
}

bool SelectTool::inFrame(SceneItem item) const
{
    const std::size_t hint = item.kind == ItemKind::Agent ? item.index : ShownAgents::kNone;
    return viewport().shownAgents().holds(agentIdOf(item), hint);
}

std::optional<glm::vec3> SelectTool::shownAt(SceneItem item) const
{
    const ShownAgents& shown = viewport().shownAgents();
    const std::size_t i = shown.find(agentIdOf(item), item.kind == ItemKind::Agent ? item.index : ShownAgents::kNone);
    return i == ShownAgents::kNone || !shown.drawn(i) ? std::nullopt : std::optional<glm::vec3>(shown.feet(i));
}

std::optional<SelectTool::Hit> SelectTool::pick(QPointF pixel) const
{
    const sim::Scene& s = document().scene();
    std::optional<Hit> best;
    double bestPx = kPickPx;
    auto consider = [&](ItemKind kind, bool moving) {
        for (std::size_t i = 0; i < itemCount(s, kind); ++i) {
            if (moving && inFrame({kind, i}))
                continue;
            const std::optional<glm::vec2> anchor = itemAnchor(s, {kind, i});
            const double d = anchor ? distancePx(pixelOf(*anchor), pixel) : bestPx;
            if (d < bestPx) {
                bestPx = d;
                best = Hit{{kind, i}};
            }
        }
    };
    for (ItemKind kind : kPointKinds)
        consider(kind, false);
    for (ItemKind kind : kMovingKinds)
        consider(kind, true);
    if (const ShownAgents::Nearest agent = viewport().shownAgents().nearest(viewport().renderView(), pixel, kPickPx);
               agent.index != ShownAgents::kNone && (!best || agent.distancePx < bestPx)) {
        const sim::AgentId id = viewport().shownAgents().id(agent.index);
        if (const std::optional<SceneItem> item = agentItem(s, id)) {
            bestPx = agent.distancePx;
            best = Hit{*item, id};
        }
    }
    if (best)
        return best;
    for (ItemKind kind : kLineKinds)
        for (std::size_t i = 0; i < itemCount(s, kind); ++i)
            if (const std::optional<Segment> hit = segmentAt({kind, i}, pixel); hit && hit->distancePx < bestPx) {
                bestPx = hit->distancePx;
                best = Hit{{kind, i}};
            }
    // A source or a measurement is picked anywhere on its line or its outline.
    auto considerOutline = [&](SceneItem item, const std::vector<glm::vec2>& outline) {
        for (std::size_t k = 1; k < outline.size(); ++k)
            if (const double d = segmentDistancePx(pixel, pixelOf(outline[k - 1]), pixelOf(outline[k])); d < bestPx) {
                bestPx = d;
                best = Hit{item};
            }
    };
    for (std::size_t i = 0; i < s.sources.size(); ++i)
        considerOutline({ItemKind::Source, i}, sourceOutline(s.sources[i]));
    for (std::size_t i = 0; i < s.measurements.size(); ++i)
        considerOutline({ItemKind::Measurement, i}, measurementOutline(s.measurements[i]));
    return best;
}

// A closed path's last segment runs from its last point back to its first.
std::optional<SelectTool::Segment> SelectTool::segmentAt(SceneItem item, QPointF pixel) const
{
    const sim::Scene& s = document().scene();
    const std::span<const glm::vec2> line = itemPolyline(s, item);
    const bool closed = item.kind == ItemKind::Path && s.paths[item.index].closed && line.size() >= 3;
    std::optional<Segment> best;
    for (std::size_t k = 1; k < line.size() + (closed ? 1 : 0); ++k) {
        const double d = segmentDistancePx(pixel, pixelOf(line[k - 1]), pixelOf(line[k % line.size()]));
        if (d < kPickPx && (!best || d < best->distancePx))
            best = Segment{k, d};
    }
    return best;
}

// A double click on a segment of the one selected path, wall, lane or flow stroke
// inserts a point there.
void SelectTool::mouseDoubleClicked(const ToolMouse& mouse)
{
    const Selection& selection = document().selection();
    if (selection.size() != 1 || !mouse.ground)
        return;
    const SceneItem item = selection.front();
    const std::optional<Segment> hit = segmentAt(item, mouse.pixel);
    if (!hit)
        return;
    const sim::Scene& scene = document().scene();
    const std::span<const glm::vec2> line = itemPolyline(scene, item);
    std::vector<glm::vec2> points(line.begin(), line.end());
    points.insert(points.begin() + std::ptrdiff_t(hit->insertAt), glm::vec2(mouse.ground->x, mouse.ground->z));
    const QString key = QStringLiteral("insertPoint/%1/%2/%3").arg(int(item.kind)).arg(item.index).arg(++m_dragSerial);
    document().undoStack()->push(new ChangeValueCommand<std::vector<glm::vec2>>(
        document(), key, pointsOf(item), std::move(points), tr("Insert a point in %1").arg(itemLabel(scene, item)),
        SceneChange::of(item, SceneField::Position)));
    emit overlayChanged();
}

std::function<std::vector<glm::vec2>&(sim::Scene&)> SelectTool::pointsOf(SceneItem item)
{
    return [item](sim::Scene& s) -> std::vector<glm::vec2>& {
        return item.kind == ItemKind::Path   ? s.paths[item.index].points
               : item.kind == ItemKind::Wall ? s.walls[item.index].points
               : item.kind == ItemKind::Lane ? s.lanes[item.index].points
                                             : s.flowStrokes[item.index].points;
    };
}

bool SelectTool::pressHandle(const ToolMouse& mouse)
{
    for (const EditHandle& h : editHandles(document().scene(), document().selection()))
        if (distancePx(pixelOf(h.ground), mouse.pixel) <= kHandlePx) {
            m_drag = h.kind == EditHandle::Kind::Point ? Drag::Point : Drag::Radius;
            m_handleItem = h.item;
            m_handlePoint = h.point;
            return true;
        }
    return false;
}

void SelectTool::mousePressed(const ToolMouse& mouse)
{
    m_pushed = false;
    ++m_dragSerial;
    setState(State::Dragging);
    if (mouse.ground)
        m_lastGround = {mouse.ground->x, mouse.ground->z};
    if (mouse.ground && pressHandle(mouse))
        return;
    const std::optional<Hit> hit = pick(mouse.pixel);
    if (!hit) {
        m_drag = Drag::Box;
        m_boxStart = m_boxEnd = mouse.pixel;
        emit overlayChanged();
        return;
    }
    Selection selection = document().selection();
    const bool selected = std::find(selection.begin(), selection.end(), hit->item) != selection.end();
    if (mouse.modifiers & Qt::ShiftModifier) {
        if (!selected)
            selection.push_back(hit->item);
    } else if (!selected) {
        selection = {hit->item};
    }
    // Focus first: the selection change then keeps it (its item is selected).
    if (hit->agent != 0 || !(mouse.modifiers & Qt::ShiftModifier))
        viewport().setFocusedAgent(hit->agent);
    document().setSelection(selection);
    m_drag = mouse.ground ? Drag::Move : Drag::None;
    emit overlayChanged();
}

void SelectTool::mouseMoved(const ToolMouse& mouse)
{
    if (state() == State::Dragging)
        dragTo(mouse);
}

void SelectTool::dragTo(const ToolMouse& mouse)
{
    if (m_drag == Drag::Box) {
        m_boxEnd = mouse.pixel;
        emit overlayChanged();
        return;
    }
    if (!mouse.ground || m_drag == Drag::None)
        return;
    const glm::vec2 ground(mouse.ground->x, mouse.ground->z);
    QUndoStack* stack = document().undoStack();
    const sim::Scene& scene = document().scene();
    if (m_drag == Drag::Move) {
        const glm::vec2 delta = ground - m_lastGround;
        const Selection& selection = document().selection();
        // A vehicle stays on its lane: a drag of nothing movable pushes nothing.
        if (delta == glm::vec2(0.0f) || std::none_of(selection.begin(), selection.end(), [](SceneItem item) {
                return MoveItemsCommand::movable(item.kind);
            }))
            return;
        m_lastGround = ground;
        stack->push(new MoveItemsCommand(document(), document().selection(), delta, m_dragSerial));
        m_pushed = true;
    } else if (m_drag == Drag::Point) {
        std::span<const glm::vec2> line = itemPolyline(scene, m_handleItem);
        if (m_handlePoint >= line.size())
            return;
        std::vector<glm::vec2> points(line.begin(), line.end());
        points[m_handlePoint] = ground;
        const SceneItem item = m_handleItem;
        const QString key = QStringLiteral("points/%1/%2/%3").arg(int(item.kind)).arg(item.index).arg(m_dragSerial);
        stack->push(new ChangeValueCommand<std::vector<glm::vec2>>(
            document(), key, pointsOf(item), std::move(points), tr("Edit %1").arg(itemLabel(scene, item)),
            SceneChange::of(item, SceneField::Position)));
        m_pushed = true;
    } else if (m_drag == Drag::Radius) {
        const std::size_t i = m_handleItem.index;
        const float radius = std::max(0.05f, polylineDistance(scene.paths[i].points, ground));
        const QString key = QStringLiteral("pathRadius/%1/%2").arg(i).arg(m_dragSerial);
        stack->push(new ChangeValueCommand<float>(
            document(), key, [i](sim::Scene& s) -> float& { return s.paths[i].radiusM; }, radius,
            tr("Change radius of %1").arg(itemLabel(scene, m_handleItem)), SceneChange::of(m_handleItem, SceneField::Shape)));
        m_pushed = true;
    }
    emit overlayChanged();
}

void SelectTool::mouseReleased(const ToolMouse& mouse)
{
    if (state() != State::Dragging)
        return;
    dragTo(mouse);
    if (m_drag == Drag::Box)
        finishBox(mouse.modifiers);
    m_drag = Drag::None;
    setState(State::Idle);
    emit overlayChanged();
}

void SelectTool::finishBox(Qt::KeyboardModifiers modifiers)
{
    Selection selection = (modifiers & Qt::ShiftModifier) ? document().selection() : Selection{};
    if (distancePx(m_boxStart, m_boxEnd) >= kClickPx) {
        const QRectF box = QRectF(m_boxStart, m_boxEnd).normalized();
        const sim::Scene& s = document().scene();
        auto add = [&selection](SceneItem item) {
            if (std::find(selection.begin(), selection.end(), item) == selection.end())
                selection.push_back(item);
        };
        auto addInside = [&](ItemKind kind, bool moving) {
            for (std::size_t i = 0; i < itemCount(s, kind); ++i)
                if (const std::optional<glm::vec2> anchor = itemAnchor(s, {kind, i});
                    anchor && !(moving && inFrame({kind, i})) && box.contains(pixelOf(*anchor)))
                    add({kind, i});
        };
        for (ItemKind kind : kPointKinds)
            addInside(kind, false);
        for (ItemKind kind : kMovingKinds)
            addInside(kind, true);
        // A spawned agent inside the box brings its whole group.
        const ShownAgents& shown = viewport().shownAgents();
        for (std::size_t i : shown.inside(viewport().renderView(), box))
            if (const std::optional<SceneItem> item = agentItem(s, shown.id(i)))
                add(*item);
        for (ItemKind kind : kLineKinds)
            for (std::size_t i = 0; i < itemCount(s, kind); ++i) {
                const std::span<const glm::vec2> line = itemPolyline(s, {kind, i});
                if (!line.empty() && std::all_of(line.begin(), line.end(),
                                                 [&](glm::vec2 p) { return box.contains(pixelOf(p)); }))
                    add({kind, i});
            }
        auto inBox = [&](const std::vector<glm::vec2>& outline) {
            return std::all_of(outline.begin(), outline.end(), [&](glm::vec2 p) { return box.contains(pixelOf(p)); });
        };
        for (std::size_t i = 0; i < s.sources.size(); ++i)
            if (inBox(sourceOutline(s.sources[i])))
                add({ItemKind::Source, i});
        for (std::size_t i = 0; i < s.measurements.size(); ++i)
            if (inBox(measurementOutline(s.measurements[i])))
                add({ItemKind::Measurement, i});
    }
    document().setSelection(selection);
}

void SelectTool::cancel()
{
    // A drag pushes as it goes: taking it back leaves the scene as before the drag.
    if (m_drag != Drag::Box)
        revertDrag();
    m_pushed = false;
    m_drag = Drag::None;
    setState(State::Idle);
    emit overlayChanged();
}

void SelectTool::drawOverlay(QPainter& painter) const
{
    const sim::Scene& s = document().scene();
    for (const SceneItem& item : document().selection()) {
        const bool moving = std::find(std::begin(kMovingKinds), std::end(kMovingKinds), item.kind) != std::end(kMovingKinds);
        if (moving && inFrame(item)) {
            if (const std::optional<glm::vec3> p = shownAt(item))
                drawBrushCircle(painter, viewport(), *p, 0.6f, QColor(255, 230, 0));
        } else if (const std::optional<glm::vec2> p = itemAnchor(s, item)) {
            drawBrushCircle(painter, viewport(), {p->x, 0.0f, p->y}, 0.6f, QColor(255, 230, 0));
        }
    }
    painter.setPen(QPen(QColor(20, 20, 20), 1.0));
    for (const EditHandle& h : editHandles(s, document().selection())) {
        const QPointF at = pixelOf(h.ground);
        painter.setBrush(h.kind == EditHandle::Kind::Point ? QColor(255, 230, 0) : QColor(80, 200, 255));
        if (h.kind == EditHandle::Kind::Point)
            painter.drawRect(QRectF(at - QPointF(4, 4), QSizeF(8, 8)));
        else
            painter.drawPolygon(QPolygonF({at + QPointF(0, -6), at + QPointF(6, 0), at + QPointF(0, 6), at + QPointF(-6, 0)}));
    }
    if (m_drag == Drag::Box) {
        painter.setPen(QPen(QColor(255, 230, 0), 1.0, Qt::DashLine));
        painter.setBrush(QColor(255, 230, 0, 30));
        painter.drawRect(QRectF(m_boxStart, m_boxEnd).normalized());
    }
}

}  // namespace throng::editor
