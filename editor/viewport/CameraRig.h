#pragma once
// The viewport's two cameras (top orthographic and perspective orbit) and which one is
// live; turns navigation gestures into camera moves. Owns no GL and no scene data.

#include "editor/viewport/GroundBox.h"
#include "editor/viewport/OrbitCamera.h"
#include "editor/viewport/RenderView.h"
#include "editor/viewport/TopCamera.h"

#include <QPointF>
#include <QSize>

#include <glm/vec3.hpp>

#include <optional>

namespace throng::editor {

enum class ViewMode { Top, Orbit };

class CameraRig {
public:
    void setMode(ViewMode mode) { m_mode = mode; }
    ViewMode mode() const { return m_mode; }
    void setViewportSize(QSize sizePx);

    // Gestures in widget pixels. `pan` drags the ground; `rotate` orbits (perspective
    // only); `zoomAt` zooms by `factor` (> 1 in) towards what lies under `pixel`: the
    // ground point there stays there (in perspective `ground`, the point the pixel's ray
    // meets; without one, the distance to the target shrinks).
    void pan(QPointF deltaPx);
    void rotate(QPointF deltaPx);
    void zoomAt(QPointF pixel, float factor, std::optional<glm::vec3> ground = std::nullopt);
    // Frames `box` in both cameras, so switching views keeps the scene in sight.
    void frame(const GroundBox& box);

    const TopCamera& top() const { return m_top; }
    RenderView renderView() const;

private:
    ViewMode m_mode = ViewMode::Top;
    TopCamera m_top;
    OrbitCamera m_orbit;
};

}  // namespace throng::editor
