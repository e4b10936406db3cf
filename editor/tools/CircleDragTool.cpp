#include "editor/tools/CircleDragTool.h"

#include "editor/tools/BrushOverlay.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <cmath>

namespace throng::editor {

float CircleDragTool::radiusTo(const ToolMouse& mouse) const
{
    if (!mouse.ground)
        return m_radiusM;
    const float r = glm::length(glm::vec2(mouse.ground->x - m_centre.x, mouse.ground->z - m_centre.z));
    return r < clickRadiusM() ? defaultRadiusM() : r;
}

void CircleDragTool::mousePressed(const ToolMouse& mouse)
{
    if (!mouse.ground)
        return;
    m_centre = *mouse.ground;
    m_radiusM = defaultRadiusM();
    setState(State::Dragging);
    emit overlayChanged();
}

void CircleDragTool::mouseMoved(const ToolMouse& mouse)
{
    if (state() != State::Dragging)
        return;
    m_radiusM = radiusTo(mouse);
    emit overlayChanged();
}

void CircleDragTool::mouseReleased(const ToolMouse& mouse)
{
    if (state() != State::Dragging)
        return;
    m_radiusM = radiusTo(mouse);
    m_headingDeg.reset();
    if (mouse.ground) {
        const glm::vec2 d(mouse.ground->x - m_centre.x, mouse.ground->z - m_centre.z);
        if (glm::length(d) >= clickRadiusM())
            m_headingDeg = glm::degrees(std::atan2(-d.y, d.x));
    }
    setState(State::Idle);
    place({m_centre.x, m_centre.z}, m_radiusM);
    emit overlayChanged();
}

void CircleDragTool::drawOverlay(QPainter& painter) const
{
    if (state() == State::Dragging)
        drawBrushCircle(painter, viewport(), m_centre, m_radiusM, previewColour());
}

}  // namespace throng::editor
