#include "editor/tools/BrushOverlay.h"

#include "editor/viewport/Viewport.h"

#include <QPainter>
#include <QPolygonF>

#include <cmath>
#include <numbers>

namespace throng::editor {

void drawBrushCircle(QPainter& painter, const Viewport& viewport, glm::vec3 centre, float radiusM, QColor colour)
{
    constexpr int kSegments = 48;
    QPolygonF ring;
    for (int i = 0; i <= kSegments; ++i) {
        const float a = 2.0f * std::numbers::pi_v<float> * float(i) / float(kSegments);
        ring << viewport.worldToPixel(centre + glm::vec3(std::cos(a) * radiusM, 0.0f, std::sin(a) * radiusM));
    }
    painter.setPen(QPen(colour, 1.5));
    painter.setBrush(Qt::NoBrush);
    painter.drawPolyline(ring);
    painter.drawPoint(viewport.worldToPixel(centre));
}

}  // namespace throng::editor
