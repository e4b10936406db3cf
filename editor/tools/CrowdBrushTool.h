#pragma once
// The crowd brush: a left drag paints agents inside a disk that follows the mouse on the
// ground (2D) or the terrain (3D), at the density, spacing, type mix and heading mode
// of its settings. Each dab is a PaintAgentsCommand; one stroke is one undo step.

#include "editor/tools/CrowdBrushPlacement.h"
#include "editor/tools/ViewportTool.h"

#include <glm/vec2.hpp>

namespace throng::editor {

class CrowdBrushTool : public ViewportTool {
    Q_OBJECT

public:
    using ViewportTool::ViewportTool;

    QString name() const override { return tr("Crowd Brush"); }
    QString toolTip() const override;
    QKeySequence shortcut() const override { return QKeySequence(Qt::Key_B); }
    QString objectKey() const override { return QStringLiteral("crowdBrush"); }

    void mousePressed(const ToolMouse& mouse) override;
    void mouseMoved(const ToolMouse& mouse) override;
    void mouseReleased(const ToolMouse& mouse) override;
    void cancel() override;
    void drawOverlay(QPainter& painter) const override;
    QWidget* createOptionsWidget(QWidget* parent) override;

    CrowdBrushSettings& settings() { return m_settings; }
    // Agents added by the stroke in progress or the last one.
    std::size_t strokeAgentCount() const { return m_strokeAgents; }

private:
    void dab(glm::vec2 centre, glm::vec2 direction);

    CrowdBrushSettings m_settings;
    std::optional<glm::vec3> m_cursor;
    glm::vec2 m_lastDab{0.0f};
    int m_strokeId = 0;
    int m_dabIndex = 0;
    std::size_t m_strokeAgents = 0;
};

}  // namespace throng::editor
