// The viewport's input: the left button goes to the active tool, keys to the tool first.
// The camera follows the Maya/Houdini convention: with Alt held the left button orbits
// (pans in the top view), the middle pans and the right zooms towards where the drag
// began; without Alt the middle pans and the right orbits in 3D (Shift: pans) or pans
// from above. The wheel zooms towards the cursor. F frames the selection, A everything.
#include "editor/viewport/Viewport.h"

#include "editor/viewport/ToolOverlay.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QResizeEvent>
#include <QWheelEvent>

#include <cmath>

namespace throng::editor {

namespace {
constexpr float kWheelZoomPerDegree = 1.01f;  // one 15-degree notch zooms by about 16 %
constexpr float kDragZoomPerPixel = 1.01f;    // an Alt+right drag of 100 px zooms by 2.7x
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
    if (alt && m_dragButton == Qt::NoButton && !m_toolDragging) {
        m_dragButton = event->button();
        m_altDrag = true;
        m_lastMousePos = m_pressPos = event->position();
        m_pressGround = pixelToGround(m_pressPos);
        event->accept();
        return;
    }
    if (event->button() == Qt::LeftButton && m_tool && m_dragButton == Qt::NoButton) {
        m_toolDragging = true;
        forwardToTool(event, &ViewportTool::mousePressed);
        return;
    }
    if (event->button() == Qt::MiddleButton || event->button() == Qt::RightButton) {
        m_dragButton = event->button();
        m_altDrag = false;
        m_lastMousePos = event->position();
        event->accept();
        return;
    }
    QOpenGLWidget::mousePressEvent(event);
}

void Viewport::mouseMoveEvent(QMouseEvent* event)
{
    if (m_dragButton == Qt::NoButton) {
        if (m_tool)
            forwardToTool(event, &ViewportTool::mouseMoved);
        else
            QOpenGLWidget::mouseMoveEvent(event);
        return;
    }
    const QPointF delta = event->position() - m_lastMousePos;
    m_lastMousePos = event->position();
    dragCamera(delta, event->modifiers());
}

void Viewport::dragCamera(QPointF delta, Qt::KeyboardModifiers modifiers)
{
    m_camera.setViewportSize(size());
    const bool orbitView = m_camera.mode() == ViewMode::Orbit;
    if (m_altDrag && m_dragButton == Qt::RightButton) {
        // Right or up zooms in, as Maya's dolly does.
        m_camera.zoomAt(m_pressPos, std::pow(kDragZoomPerPixel, float(delta.x() - delta.y())), m_pressGround);
    } else if (m_altDrag && m_dragButton == Qt::LeftButton) {
        if (orbitView)
            m_camera.rotate(delta);
        else
            m_camera.pan(delta);
    } else if (!m_altDrag && orbitView && m_dragButton == Qt::RightButton && !(modifiers & Qt::ShiftModifier)) {
        m_camera.rotate(delta);
    } else {
        m_camera.pan(delta);
    }
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
    if (event->button() == m_dragButton) {
        m_dragButton = Qt::NoButton;
        m_altDrag = false;
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
