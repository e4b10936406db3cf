#pragma once
// Draws a path for agents to follow: click its points, finish with Enter or a
// double-click; its radius comes from the tool options. One AddPath step.

#include "editor/tools/PolylineTool.h"

namespace throng::editor {

class PathTool : public PolylineTool {
    Q_OBJECT

public:
    using PolylineTool::PolylineTool;

    QString name() const override { return tr("Path"); }
    QString toolTip() const override
    {
        return tr("Path (P): click the points agents follow, Enter or double-click to finish");
    }
    QKeySequence shortcut() const override { return QKeySequence(Qt::Key_P); }
    QString objectKey() const override { return QStringLiteral("path"); }
    QWidget* createOptionsWidget(QWidget* parent) override;

protected:
    void add(const std::vector<glm::vec2>& points) override;
    QColor previewColour() const override { return QColor(250, 200, 60); }

private:
    float m_radiusM = 1.0f;
};

}  // namespace throng::editor
