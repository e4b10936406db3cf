#pragma once
// The erase brush: a left drag removes the placed agents inside a disk that follows the
// mouse. Each dab is an EraseAgentsCommand; one stroke is one undo step.

#include "editor/tools/BrushTool.h"

namespace throng::editor {

class EraseBrushTool : public BrushTool {
    Q_OBJECT

public:
    EraseBrushTool(SceneDocument& document, Viewport& viewport, QObject* parent = nullptr);

    QString name() const override { return tr("Erase Brush"); }
    QString toolTip() const override
    {
        return tr("Erase Brush (E): drag to remove placed agents under the brush; [ and ] or Ctrl+drag size it");
    }
    QKeySequence shortcut() const override { return QKeySequence(Qt::Key_E); }
    QString objectKey() const override { return QStringLiteral("eraseBrush"); }
    QWidget* createOptionsWidget(QWidget* parent) override;

protected:
    void strokeBegan(glm::vec2 point) override;
    void strokeMoved(glm::vec2 point) override { dab(point); }
    QColor brushColour() const override { return QColor(255, 110, 90); }

private:
    void dab(glm::vec2 centre);

    int m_strokeId = 0;
};

}  // namespace throng::editor
