#pragma once
// Layout Move (Y): moves or turns recorded trajectories through the layout layer, as a
// director asks after the take. With agents, groups or types selected, a drag adds a
// Translate operation for them (Shift: a Rotate about their centre on the shown frame)
// and sets its offset or angle as the mouse goes; with a Translate or Rotate operation
// selected, a drag changes its amount. Ctrl+drag draws a lasso round agents where the shown
// frame has them: it adds a Translate for the agents inside (a lasso on that frame), to
// drag next or turn into any other operation in Properties. Each drag is one undoable
// step; Escape takes it back. Draws the gizmo over the agents' centre: a cross for a move,
// a ring for a turn; and the lasso as it is drawn.

#include "editor/tools/ViewportTool.h"
#include "simcore/layout/LayoutLayer.h"

#include <glm/vec2.hpp>

#include <optional>
#include <vector>

namespace throng::editor {

class LayoutMoveTool : public ViewportTool {
    Q_OBJECT

public:
    using ViewportTool::ViewportTool;

    QString name() const override { return tr("Layout Move"); }
    QString toolTip() const override
    {
        return tr("Layout Move (Y): drag to move the selected agents' recorded paths without simulating again, "
                  "Shift+drag to turn them, Ctrl+drag to lasso agents on the shown frame; with a layout operation "
                  "selected, drag to change it");
    }
    QKeySequence shortcut() const override { return QKeySequence(Qt::Key_Y); }
    QString objectKey() const override { return QStringLiteral("layoutMove"); }

    void mousePressed(const ToolMouse& mouse) override;
    void mouseMoved(const ToolMouse& mouse) override;
    void mouseReleased(const ToolMouse& mouse) override;
    void cancel() override;
    void drawOverlay(QPainter& painter) const override;

    // A drag shorter than this on screen changes nothing (a click), px.
    static constexpr double kDeadPx = 3.0;

private:
    // The operation a drag edits: the one selected (its index), or a new one to append.
    struct Target {
        std::optional<std::size_t> index;
        sim::LayoutOp op;  // as it was when the drag began (new: with nothing done yet)
    };
    std::optional<Target> target(bool turn) const;
    // Where the agents `op` names stand on the shown frame: their centre (the scene's x, z).
    std::optional<glm::vec2> centreOf(const sim::LayoutOp& op) const;
    void apply(glm::vec2 ground);
    // Adds the lasso's operation, if the lasso holds a place (3 corners, not crossing itself).
    void finishLasso();

    std::optional<Target> m_target;
    std::vector<glm::vec2> m_lasso;  // while a Ctrl+drag draws one: its corners (x, z)
    // A lasso's corners are at least this far apart, m.
    static constexpr float kLassoStepM = 0.25f;
    glm::vec2 m_press{0.0f}, m_now{0.0f}, m_centre{0.0f};
    QPointF m_pressPixel;
    bool m_moved = false;
    int m_serial = 0;  // one merge key per drag
};

}  // namespace throng::editor
