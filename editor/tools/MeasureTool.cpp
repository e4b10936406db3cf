#include "editor/tools/MeasureTool.h"

#include "editor/SceneDocument.h"
#include "editor/commands/AddSceneItemCommand.h"
#include "editor/tools/UniqueName.h"
#include "editor/viewport/Viewport.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPainter>

namespace throng::editor {

void MeasureTool::mousePressed(const ToolMouse& mouse)
{
    if (!mouse.ground)
        return;
    m_from = m_to = {mouse.ground->x, mouse.ground->z};
    setState(State::Dragging);
    emit overlayChanged();
}

void MeasureTool::mouseMoved(const ToolMouse& mouse)
{
    if (state() != State::Dragging || !mouse.ground)
        return;
    m_to = {mouse.ground->x, mouse.ground->z};
    emit overlayChanged();
}

void MeasureTool::mouseReleased(const ToolMouse& mouse)
{
    if (state() != State::Dragging)
        return;
    if (mouse.ground)
        m_to = {mouse.ground->x, mouse.ground->z};
    setState(State::Idle);
    place();
    emit overlayChanged();
}

void MeasureTool::place()
{
    const glm::vec2 d = glm::abs(m_to - m_from);
    const bool tooSmall = m_shape == sim::MeasurementShape::Line ? glm::length(m_to - m_from) < kMinimumM
                                                                 : d.x < kMinimumM || d.y < kMinimumM;
    if (tooSmall)
        return;
    sim::Measurement m;
    m.shape = m_shape;
    if (m_shape == sim::MeasurementShape::Line) {
        m.name = uniqueName(document().scene().measurements, "line");
        m.points = {m_from, m_to};
    } else {
        m.name = uniqueName(document().scene().measurements, "area");
        const glm::vec2 lo = glm::min(m_from, m_to), hi = glm::max(m_from, m_to);
        m.points = {lo, {hi.x, lo.y}, hi, {lo.x, hi.y}};
    }
    const QString text = tr("Add measurement %1").arg(QString::fromStdString(m.name));
    addAndSelect(document(), &sim::Scene::measurements, std::move(m), text);
}

void MeasureTool::cancel()
{
    m_from = m_to = glm::vec2(0.0f);
    ViewportTool::cancel();
}

void MeasureTool::drawOverlay(QPainter& painter) const
{
    if (state() != State::Dragging)
        return;
    auto px = [&](glm::vec2 p) { return viewport().worldToPixel({p.x, 0.0f, p.y}); };
    const QColor colour(84, 143, 255);
    painter.setPen(QPen(colour, 2.0, Qt::DashLine));
    painter.setBrush(Qt::NoBrush);
    if (m_shape == sim::MeasurementShape::Line) {
        painter.drawLine(px(m_from), px(m_to));
        return;
    }
    const QPolygonF box({px(m_from), px({m_to.x, m_from.y}), px(m_to), px({m_from.x, m_to.y})});
    painter.drawPolygon(box);
}

QWidget* MeasureTool::createOptionsWidget(QWidget* parent)
{
    auto* box = new QWidget(parent);
    auto* row = new QHBoxLayout(box);
    row->setContentsMargins(4, 0, 4, 0);
    auto* shape = new QComboBox(box);
    shape->setObjectName("measureShape");
    shape->addItems({tr("Line"), tr("Area")});
    shape->setCurrentIndex(int(m_shape));
    shape->setToolTip(tr("Line: counts the walkers crossing it, each way, and the flow over time. Area: the density "
                         "of the walkers inside and their speed, for the speed-density diagram"));
    connect(shape, &QComboBox::currentIndexChanged, this, [this](int i) { m_shape = sim::MeasurementShape(i); });
    row->addWidget(new QLabel(tr("Shape"), box));
    row->addWidget(shape);
    return box;
}

}  // namespace throng::editor
