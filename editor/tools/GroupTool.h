#pragma once
// Draws a spawn group: a left drag spans its rectangle (corner to corner) or its circle
// (centre, then radius); a click gives a 10 m square or a 5 m circle. The group gets the
// chosen agent type and either a count or a density times its area. The preview stays in
// the tool until the release pushes one undo step; it never edits the scene itself.

#include "editor/tools/ViewportTool.h"
#include "simcore/scene/Scene.h"

#include <glm/vec2.hpp>

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

private:
    sim::SpawnGroup previewGroup() const;
    std::uint32_t countFor(const sim::SpawnGroup& group) const;

    Settings m_settings;
    glm::vec2 m_start{0.0f}, m_end{0.0f};
};

}  // namespace throng::editor
