#pragma once
// A tool that places one round thing: press at its centre and drag out its radius (a
// drag shorter than clickRadiusM() is a click and gives defaultRadiusM()). The preview
// circle stays in the tool; the release hands centre and radius to place(), which pushes
// one undo step. Shared by GoalTool, ObstacleTool and ActionPointTool; never edits the
// scene itself.

#include "editor/tools/ViewportTool.h"

#include <glm/vec2.hpp>

#include <QColor>

#include <optional>

namespace throng::editor {

class CircleDragTool : public ViewportTool {
    Q_OBJECT

public:
    using ViewportTool::ViewportTool;

    void mousePressed(const ToolMouse& mouse) override;
    void mouseMoved(const ToolMouse& mouse) override;
    void mouseReleased(const ToolMouse& mouse) override;
    void drawOverlay(QPainter& painter) const override;

protected:
    virtual float defaultRadiusM() const = 0;  // m, > 0
    virtual float clickRadiusM() const = 0;    // m: drags shorter than this are clicks
    virtual QColor previewColour() const = 0;
    // Pushes the command that adds the thing at `centre` (x, z) with `radiusM`.
    virtual void place(glm::vec2 centre, float radiusM) = 0;
    // In place(): the heading from the centre to where the drag ended, degrees (0 = +x,
    // counter-clockwise seen from above); nothing for a click.
    std::optional<float> dragHeadingDeg() const { return m_headingDeg; }

private:
    float radiusTo(const ToolMouse& mouse) const;

    glm::vec3 m_centre{0.0f};
    float m_radiusM = 0.0f;
    std::optional<float> m_headingDeg;
};

}  // namespace throng::editor
