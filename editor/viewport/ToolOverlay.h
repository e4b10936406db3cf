#pragma once
// A transparent widget over the viewport on which the active tool draws its preview
// (brush circle, wall being drawn) with QPainter. Lets every mouse event through; never
// part of a screenshot.

#include <QWidget>

namespace throng::editor {

class ViewportTool;

class ToolOverlay : public QWidget {
    Q_OBJECT

public:
    explicit ToolOverlay(QWidget* parent);
    void setTool(const ViewportTool* tool);

protected:
    void paintEvent(QPaintEvent* event) override;

private:
    const ViewportTool* m_tool = nullptr;
};

}  // namespace throng::editor
