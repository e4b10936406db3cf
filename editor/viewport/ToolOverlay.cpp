#include "editor/viewport/ToolOverlay.h"

#include "editor/tools/ViewportTool.h"

#include <QPainter>

namespace throng::editor {

ToolOverlay::ToolOverlay(QWidget* parent) : QWidget(parent)
{
    setAttribute(Qt::WA_TransparentForMouseEvents);
    setAttribute(Qt::WA_NoSystemBackground);
    setAttribute(Qt::WA_TranslucentBackground);
}

void ToolOverlay::setTool(const ViewportTool* tool)
{
    m_tool = tool;
    update();
}

void ToolOverlay::paintEvent(QPaintEvent*)
{
    if (!m_tool)
        return;
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    m_tool->drawOverlay(painter);
}

}  // namespace throng::editor
