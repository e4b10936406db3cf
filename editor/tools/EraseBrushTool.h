#pragma once
// The erase brush: a left drag removes the placed agents inside a disk that follows the
// mouse. Each dab is an EraseAgentsCommand; one stroke is one undo step.

#include "editor/tools/ViewportTool.h"

#include <glm/vec2.hpp>

namespace throng::editor {

class EraseBrushTool : public ViewportTool {
    Q_OBJECT

public:
    using ViewportTool::ViewportTool;

    QString name() const override { return tr("Erase Brush"); }
    QString toolTip() const override { return tr("Erase Brush (E): drag to remove placed agents under the brush"); }
    QKeySequence shortcut() const override { return QKeySequence(Qt::Key_E); }
    QString objectKey() const override { return QStringLiteral("eraseBrush"); }

    void mousePressed(const ToolMouse& mouse) override;
    void mouseMoved(const ToolMouse& mouse) override;
    void mouseReleased(const ToolMouse& mouse) override;
    void cancel() override;
    void drawOverlay(QPainter& painter) const override;
    QWidget* createOptionsWidget(QWidget* parent) override;

    float radiusM() const { return m_radiusM; }
    void setRadiusM(float r) { m_radiusM = r; }

private:
    void dab(glm::vec2 centre);

    float m_radiusM = 2.0f;
    std::optional<glm::vec3> m_cursor;
    int m_strokeId = 0;
};

}  // namespace throng::editor
