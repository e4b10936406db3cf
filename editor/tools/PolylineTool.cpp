#include "editor/tools/PolylineTool.h"

#include "editor/SceneDocument.h"
#include "editor/viewport/Viewport.h"

#include <QKeyEvent>
#include <QPainter>
#include <QPolygonF>

namespace throng::editor {

void PolylineTool::mousePressed(const ToolMouse& mouse)
{
    if (!mouse.ground)
        return;
    m_cursor = mouse.ground;
    m_points.emplace_back(mouse.ground->x, mouse.ground->z);
    setState(State::Dragging);
    emit overlayChanged();
}

void PolylineTool::mouseMoved(const ToolMouse& mouse)
{
    m_cursor = mouse.ground;
    if (m_points.empty())
        setState(mouse.ground ? State::Hover : State::Idle);
    emit overlayChanged();
}

void PolylineTool::mouseDoubleClicked(const ToolMouse&)
{
    finish();
}

bool PolylineTool::keyPressed(QKeyEvent* event)
{
    switch (event->key()) {
    case Qt::Key_Return:
    case Qt::Key_Enter:
        finish();
        return true;
    case Qt::Key_Escape:
        cancel();
        return true;
    case Qt::Key_Backspace:
        if (m_points.empty())
            return false;
        m_points.pop_back();
        emit overlayChanged();
        return true;
    default:
        return false;
    }
}

void PolylineTool::finish()
{
    std::vector<glm::vec2> points = std::move(m_points);
    m_points.clear();
    setState(State::Idle);
    // A double-click leaves its point twice; a wall needs no zero-length piece.
    while (points.size() >= 2 && points[points.size() - 1] == points[points.size() - 2])
        points.pop_back();
    if (points.size() >= 2)
        add(points);
    emit overlayChanged();
}

void PolylineTool::cancel()
{
    m_points.clear();
    setState(State::Idle);
    emit overlayChanged();
}

void PolylineTool::drawOverlay(QPainter& painter) const
{
    QPolygonF line;
    for (glm::vec2 p : m_points)
        line << viewport().worldToPixel({p.x, 0.0f, p.y});
    if (m_cursor && !m_points.empty())
        line << viewport().worldToPixel(*m_cursor);
    painter.setPen(QPen(previewColour(), 2.0, Qt::DashLine));
    painter.drawPolyline(line);
    painter.setBrush(previewColour());
    for (int i = 0; i < int(m_points.size()); ++i)
        painter.drawEllipse(line[i], 3.0, 3.0);
}

}  // namespace throng::editor
