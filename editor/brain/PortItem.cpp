#include "editor/brain/PortItem.h"

#include <QBrush>
#include <QPen>

namespace throng::editor {

QColor portColour(sim::PortKind kind)
{
    switch (kind) {
    case sim::PortKind::PerNeighbour:
        return QColor(230, 160, 40);
    case sim::PortKind::Any:
        return QColor(170, 170, 170);
    case sim::PortKind::Scalar:
        break;
    }
    return QColor(90, 170, 240);
}

PortItem::PortItem(NodeItem* node, bool isInput, int index, sim::PortKind kind, const QString& name)
    : QGraphicsEllipseItem(-kRadius, -kRadius, 2 * kRadius, 2 * kRadius), m_node(node), m_input(isInput),
      m_index(index), m_kind(kind)
{
    setBrush(portColour(kind));
    setPen(QPen(QColor(30, 30, 30), 1.0));
    const QString kindText = kind == sim::PortKind::PerNeighbour ? QObject::tr("per neighbour")
                             : kind == sim::PortKind::Any        ? QObject::tr("per agent or per neighbour")
                                                                 : QObject::tr("per agent");
    setToolTip(QStringLiteral("%1 %2: %3 (%4)")
                   .arg(isInput ? QObject::tr("input") : QObject::tr("output"))
                   .arg(index)
                   .arg(name, kindText));
    setZValue(2);
}

void PortItem::setDropState(int state)
{
    setPen(state == 0 ? QPen(QColor(30, 30, 30), 1.0)
                      : QPen(state > 0 ? QColor(60, 220, 90) : QColor(230, 40, 40), 3.0));
}

}  // namespace throng::editor
