#include "editor/viewport/OrbitCamera.h"

#include <glm/common.hpp>
#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::editor {

namespace {
constexpr float kFovYRad = 0.785398f;  // 45 degrees
constexpr float kRadPerPixel = 0.008f;
constexpr float kMinPitchRad = 0.05f;
constexpr float kMaxPitchRad = 1.55f;
constexpr float kMinDistanceM = 0.5f;
constexpr float kMaxDistanceM = 1e5f;
}  // namespace

glm::vec3 OrbitCamera::eye() const
{
    const float c = std::cos(m_pitchRad);
    return m_target + m_distanceM * glm::vec3(c * std::cos(m_yawRad), std::sin(m_pitchRad), c * std::sin(m_yawRad));
}

void OrbitCamera::orbit(QPointF deltaPx)
{
    m_yawRad += float(deltaPx.x()) * kRadPerPixel;
    m_pitchRad = std::clamp(m_pitchRad + float(deltaPx.y()) * kRadPerPixel, kMinPitchRad, kMaxPitchRad);
}

void OrbitCamera::pan(QPointF deltaPx)
{
    // One pixel moves the ground by what a pixel spans at the target's distance.
    const float metresPerPixel = 2.0f * m_distanceM * std::tan(0.5f * kFovYRad) / float(std::max(1, m_size.height()));
    const glm::vec3 toEye = eye() - m_target;
    const glm::vec3 back = glm::normalize(glm::vec3(toEye.x, 0.0f, toEye.z));
    const glm::vec3 right{back.z, 0.0f, -back.x};  // up x back
    m_target += (-float(deltaPx.x()) * right - float(deltaPx.y()) * back) * metresPerPixel;
}

void OrbitCamera::zoom(float factor)
{
    m_distanceM = std::clamp(m_distanceM / factor, kMinDistanceM, kMaxDistanceM);
}

void OrbitCamera::zoomTowards(glm::vec3 point, float factor)
{
    const float before = m_distanceM;
    zoom(factor);
    // Scaling the whole view about `point` keeps the ray through it: the clamp decides
    // how far that scaling may go.
    m_target = point + (m_target - point) * (m_distanceM / before);
}

void OrbitCamera::frame(const GroundBox& box)
{
    if (box.empty)
        return;
    const glm::vec2 c = box.centre();
    m_target = {c.x, 0.0f, c.y};
    // The box is flat: its width must fit the horizontal field of view, and its depth,
    // foreshortened by the pitch, the vertical one. The factor covers the perspective
    // growth of the near edge.
    const float aspect = float(std::max(1, m_size.width())) / float(std::max(1, m_size.height()));
    const float tanHalfY = std::tan(0.5f * kFovYRad), tanHalfX = tanHalfY * aspect;
    const glm::vec2 half = 0.5f * glm::max(box.size(), glm::vec2(1.0f));
    const float fitWidth = std::max(half.x, half.y) / tanHalfX;
    const float fitDepth = std::max(half.x, half.y) * std::sin(m_pitchRad) / tanHalfY;
    m_distanceM = std::clamp(1.25f * std::max(fitWidth, fitDepth), kMinDistanceM, kMaxDistanceM);
}

RenderView OrbitCamera::renderView() const
{
    const float aspect = float(std::max(1, m_size.width())) / float(std::max(1, m_size.height()));
    const glm::vec3 e = eye();
    const float nearM = std::max(0.05f, 0.01f * m_distanceM);
    const glm::mat4 projection = glm::perspective(kFovYRad, aspect, nearM, 50.0f * m_distanceM + 1000.0f);
    RenderView v;
    v.viewProjection = projection * glm::lookAt(e, m_target, glm::vec3(0.0f, 1.0f, 0.0f));
    v.metresPerPixel = 2.0f * std::tan(0.5f * kFovYRad) / float(std::max(1, m_size.height()));
    v.perspective = true;
    v.eye = e;
    v.sizePx = {float(std::max(1, m_size.width())), float(std::max(1, m_size.height()))};
    return v;
}

}  // namespace throng::editor
