#pragma once
// One input or output port drawn on a node: a dot coloured by the kind of value it
// carries (per agent or per neighbour). Links are dragged from and dropped on it; it
// never edits the graph itself.

#include "simcore/brain/NodeCatalogue.h"

#include <QGraphicsEllipseItem>

namespace throng::editor {

class NodeItem;

class PortItem : public QGraphicsEllipseItem {
public:
    enum { Type = UserType + 2 };
    static constexpr double kRadius = 6.0;

    PortItem(NodeItem* node, bool isInput, int index, sim::PortKind kind, const QString& name);
    int type() const override { return Type; }

    NodeItem* node() const { return m_node; }
    bool isInput() const { return m_input; }
    int index() const { return m_index; }
    sim::PortKind kind() const { return m_kind; }
    QPointF centre() const { return mapToScene(QPointF(0, 0)); }
    // Highlights the port as a drop target: accepted (green) or refused (red).
    void setDropState(int state);

private:
    NodeItem* m_node;
    bool m_input;
    int m_index;
    sim::PortKind m_kind;
};

QColor portColour(sim::PortKind kind);

}  // namespace throng::editor
