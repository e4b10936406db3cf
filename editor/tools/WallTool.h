#pragma once
// Draws a wall: click its corners, finish with Enter or a double-click. One AddWall step.

#include "editor/tools/PolylineTool.h"

namespace throng::editor {

class WallTool : public PolylineTool {
    Q_OBJECT

public:
    using PolylineTool::PolylineTool;

    QString name() const override { return tr("Wall"); }
    QString toolTip() const override
    {
        return tr("Wall (W): click the corners, Enter or double-click to finish, Esc to cancel");
    }
    QKeySequence shortcut() const override { return QKeySequence(Qt::Key_W); }
    QString objectKey() const override { return QStringLiteral("wall"); }

protected:
    void add(const std::vector<glm::vec2>& points) override;
    QColor previewColour() const override { return QColor(240, 240, 240); }
};

}  // namespace throng::editor
