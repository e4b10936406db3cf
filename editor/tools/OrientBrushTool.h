#pragma once
// The orient brush: combs the headings of the placed agents under the brush toward the
// direction of the stroke (by its strength, 1 = exactly along it). One stroke is one
// undo step.

#include "editor/tools/AgentBrushTool.h"

namespace throng::editor {

class OrientBrushTool : public AgentBrushTool {
    Q_OBJECT

public:
    using AgentBrushTool::AgentBrushTool;

    QString name() const override { return tr("Orient Brush"); }
    QString toolTip() const override
    {
        return tr("Orient Brush (C): drag over agents to comb their headings along the stroke");
    }
    QKeySequence shortcut() const override { return QKeySequence(Qt::Key_C); }
    QString objectKey() const override { return QStringLiteral("orientBrush"); }
    QWidget* createOptionsWidget(QWidget* parent) override;

    float strength() const { return m_strength; }
    void setStrength(float s) { m_strength = s; }

protected:
    bool editAgent(sim::Agent& agent, glm::vec2 centre, glm::vec2 direction, int strokeId) const override;
    QString verb() const override { return tr("Comb"); }
    QColor brushColour() const override { return QColor(120, 230, 160); }

private:
    float m_strength = 1.0f;  // share of the turn toward the stroke per dab, (0, 1]
};

}  // namespace throng::editor
