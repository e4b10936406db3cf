#pragma once
// Places a goal area: press at its centre and drag out its arrival radius (a click gives
// the radius of the tool options). The preview stays in the tool until the release
// pushes one AddGoal step.

#include "editor/tools/ViewportTool.h"

namespace throng::editor {

class GoalTool : public ViewportTool {
    Q_OBJECT

public:
    using ViewportTool::ViewportTool;

    QString name() const override { return tr("Goal"); }
    QString toolTip() const override
    {
        return tr("Goal (G): press at the centre and drag out the arrival radius; a click uses the default radius");
    }
    QKeySequence shortcut() const override { return QKeySequence(Qt::Key_G); }
    QString objectKey() const override { return QStringLiteral("goal"); }

    void mousePressed(const ToolMouse& mouse) override;
    void mouseMoved(const ToolMouse& mouse) override;
    void mouseReleased(const ToolMouse& mouse) override;
    void drawOverlay(QPainter& painter) const override;
    QWidget* createOptionsWidget(QWidget* parent) override;

private:
    float radiusTo(const ToolMouse& mouse) const;

    glm::vec3 m_centre{0.0f};
    float m_dragRadiusM = 0.0f;
    float m_defaultRadiusM = 1.5f;
};

}  // namespace throng::editor
