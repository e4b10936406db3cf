#pragma once
// Draws a brush disk lying on the ground as the viewport shows it (an ellipse in 3D).
// Drawing only; used by the brush tools' overlays.

#include <glm/vec3.hpp>

#include <QColor>

class QPainter;

namespace throng::editor {

class Viewport;

void drawBrushCircle(QPainter& painter, const Viewport& viewport, glm::vec3 centre, float radiusM, QColor colour);

}  // namespace throng::editor
