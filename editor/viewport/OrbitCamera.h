#pragma once
// The perspective camera orbiting a target point on the ground: yaw, pitch and distance.
// Yaw 90 degrees looks north from the south, like the top view turned up. No GL.

#include "editor/viewport/GroundBox.h"
#include "editor/viewport/RenderView.h"

#include <glm/vec3.hpp>

#include <QPointF>
#include <QSize>

namespace throng::editor {

class OrbitCamera {
public:
    void setViewportSize(QSize sizePx) { m_size = sizePx; }

    // Turns around the target by a mouse drag of `deltaPx`.
    void orbit(QPointF deltaPx);
    // Slides the target across the ground by a mouse drag of `deltaPx`.
    void pan(QPointF deltaPx);
    // Divides the distance by `factor` (> 1 moves closer).
    void zoom(float factor);
    // Moves the eye and the target towards `point` (> 1) or away from it, dividing the
    // distance by `factor`; the view direction is kept, so `point` stays on its pixel.
    void zoomTowards(glm::vec3 point, float factor);
    float distanceM() const { return m_distanceM; }
    // Looks at the centre of `box` from far enough to see all of it.
    void frame(const GroundBox& box);

    glm::vec3 eye() const;
    glm::vec3 target() const { return m_target; }
    RenderView renderView() const;

private:
    QSize m_size{1, 1};
    glm::vec3 m_target{0.0f};
    float m_distanceM = 60.0f;
    float m_yawRad = 1.5707964f;
    float m_pitchRad = 0.85f;
};

}  // namespace throng::editor
