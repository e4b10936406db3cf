#pragma once
// The crowd brush: a left drag paints agents inside a disk that follows the mouse on the
// ground (2D) or the terrain (3D), at the density, spacing, type mix and heading mode
// of its settings. Each dab is a PaintAgentsCommand; one stroke is one undo step.

#include "editor/tools/BrushTool.h"
#include "editor/tools/CrowdBrushPlacement.h"

namespace throng::editor {

class CrowdBrushTool : public BrushTool {
    Q_OBJECT

public:
    CrowdBrushTool(SceneDocument& document, Viewport& viewport, QObject* parent = nullptr);

    QString name() const override { return tr("Crowd Brush"); }
    QString toolTip() const override;
    QKeySequence shortcut() const override { return QKeySequence(Qt::Key_B); }
    QString objectKey() const override { return QStringLiteral("crowdBrush"); }
    QWidget* createOptionsWidget(QWidget* parent) override;

    // The brush's settings; its radius is BrushTool's (radiusM), whatever radiusM says here.
    CrowdBrushSettings& settings() { return m_settings; }
    // Agents added by the stroke in progress or the last one.
    std::size_t strokeAgentCount() const { return m_strokeAgents; }

protected:
    bool strokeAllowed() override;
    void strokeBegan(glm::vec2 point) override;
    void strokeMoved(glm::vec2 point) override;
    QColor brushColour() const override { return QColor(80, 200, 255); }

private:
    void dab(glm::vec2 centre, glm::vec2 direction);

    CrowdBrushSettings m_settings;
    glm::vec2 m_lastDab{0.0f};
    int m_strokeId = 0;
    int m_dabIndex = 0;
    std::size_t m_strokeAgents = 0;
};

}  // namespace throng::editor
