#pragma once
// The variation brush: sets the tint, mesh variant (look) and height scale of the placed
// agents under the brush, to fixed values or to draws from the agent type's palette and
// a height range. One stroke is one undo step.

#include "editor/tools/AgentBrushTool.h"

namespace throng::editor {

struct VariationBrushSettings {
    bool setTint = true;
    int tint = -1;              // 0-based index into the type's tints; -1 = a random one per agent
    bool setLook = false;
    int look = -1;              // 0-based index into the type's looks; -1 = a random one per agent
    bool setHeight = false;
    float heightMin = 0.9f;     // height scale drawn uniformly in [min, max], > 0
    float heightMax = 1.1f;
};

class VariationBrushTool : public AgentBrushTool {
    Q_OBJECT

public:
    using AgentBrushTool::AgentBrushTool;

    QString name() const override { return tr("Variation Brush"); }
    QString toolTip() const override
    {
        return tr("Variation Brush (V): drag over agents to set their tint, look and height");
    }
    QKeySequence shortcut() const override { return QKeySequence(Qt::Key_V); }
    QString objectKey() const override { return QStringLiteral("variationBrush"); }
    QWidget* createOptionsWidget(QWidget* parent) override;

    VariationBrushSettings& settings() { return m_settings; }

protected:
    bool editAgent(sim::Agent& agent, glm::vec2 centre, glm::vec2 direction, int strokeId) const override;
    QString verb() const override { return tr("Vary"); }
    QColor brushColour() const override { return QColor(240, 140, 220); }

private:
    VariationBrushSettings m_settings;
};

}  // namespace throng::editor
