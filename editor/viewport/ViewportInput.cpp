// The viewport's input: the left button goes to the active tool, the middle and right
// buttons and the wheel move the camera, keys go to the tool first.
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
}  // namespace

void Viewport::forwardToTool(QMouseEvent* event, void (ViewportTool::*handler)(const ToolMouse&))
{
    const ToolMouse mouse{event->position(), pixelToGround(event->position()), event->modifiers()};
    (m_tool->*handler)(mouse);
    event->accept();
}

void Viewport::mousePressEvent(QMouseEvent* event)
{
    if (event->button() == Qt::LeftButton && m_tool && m_dragButton == Qt::NoButton) {
        m_toolDragging = true;
        forwardToTool(event, &ViewportTool::mousePressed);
        return;
    }
    if (event->button() == Qt::MiddleButton || event->button() == Qt::RightButton) {
        m_dragButton = event->button();
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
    const bool orbit = m_camera.mode() == ViewMode::Orbit && m_dragButton == Qt::RightButton &&
                       !(event->modifiers() & Qt::ShiftModifier);
    if (orbit)
        m_camera.rotate(delta);
    else
        m_camera.pan(delta);
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
        event->accept();
        return;
    }
    QOpenGLWidget::mouseReleaseEvent(event);
}

void Viewport::mouseDoubleClickEvent(QMouseEvent* event)
{
    if (event->button() == Qt::LeftButton && m_tool) {
        forwardToTool(event, &ViewportTool::mouseDoubleClicked);
        return;
    }
    QOpenGLWidget::mouseDoubleClickEvent(event);
}

void Viewport::resizeEvent(QResizeEvent* event)
{
    QOpenGLWidget::resizeEvent(event);
    m_overlay->resize(event->size());
}

void Viewport::wheelEvent(QWheelEvent* event)
{
    const float degrees = float(event->angleDelta().y()) / 8.0f;
    if (degrees == 0.0f)
        return;
    m_camera.setViewportSize(size());
    m_camera.zoomAt(event->position(), std::pow(kWheelZoomPerDegree, degrees));
    m_cameraMovedByUser = true;
    m_frameOnNextPaint = false;
    update();
}

void Viewport::keyPressEvent(QKeyEvent* event)
{
    if (m_tool && m_tool->keyPressed(event))
        return;
    if (event->key() == Qt::Key_F && event->modifiers() == Qt::NoModifier) {
        frameAll();
        return;
    }
    QOpenGLWidget::keyPressEvent(event);
}

}  // namespace throng::editor
