// The viewport's input: the left button goes to the active tool, keys to the tool first.
// Alt with any button, the middle and the right button drag the camera (CameraDrag says
// how). The wheel zooms towards the cursor. F frames the selection, A everything.
#include "editor/viewport/Viewport.h"

#include "editor/viewport/ToolOverlay.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QResizeEvent>
#include <QWheelEvent>

#include <cmath>
#include <optional>

namespace throng::editor {

namespace {
constexpr float kWheelZoomPerDegree = 1.01f;  // one 15-degree notch zooms by about 16 %
}  // namespace

void Viewport::forwardToTool(QMouseEvent* event, void (ViewportTool::*handler)(const ToolMouse&))
{
    const ToolMouse mouse{event->position(), pixelToGround(event->position()), event->modifiers()};
    (m_tool->*handler)(mouse);
    event->accept();
}

void Viewport::mousePressEvent(QMouseEvent* event)
{
    // Alt+any button belongs to the camera, never to the tool (a DCC user's reflex).
    const bool alt = event->modifiers() & Qt::AltModifier;
    if (alt && !m_drag.active() && !m_toolDragging) {
        m_drag.begin(event->button(), true, event->position(), pixelToGround(event->position()));
        event->accept();
        return;
    }
    if (event->button() == Qt::LeftButton && m_tool && !m_drag.active()) {
        m_toolDragging = true;
        forwardToTool(event, &ViewportTool::mousePressed);
        return;
    }
    if (event->button() == Qt::MiddleButton || event->button() == Qt::RightButton) {
        m_drag.begin(event->button(), false, event->position(), std::nullopt);
        event->accept();
        return;
    }
    QOpenGLWidget::mousePressEvent(event);
}

void Viewport::mouseMoveEvent(QMouseEvent* event)
{
    if (!m_drag.active()) {
        if (m_tool)
            forwardToTool(event, &ViewportTool::mouseMoved);
        else
            QOpenGLWidget::mouseMoveEvent(event);
        return;
    }
    m_camera.setViewportSize(size());
    m_drag.move(event->position(), event->modifiers(), m_camera);
    cameraMovedByUser();
}

void Viewport::cameraMovedByUser()
{
    m_cameraMovedByUser = true;
    m_frameOnNextPaint = false;
    update();
}

void Viewport::mouseReleaseEvent(QMouseEvent* event)
{
    if (event->button() == Qt::LeftButton && m_tool && m_toolDragging) {
        m_toolDragging = false;
        forwardToTool(event, &ViewportTool::mouseReleased);
        return;
    }
    if (m_drag.end(event->button())) {
        event->accept();
        return;
    }
    QOpenGLWidget::mouseReleaseEvent(event);
}

void Viewport::mouseDoubleClickEvent(QMouseEvent* event)
{
    if (event->button() == Qt::LeftButton && m_tool && !(event->modifiers() & Qt::AltModifier)) {
        forwardToTool(event, &ViewportTool::mouseDoubleClicked);
        return;
    }
    QOpenGLWidget::mouseDoubleClickEvent(event);
}

void Viewport::resizeEvent(QResizeEvent* event)
{
    QOpenGLWidget::resizeEvent(event);
    m_overlay->resize(event->size());
    m_hud->resize(event->size());
}

void Viewport::wheelEvent(QWheelEvent* event)
{
    const float degrees = float(event->angleDelta().y()) / 8.0f;
    if (degrees == 0.0f)
        return;
    m_camera.setViewportSize(size());
    m_camera.zoomAt(event->position(), std::pow(kWheelZoomPerDegree, degrees), pixelToGround(event->position()));
    cameraMovedByUser();
}

void Viewport::keyPressEvent(QKeyEvent* event)
{
    if (m_tool && m_tool->keyPressed(event))
        return;
    if (event->key() == Qt::Key_F && event->modifiers() == Qt::NoModifier) {
        frameSelection();
        return;
    }
    if (event->key() == Qt::Key_A && event->modifiers() == Qt::NoModifier) {
        frameAll();
        return;
    }
    QOpenGLWidget::keyPressEvent(event);
}

}  // namespace throng::editor
