#pragma once
// Places a circular obstacle: press at its centre and drag out its radius (a click gives
// the default radius). The preview stays in the tool until the release pushes one step.

#include "editor/tools/CircleDragTool.h"

namespace throng::editor {

class ObstacleTool : public CircleDragTool {
    Q_OBJECT

public:
    using CircleDragTool::CircleDragTool;

    QString name() const override { return tr("Obstacle"); }
    QString toolTip() const override
    {
        return tr("Obstacle (O): press at the centre and drag out the radius; a click places a 0.5 m post");
    }
    QKeySequence shortcut() const override { return QKeySequence(Qt::Key_O); }
    QString objectKey() const override { return QStringLiteral("obstacle"); }

protected:
    float defaultRadiusM() const override { return 0.5f; }
    float clickRadiusM() const override { return 0.1f; }
    QColor previewColour() const override { return QColor(200, 140, 255); }
    void place(glm::vec2 centre, float radiusM) override;
};

}  // namespace throng::editor
