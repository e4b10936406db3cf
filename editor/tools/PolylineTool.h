#pragma once
// Base of the tools that draw a polyline by clicks (walls, paths): each click adds a
// point, the mouse drags a rubber band to the next one, Enter or a double-click finishes
// (two points at least), Backspace drops the last point and Escape throws it all away.
// The preview stays in the tool until finish pushes one command.

#include "editor/tools/ViewportTool.h"

#include <glm/vec2.hpp>

#include <QColor>

#include <vector>

class QUndoCommand;

namespace throng::editor {

class PolylineTool : public ViewportTool {
    Q_OBJECT

public:
    using ViewportTool::ViewportTool;

    void mousePressed(const ToolMouse& mouse) override;
    void mouseMoved(const ToolMouse& mouse) override;
    void mouseDoubleClicked(const ToolMouse& mouse) override;
    bool keyPressed(QKeyEvent* event) override;
    void cancel() override;
    void drawOverlay(QPainter& painter) const override;

    const std::vector<glm::vec2>& points() const { return m_points; }
    // Pushes the polyline drawn so far (when it has two points) and starts a new one.
    void finish();

protected:
    // Adds the finished polyline (>= 2 points) to the scene, as one undo step, and selects it.
    virtual void add(const std::vector<glm::vec2>& points) = 0;
    virtual QColor previewColour() const = 0;

private:
    std::vector<glm::vec2> m_points;
    std::optional<glm::vec3> m_cursor;
};

}  // namespace throng::editor
