#include "editor/viewport/TopCamera.h"

#include <glm/common.hpp>
#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>

#include <algorithm>

namespace throng::editor {

namespace {
constexpr float kMinPixelsPerMetre = 1e-3f;
constexpr float kMaxPixelsPerMetre = 1e4f;
constexpr float kEyeHeightM = 5000.0f;
}  // namespace

glm::vec2 TopCamera::pixelToGround(QPointF pixel) const
{
    const glm::vec2 fromCentre{float(pixel.x()) - 0.5f * float(m_size.width()),
                               float(pixel.y()) - 0.5f * float(m_size.height())};
    return m_centre + fromCentre / m_pixelsPerMetre;
}

QPointF TopCamera::groundToPixel(glm::vec2 ground) const
{
    const glm::vec2 p = (ground - m_centre) * m_pixelsPerMetre;
    return {double(p.x) + 0.5 * m_size.width(), double(p.y) + 0.5 * m_size.height()};
}

void TopCamera::pan(QPointF deltaPx)
{
    m_centre -= glm::vec2(float(deltaPx.x()), float(deltaPx.y())) / m_pixelsPerMetre;
}

void TopCamera::zoomAt(QPointF pixel, float factor)
{
    const glm::vec2 anchor = pixelToGround(pixel);
    m_pixelsPerMetre *= factor;
    clampZoom();
    m_centre += anchor - pixelToGround(pixel);
}

void TopCamera::frame(const GroundBox& box, float marginPx)
{
    if (box.empty)
        return;
    const glm::vec2 extent = glm::max(box.size(), glm::vec2(1.0f));
    const float w = std::max(1.0f, float(m_size.width()) - 2.0f * marginPx);
    const float h = std::max(1.0f, float(m_size.height()) - 2.0f * marginPx);
    m_centre = box.centre();
    m_pixelsPerMetre = std::min(w / extent.x, h / extent.y);
    clampZoom();
}

RenderView TopCamera::renderView() const
{
    const float halfW = 0.5f * float(m_size.width()) / m_pixelsPerMetre;
    const float halfH = 0.5f * float(m_size.height()) / m_pixelsPerMetre;
    const glm::vec3 eye{m_centre.x, kEyeHeightM, m_centre.y};
    // Looking down -y with -z as screen up keeps +x to the right (right-handed).
    const glm::mat4 view = glm::lookAt(eye, glm::vec3(m_centre.x, 0.0f, m_centre.y), glm::vec3(0.0f, 0.0f, -1.0f));
    const glm::mat4 projection = glm::ortho(-halfW, halfW, -halfH, halfH, 1.0f, 2.0f * kEyeHeightM);
    RenderView v;
    v.viewProjection = projection * view;
    v.metresPerPixel = 1.0f / m_pixelsPerMetre;
    v.perspective = false;
    v.eye = eye;
    v.sizePx = {float(std::max(1, m_size.width())), float(std::max(1, m_size.height()))};
    return v;
}

void TopCamera::clampZoom()
{
    m_pixelsPerMetre = std::clamp(m_pixelsPerMetre, kMinPixelsPerMetre, kMaxPixelsPerMetre);
}

}  // namespace throng::editor
