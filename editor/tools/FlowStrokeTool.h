#pragma once
// The walking brush: a left drag draws a flow stroke, a freehand line whose direction
// of travel steers the crowd within its width (flow-field following). The preview
// stays in the tool; the release pushes one AddFlowStroke step, Escape drops it.

#include "editor/tools/ViewportTool.h"

#include <glm/vec2.hpp>

#include <vector>

namespace throng::editor {

class FlowStrokeTool : public ViewportTool {
    Q_OBJECT

public:
    using ViewportTool::ViewportTool;

    QString name() const override { return tr("Flow Stroke"); }
    QString toolTip() const override
    {
        return tr("Flow Stroke (K): drag the way the crowd should walk; agents within its width follow it");
    }
    QKeySequence shortcut() const override { return QKeySequence(Qt::Key_K); }
    QString objectKey() const override { return QStringLiteral("flowStroke"); }

    void mousePressed(const ToolMouse& mouse) override;
    void mouseMoved(const ToolMouse& mouse) override;
    void mouseReleased(const ToolMouse& mouse) override;
    void cancel() override;
    void drawOverlay(QPainter& painter) const override;
    QWidget* createOptionsWidget(QWidget* parent) override;

    // Points are kept at least this far apart along the stroke, m.
    static constexpr float kSampleM = 1.0f;

private:
    std::vector<glm::vec2> m_points;
    float m_widthM = 4.0f;
};

}  // namespace throng::editor
