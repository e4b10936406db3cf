#pragma once
// The orthographic camera looking straight down: screen right is +x (east), screen up is
// -z (north). Knows only its centre, zoom and the widget size; never touches GL.

#include "editor/viewport/GroundBox.h"
#include "editor/viewport/RenderView.h"

#include <glm/vec2.hpp>

#include <QPointF>
#include <QSize>

namespace throng::editor {

class TopCamera {
public:
    void setViewportSize(QSize sizePx) { m_size = sizePx; }
    QSize viewportSize() const { return m_size; }

    glm::vec2 centre() const { return m_centre; }
    float pixelsPerMetre() const { return m_pixelsPerMetre; }

    // The ground point (x, z) under a widget pixel, and the pixel showing a ground point.
    glm::vec2 pixelToGround(QPointF pixel) const;
    QPointF groundToPixel(glm::vec2 ground) const;

    // Moves the view by a mouse drag of `deltaPx` (the ground follows the mouse).
    void pan(QPointF deltaPx);
    // Multiplies the zoom by `factor` (> 1 zooms in), keeping the ground under `pixel` fixed.
    void zoomAt(QPointF pixel, float factor);
    // Shows all of `box` with `marginPx` free at the widget's edges.
    void frame(const GroundBox& box, float marginPx);

    RenderView renderView() const;

private:
    void clampZoom();

    QSize m_size{1, 1};
    glm::vec2 m_centre{0.0f};
    float m_pixelsPerMetre = 10.0f;
};

}  // namespace throng::editor
