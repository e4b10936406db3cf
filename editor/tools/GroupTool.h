#pragma once
// Draws a spawn group: a left drag spans its rectangle (corner to corner) or its circle
// (centre, then radius); a click gives a 10 m square or a 5 m circle; a polygon takes a
// click per corner and closes on a double-click or Enter (Backspace drops the last corner,
// Escape all of them). The group gets the chosen agent type and either a count or a
// density times its area. The preview stays in the tool until the release (or the close)
// pushes one undo step; it never edits the scene itself.

#include "editor/tools/ViewportTool.h"
#include "simcore/scene/Scene.h"

#include <glm/vec2.hpp>

#include <optional>
#include <vector>

namespace throng::editor {

class GroupTool : public ViewportTool {
    Q_OBJECT

public:
    using ViewportTool::ViewportTool;

    QString name() const override { return tr("Spawn Group"); }
    QString toolTip() const override;
    QKeySequence shortcut() const override { return QKeySequence(Qt::Key_S); }
    QString objectKey() const override { return QStringLiteral("group"); }
    QString iconKey() const override { return QStringLiteral("tool-spawn-group"); }

    void mousePressed(const ToolMouse& mouse) override;
    void mouseMoved(const ToolMouse& mouse) override;
    void mouseReleased(const ToolMouse& mouse) override;
    void mouseDoubleClicked(const ToolMouse& mouse) override;
    bool keyPressed(QKeyEvent* event) override;
    void cancel() override;
    void drawOverlay(QPainter& painter) const override;
    QString statusText() const override;
    QWidget* createOptionsWidget(QWidget* parent) override;

    enum class Amount { Count, Density };
    struct Settings {
        sim::AreaShape shape = sim::AreaShape::Rect;
        Amount amount = Amount::Density;
        int count = 100;                // agents, Amount::Count
        double densityPerM2 = 0.5;      // agents per m², Amount::Density
        std::string type;               // empty = the scene's first type
    };
    Settings& settings() { return m_settings; }
    // The polygon's corners clicked so far (empty outside the polygon shape).
    const std::vector<glm::vec2>& corners() const { return m_corners; }
    // Why the last try to close the polygon was refused, or empty.
    const QString& refusal() const { return m_refusal; }

private:
    sim::SpawnGroup previewGroup() const;
    std::uint32_t countFor(const sim::SpawnGroup& group) const;
    void pushGroup(sim::SpawnGroup group);
    // Closes the polygon into a group, or refuses (refusal()) and keeps its corners.
    void closePolygon();
    void drawPolygonOverlay(QPainter& painter) const;

    Settings m_settings;
    glm::vec2 m_start{0.0f}, m_end{0.0f};
    std::vector<glm::vec2> m_corners;
    std::optional<glm::vec2> m_cursor;  // the ground under the mouse, for the polygon's next edge
    QString m_refusal;
};

}  // namespace throng::editor
