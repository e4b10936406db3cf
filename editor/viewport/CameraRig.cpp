#include "editor/viewport/CameraRig.h"

namespace throng::editor {

namespace {
constexpr float kFrameMarginPx = 24.0f;
}

void CameraRig::setViewportSize(QSize sizePx)
{
    m_top.setViewportSize(sizePx);
    m_orbit.setViewportSize(sizePx);
}

void CameraRig::pan(QPointF deltaPx)
{
    if (m_mode == ViewMode::Top)
        m_top.pan(deltaPx);
    else
        m_orbit.pan(deltaPx);
}

void CameraRig::rotate(QPointF deltaPx)
{
    if (m_mode == ViewMode::Orbit)
        m_orbit.orbit(deltaPx);
}

void CameraRig::zoomAt(QPointF pixel, float factor, std::optional<glm::vec3> ground)
{
    if (m_mode == ViewMode::Top)
        m_top.zoomAt(pixel, factor);
    else if (ground)
        m_orbit.zoomTowards(*ground, factor);
    else
        m_orbit.zoom(factor);
}

void CameraRig::frame(const GroundBox& box)
{
    m_top.frame(box, kFrameMarginPx);
    m_orbit.frame(box);
}

RenderView CameraRig::renderView() const
{
    return m_mode == ViewMode::Top ? m_top.renderView() : m_orbit.renderView();
}

}  // namespace throng::editor
