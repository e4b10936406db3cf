#pragma once
// Select and move: a click picks the agent, obstacle, goal or light under the mouse
// (Shift adds to the selection, a click on nothing clears it); dragging a picked item
// moves it, one undo step per drag.

#include "editor/SceneItem.h"
#include "editor/tools/ViewportTool.h"

#include <glm/vec2.hpp>

namespace throng::editor {

class SelectTool : public ViewportTool {
    Q_OBJECT

public:
    using ViewportTool::ViewportTool;

    QString name() const override { return tr("Select"); }
    QString toolTip() const override
    {
        return tr("Select (Q): click an agent, obstacle, goal or light; Shift+click adds; drag to move it");
    }
    QKeySequence shortcut() const override { return QKeySequence(Qt::Key_Q); }
    QString objectKey() const override { return QStringLiteral("select"); }

    void mousePressed(const ToolMouse& mouse) override;
    void mouseMoved(const ToolMouse& mouse) override;
    void mouseReleased(const ToolMouse& mouse) override;
    void cancel() override;
    void drawOverlay(QPainter& painter) const override;

    // The item drawn within kPickPx of `pixel`, nearest first; empty when none.
    std::optional<SceneItem> pick(QPointF pixel) const;
    static constexpr double kPickPx = 10.0;

private:
    void moveTo(glm::vec2 ground);

    std::optional<SceneItem> m_dragged;
    glm::vec2 m_grabOffset{0.0f};  // item position minus the ground point grabbed
    int m_dragSerial = 0;
};

}  // namespace throng::editor
