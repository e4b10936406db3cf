#pragma once
// Places a circular obstacle: press at its centre and drag out its radius (a click gives
// the default radius). The preview stays in the tool until the release pushes one step.

#include "editor/tools/ViewportTool.h"

#include <glm/vec2.hpp>

namespace throng::editor {

class ObstacleTool : public ViewportTool {
    Q_OBJECT

public:
    using ViewportTool::ViewportTool;

    QString name() const override { return tr("Obstacle"); }
    QString toolTip() const override
    {
        return tr("Obstacle (O): press at the centre and drag out the radius; a click places a 0.5 m post");
    }
    QKeySequence shortcut() const override { return QKeySequence(Qt::Key_O); }
    QString objectKey() const override { return QStringLiteral("obstacle"); }

    void mousePressed(const ToolMouse& mouse) override;
    void mouseMoved(const ToolMouse& mouse) override;
    void mouseReleased(const ToolMouse& mouse) override;
    void drawOverlay(QPainter& painter) const override;

private:
    float radiusTo(const ToolMouse& mouse) const;

    glm::vec3 m_centre{0.0f};
    float m_radiusM = 0.5f;
};

}  // namespace throng::editor
