#include "editor/tools/LayoutMoveTool.h"

#include "editor/SceneDocument.h"
#include "editor/layout/LayoutEdits.h"
#include "editor/tools/SelectionGeometry.h"
#include "editor/viewport/Viewport.h"
#include "simcore/scene/GroundPolygon.h"

#include <glm/geometric.hpp>

#include <QPainter>

#include <cmath>
#include <numbers>

namespace throng::editor {

namespace {

bool movesOrTurns(const sim::LayoutOp& op)
{
    return op.kind == sim::LayoutKind::Translate || op.kind == sim::LayoutKind::Rotate;
}

}  // namespace

std::optional<LayoutMoveTool::Target> LayoutMoveTool::target(bool turn) const
{
    const sim::Scene& scene = document().scene();
    const Selection& selection = document().selection();
    if (selection.size() == 1 && selection.front().kind == ItemKind::LayoutOp &&
        selection.front().index < scene.layout.ops.size()) {
        const sim::LayoutOp& op = scene.layout.ops[selection.front().index];
        if (!movesOrTurns(op))
            return std::nullopt;
        return Target{selection.front().index, op};
    }
    sim::AgentSelector agents = selectorFor(scene, selection);
    if (agents == sim::AgentSelector{})
        return std::nullopt;
    const auto kind = turn ? sim::LayoutKind::Rotate : sim::LayoutKind::Translate;
    return Target{std::nullopt, newLayoutOp(kind, std::move(agents), scene.layout, 0, 24.0, glm::vec2(0.0f))};
}

std::optional<glm::vec2> LayoutMoveTool::centreOf(const sim::LayoutOp& op) const
{
    const sim::Scene& scene = document().scene();
    std::vector<std::pair<sim::AgentId, sim::AgentId>> groups;
    for (const std::string& name : op.agents.groups)
        for (std::size_t g = 0; g < scene.groups.size(); ++g)
            if (scene.groups[g].name == name)
                groups.push_back(groupMemberIds(scene, g));
    const ShownAgents& shown = viewport().shownAgents();
    glm::dvec2 sum(0.0);
    std::size_t n = 0;
    for (std::size_t i = 0; i < shown.size(); ++i) {
        const sim::AgentId id = shown.id(i);
        const bool named = std::find(op.agents.ids.begin(), op.agents.ids.end(), id) != op.agents.ids.end() ||
                           std::any_of(groups.begin(), groups.end(),
                                       [id](const auto& r) { return id >= r.first && id < r.second; });
        if (!named || !shown.drawn(i))
            continue;
        sum += glm::dvec2(shown.feet(i).x, shown.feet(i).z);
        ++n;
    }
    if (n == 0)
        return std::nullopt;
    return glm::vec2(sum / double(n));
}

void LayoutMoveTool::mousePressed(const ToolMouse& mouse)
{
    if (!mouse.ground)
        return;
    if (mouse.modifiers & Qt::ControlModifier) {
        m_lasso = {{mouse.ground->x, mouse.ground->z}};
        setState(State::Dragging);
        emit overlayChanged();
        return;
    }
    m_target = target(mouse.modifiers & Qt::ShiftModifier);
    if (!m_target)
        return;
    m_press = m_now = {mouse.ground->x, mouse.ground->z};
    m_pressPixel = mouse.pixel;
    m_centre = centreOf(m_target->op).value_or(m_press);
    // A new turn goes about the centre the user sees; a turn without a pivot keeps its own.
    if (!m_target->index && m_target->op.kind == sim::LayoutKind::Rotate)
        m_target->op.pivot = m_centre;
    else if (m_target->op.kind == sim::LayoutKind::Rotate && m_target->op.pivot)
        m_centre = *m_target->op.pivot;
    m_moved = false;
    ++m_serial;
    setState(State::Dragging);
    emit overlayChanged();
}

void LayoutMoveTool::mouseMoved(const ToolMouse& mouse)
{
    if (state() != State::Dragging || !mouse.ground)
        return;
    if (!m_lasso.empty()) {
        const glm::vec2 p(mouse.ground->x, mouse.ground->z);
        if (glm::length(p - m_lasso.back()) >= kLassoStepM) {
            m_lasso.push_back(p);
            emit overlayChanged();
        }
        return;
    }
    const QPointF d = mouse.pixel - m_pressPixel;
    if (!m_moved && std::hypot(d.x(), d.y()) < kDeadPx)
        return;
    m_moved = true;
    apply({mouse.ground->x, mouse.ground->z});
}

void LayoutMoveTool::mouseReleased(const ToolMouse& mouse)
{
    if (state() != State::Dragging)
        return;
    if (!m_lasso.empty()) {
        setState(State::Idle);
        finishLasso();
        m_lasso.clear();
        emit overlayChanged();
        return;
    }
    if (m_moved && mouse.ground)
        apply({mouse.ground->x, mouse.ground->z});
    setState(State::Idle);
    const std::size_t edited = m_target->index.value_or(document().scene().layout.ops.size() - 1);
    if (m_moved && edited < document().scene().layout.ops.size())
        document().setSelection({{ItemKind::LayoutOp, edited}});
    m_target.reset();
    emit overlayChanged();
}

void LayoutMoveTool::apply(glm::vec2 ground)
{
    m_now = ground;
    sim::LayoutOp op = m_target->op;
    if (op.kind == sim::LayoutKind::Translate) {
        op.offset += m_now - m_press;
    } else {
        // The layer turns (x, z) by -angle in the usual orientation of the ground's axes
        // (LayoutApply's turned()): the mouse's turn about the centre, negated.
        const glm::vec2 a = m_press - m_centre, b = m_now - m_centre;
        if (glm::length(a) < 1e-3f || glm::length(b) < 1e-3f)
            return;
        const float turn = std::atan2(a.x * b.y - a.y * b.x, glm::dot(a, b));
        op.angleDeg -= turn * 180.0f / std::numbers::pi_v<float>;
    }
    sim::LayoutLayer after = document().scene().layout;
    if (m_target->index) {
        after.ops[*m_target->index] = op;
    } else {
        // The first step of the drag appends the operation; the later ones edit it.
        const bool added = after.ops.size() > 0 && after.ops.back().name == op.name;
        if (added)
            after.ops.back() = op;
        else
            after.ops.push_back(op);
    }
    const QString text = (op.kind == sim::LayoutKind::Translate ? tr("Move %1") : tr("Turn %1"))
                             .arg(QString::fromStdString(op.name));
    document().undoStack()->push(
        changeLayoutCommand(document(), std::move(after), text, QStringLiteral("layoutMove/%1").arg(m_serial)));
    emit overlayChanged();
}

void LayoutMoveTool::finishLasso()
{
    if (m_lasso.size() < 3 || sim::polygonSelfCrossing(m_lasso))
        return;
    const sim::Scene& scene = document().scene();
    sim::AgentSelector agents;
    agents.lasso = m_lasso;
    agents.lassoFrame = viewport().frameIndex();
    sim::LayoutLayer after = scene.layout;
    after.ops.push_back(newLayoutOp(sim::LayoutKind::Translate, std::move(agents), scene.layout, 0, 24.0, {}));
    const QString text = tr("Lasso %1").arg(QString::fromStdString(after.ops.back().name));
    document().undoStack()->push(changeLayoutCommand(document(), std::move(after), text));
    document().setSelection({{ItemKind::LayoutOp, document().scene().layout.ops.size() - 1}});
}

void LayoutMoveTool::cancel()
{
    m_lasso.clear();
    m_target.reset();
    m_moved = false;
    ViewportTool::cancel();
}

void LayoutMoveTool::drawOverlay(QPainter& painter) const
{
    if (!m_lasso.empty()) {
        QPolygonF outline;
        for (const glm::vec2 p : m_lasso)
            outline << viewport().worldToPixel({p.x, 0.0f, p.y});
        painter.setRenderHint(QPainter::Antialiasing);
        painter.setPen(QPen(QColor(255, 217, 26), 1.5, Qt::DashLine));
        painter.setBrush(QColor(255, 217, 26, 40));
        painter.drawPolygon(outline);
        return;
    }
    std::optional<sim::LayoutOp> op;
    glm::vec2 centre = m_centre;
    if (state() == State::Dragging && m_target) {
        op = m_target->op;
    } else {
        const Selection& selection = document().selection();
        const sim::Scene& scene = document().scene();
        if (selection.size() == 1 && selection.front().kind == ItemKind::LayoutOp &&
            selection.front().index < scene.layout.ops.size() &&
            movesOrTurns(scene.layout.ops[selection.front().index])) {
            op = scene.layout.ops[selection.front().index];
            const std::optional<glm::vec2> c = op->kind == sim::LayoutKind::Rotate && op->pivot ? op->pivot
                                                                                                : centreOf(*op);
            if (!c)
                return;
            centre = *c;
        }
    }
    if (!op)
        return;
    const QPointF at = viewport().worldToPixel({centre.x, 0.0f, centre.y});
    const QColor colour(255, 217, 26);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(colour, 2.0));
    painter.setBrush(Qt::NoBrush);
    if (op->kind == sim::LayoutKind::Rotate) {
        painter.drawEllipse(at, 28.0, 28.0);
        painter.drawLine(at + QPointF(-5, 0), at + QPointF(5, 0));
        painter.drawLine(at + QPointF(0, -5), at + QPointF(0, 5));
    } else {
        for (const QPointF d : {QPointF(1, 0), QPointF(-1, 0), QPointF(0, 1), QPointF(0, -1)}) {
            const QPointF tip = at + 24.0 * d, side(-d.y(), d.x());
            painter.drawLine(at, tip);
            painter.drawLine(tip, tip - 6.0 * d + 4.0 * side);
            painter.drawLine(tip, tip - 6.0 * d - 4.0 * side);
        }
    }
    if (state() == State::Dragging && m_moved) {
        painter.setPen(QPen(colour, 1.5, Qt::DashLine));
        painter.drawLine(viewport().worldToPixel({m_press.x, 0.0f, m_press.y}),
                         viewport().worldToPixel({m_now.x, 0.0f, m_now.y}));
    }
}

}  // namespace throng::editor
