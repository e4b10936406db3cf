#include "editor/tools/FlowStrokeTool.h"

#include "editor/SceneDocument.h"
#include "editor/commands/AddSceneItemCommand.h"
#include "editor/viewport/Viewport.h"

#include <glm/geometric.hpp>

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>
#include <QPolygonF>

namespace throng::editor {

void FlowStrokeTool::mousePressed(const ToolMouse& mouse)
{
    if (!mouse.ground)
        return;
    m_points = {{mouse.ground->x, mouse.ground->z}};
    setState(State::Dragging);
    emit overlayChanged();
}

void FlowStrokeTool::mouseMoved(const ToolMouse& mouse)
{
    if (state() != State::Dragging || !mouse.ground)
        return;
    const glm::vec2 p(mouse.ground->x, mouse.ground->z);
    if (glm::length(p - m_points.back()) >= kSampleM) {
        m_points.push_back(p);
        emit overlayChanged();
    }
}

void FlowStrokeTool::mouseReleased(const ToolMouse& mouse)
{
    if (state() != State::Dragging)
        return;
    if (mouse.ground) {
        const glm::vec2 p(mouse.ground->x, mouse.ground->z);
        if (glm::length(p - m_points.back()) > 0.01f)
            m_points.push_back(p);
    }
    std::vector<glm::vec2> points = std::move(m_points);
    m_points.clear();
    setState(State::Idle);
    if (points.size() >= 2) {
        sim::FlowStroke stroke{std::move(points), m_widthM};
        addAndSelect(document(), &sim::Scene::flowStrokes, std::move(stroke), tr("Add flow stroke"));
    }
    emit overlayChanged();
}

void FlowStrokeTool::cancel()
{
    m_points.clear();
    ViewportTool::cancel();
}

void FlowStrokeTool::drawOverlay(QPainter& painter) const
{
    QPolygonF line;
    for (glm::vec2 p : m_points)
        line << viewport().worldToPixel({p.x, 0.0f, p.y});
    painter.setPen(QPen(QColor(170, 140, 240), 2.0, Qt::DashLine));
    painter.drawPolyline(line);
}

QWidget* FlowStrokeTool::createOptionsWidget(QWidget* parent)
{
    auto* box = new QWidget(parent);
    auto* row = new QHBoxLayout(box);
    row->setContentsMargins(4, 0, 4, 0);
    auto* spin = new QDoubleSpinBox(box);
    spin->setObjectName("flowWidth");
    spin->setRange(0.2, 100.0);
    spin->setValue(double(m_widthM));
    spin->setToolTip(tr("How far either side of the stroke agents feel it, in metres (full width)"));
    connect(spin, &QDoubleSpinBox::valueChanged, this, [this](double v) { m_widthM = float(v); });
    row->addWidget(new QLabel(tr("Width"), box));
    row->addWidget(spin);
    return box;
}

}  // namespace throng::editor
