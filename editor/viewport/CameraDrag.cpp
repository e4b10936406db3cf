#include "editor/viewport/CameraDrag.h"

#include <cmath>

namespace throng::editor {

namespace {
constexpr float kDragZoomPerPixel = 1.01f;  // an Alt+right drag of 100 px zooms by 2.7x
}  // namespace

void CameraDrag::begin(Qt::MouseButton button, bool alt, QPointF pixel, std::optional<glm::vec3> ground)
{
    m_button = button;
    m_alt = alt;
    m_last = m_press = pixel;
    m_pressGround = ground;
}

void CameraDrag::move(QPointF pixel, Qt::KeyboardModifiers modifiers, CameraRig& camera)
{
    const QPointF delta = pixel - m_last;
    m_last = pixel;
    const bool orbitView = camera.mode() == ViewMode::Orbit;
    if (m_alt && m_button == Qt::RightButton) {
        // Right or up zooms in, as Maya's dolly does.
        camera.zoomAt(m_press, std::pow(kDragZoomPerPixel, float(delta.x() - delta.y())), m_pressGround);
    } else if (m_alt && m_button == Qt::LeftButton) {
        if (orbitView)
            camera.rotate(delta);
        else
            camera.pan(delta);
    } else if (!m_alt && orbitView && m_button == Qt::RightButton && !(modifiers & Qt::ShiftModifier)) {
        camera.rotate(delta);
    } else {
        camera.pan(delta);
    }
}

bool CameraDrag::end(Qt::MouseButton button)
{
    if (button != m_button || !active())
        return false;
    m_button = Qt::NoButton;
    m_alt = false;
    return true;
}

}  // namespace throng::editor
