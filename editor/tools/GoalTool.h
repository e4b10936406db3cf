#pragma once
// Places a goal area: press at its centre and drag out its arrival radius (a click gives
// the radius of the tool options). The preview stays in the tool until the release
// pushes one AddGoal step.

#include "editor/tools/CircleDragTool.h"

namespace throng::editor {

class GoalTool : public CircleDragTool {
    Q_OBJECT

public:
    using CircleDragTool::CircleDragTool;

    QString name() const override { return tr("Goal"); }
    QString toolTip() const override
    {
        return tr("Goal (G): press at the centre and drag out the arrival radius; a click uses the default radius");
    }
    QKeySequence shortcut() const override { return QKeySequence(Qt::Key_G); }
    QString objectKey() const override { return QStringLiteral("goal"); }
    QWidget* createOptionsWidget(QWidget* parent) override;

protected:
    float defaultRadiusM() const override { return m_defaultRadiusM; }
    float clickRadiusM() const override { return 0.3f; }
    QColor previewColour() const override { return QColor(100, 230, 140); }
    void place(glm::vec2 centre, float radiusM) override;

private:
    float m_defaultRadiusM = 1.5f;
};

}  // namespace throng::editor
