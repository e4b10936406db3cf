#pragma once
// Draws a traffic lane: click its points in the direction of travel, finish with Enter
// or a double-click; width and speed limit come from the tool options. One AddLane step.

#include "editor/tools/PolylineTool.h"

namespace throng::editor {

class LaneTool : public PolylineTool {
    Q_OBJECT

public:
    using PolylineTool::PolylineTool;

    QString name() const override { return tr("Lane"); }
    QString toolTip() const override
    {
        return tr("Lane (N): click the points in the direction cars drive, Enter or double-click to finish");
    }
    QKeySequence shortcut() const override { return QKeySequence(Qt::Key_N); }
    QString objectKey() const override { return QStringLiteral("lane"); }
    QWidget* createOptionsWidget(QWidget* parent) override;

protected:
    void add(const std::vector<glm::vec2>& points) override;
    QColor previewColour() const override { return QColor(220, 190, 80); }

private:
    float m_widthM = 3.5f;
    float m_speedLimit = 13.9f;  // m/s
};

}  // namespace throng::editor
