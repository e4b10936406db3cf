#include "editor/brain/LinkItem.h"

#include <QPainterPath>
#include <QPainterPathStroker>
#include <QPen>

#include <algorithm>
#include <cmath>

namespace throng::editor {

LinkItem::LinkItem(int index) : m_index(index)
{
    setZValue(1);
    if (index >= 0)
        setFlag(ItemIsSelectable);
    restyle();
}

void LinkItem::setEnds(QPointF from, QPointF to)
{
    m_from = from;
    m_to = to;
    const double dx = std::max(40.0, std::abs(to.x() - from.x()) * 0.5);
    QPainterPath path(from);
    path.cubicTo(from + QPointF(dx, 0), to - QPointF(dx, 0), to);
    setPath(path);
}

void LinkItem::setError(const QString& message)
{
    m_error = !message.isEmpty();
    setToolTip(message);
    restyle();
}

void LinkItem::setFlow(std::optional<float> value)
{
    m_flow = value;
    restyle();
}

void LinkItem::setDragState(int state)
{
    m_dragState = state;
    restyle();
}

QPainterPath LinkItem::shape() const
{
    QPainterPathStroker stroker;
    stroker.setWidth(8.0);
    return stroker.createStroke(path());
}

void LinkItem::restyle()
{
    QColor colour(200, 200, 200);
    double width = 2.0;
    if (m_error)
        colour = QColor(230, 50, 50);
    if (m_dragState != 0)
        colour = m_dragState > 0 ? QColor(60, 220, 90) : QColor(230, 40, 40);
    if (m_flow && !m_error) {
        // Brighter and wider the more flows (truths 0..1; larger values saturate).
        const double f = std::clamp(double(std::abs(*m_flow)), 0.0, 1.0);
        colour = QColor::fromRgbF(0.4 + 0.6 * f, 0.8, 0.4 + 0.2 * (1.0 - f));
        width = 1.5 + 3.5 * f;
    }
    QPen pen(colour, width);
    if (m_index < 0)
        pen.setStyle(Qt::DashLine);
    setPen(pen);
}

}  // namespace throng::editor
