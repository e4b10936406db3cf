#pragma once
// Select and move: a click picks the agent, obstacle, goal, light, path (its closing
// segment too), wall, lane, flow stroke or source under the mouse (Shift adds); a drag from empty
// ground selects everything inside the box; dragging a selected item moves the whole
// selection; a single selected line shows handles: drag a point to reshape it, a path's
// radius handle to widen it, double-click a segment to insert a point. Agents and
// vehicles are picked where the shown frame draws them; a spawned agent selects its group
// and becomes the viewport's focused agent. Every drag is one undo step; Escape during a
// drag takes it back and leaves no redo step.

#include "editor/SceneItem.h"
#include "editor/tools/ViewportTool.h"
#include "simcore/world/FrameCache.h"

#include <glm/vec2.hpp>

#include <QPointF>

#include <functional>
#include <optional>
#include <vector>

namespace throng::editor {

class SelectTool : public ViewportTool {
    Q_OBJECT

public:
    using ViewportTool::ViewportTool;

    QString name() const override { return tr("Select"); }
    QString toolTip() const override
    {
        return tr("Select (Q): click or box-drag to select, Shift adds; drag a selected item to move the "
                  "selection; drag a path's handles to reshape it");
    }
    QKeySequence shortcut() const override { return QKeySequence(Qt::Key_Q); }
    QString objectKey() const override { return QStringLiteral("select"); }

    void mousePressed(const ToolMouse& mouse) override;
    void mouseMoved(const ToolMouse& mouse) override;
    void mouseReleased(const ToolMouse& mouse) override;
    void mouseDoubleClicked(const ToolMouse& mouse) override;
    void cancel() override;
    void drawOverlay(QPainter& painter) const override;

    struct Hit {
        SceneItem item;
        sim::AgentId agent = 0;  // the World agent clicked, 0 for items that are not agents
    };
    // The item drawn within kPickPx of `pixel` (an agent within its drawn body too),
    // nearest first (points before lines); empty when none.
    std::optional<Hit> pick(QPointF pixel) const;
    static constexpr double kPickPx = 10.0;
    static constexpr double kHandlePx = 8.0;

private:
    enum class Drag { None, Move, Box, Point, Radius };

    // A segment of a polyline item near a pixel: insert a new point at `insertAt`.
    struct Segment {
        std::size_t insertAt = 0;
        double distancePx = 0.0;
    };
    // The segment of `item` nearest `pixel` within kPickPx, a closed path's closing one too.
    std::optional<Segment> segmentAt(SceneItem item, QPointF pixel) const;
    // Where a path's, wall's, lane's or flow stroke's points live in the scene.
    static std::function<std::vector<glm::vec2>&(sim::Scene&)> pointsOf(SceneItem item);
    bool pressHandle(const ToolMouse& mouse);
    void dragTo(const ToolMouse& mouse);
    void finishBox(Qt::KeyboardModifiers modifiers);
    QPointF pixelOf(glm::vec2 ground) const;
    // The World id of a placed agent or vehicle; 0 for other items.
    sim::AgentId agentIdOf(SceneItem item) const;
    // Whether the shown frame holds the agent or vehicle (drawn or not). One it does not
    // (no World, or a frame from before the edit that added it) is where the scene has it.
    bool inFrame(SceneItem item) const;
    // Where the shown frame draws an agent or vehicle; empty when it does not.
    std::optional<glm::vec3> shownAt(SceneItem item) const;

    Drag m_drag = Drag::None;
    SceneItem m_handleItem;
    std::size_t m_handlePoint = 0;
    glm::vec2 m_lastGround{0.0f};
    QPointF m_boxStart, m_boxEnd;
    int m_dragSerial = 0;
    bool m_pushed = false;  // the drag has pushed (merged) commands
};

}  // namespace throng::editor
