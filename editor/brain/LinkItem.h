#pragma once
// One link drawn as a curve from an output port to an input port (or to the mouse while
// it is dragged). Shows a compiler error in red with its message as tooltip, and the
// live value flowing through it. Never edits the graph.

#include <QGraphicsPathItem>

#include <optional>

namespace throng::editor {

class LinkItem : public QGraphicsPathItem {
public:
    enum { Type = UserType + 3 };
    // `index` into BrainGraph::links; -1 for the link being dragged.
    explicit LinkItem(int index);
    int type() const override { return Type; }

    int index() const { return m_index; }
    void setEnds(QPointF from, QPointF to);
    QPointF from() const { return m_from; }
    QPointF to() const { return m_to; }
    void setError(const QString& message);
    bool hasError() const { return m_error; }
    // The value the source gives for the picked agent; empty = none shown.
    void setFlow(std::optional<float> value);
    std::optional<float> flow() const { return m_flow; }
    // Dragging: accepted (green), refused (red) or undecided.
    void setDragState(int state);
    // Only the stroke is the link: a click in a curve's belly is not on it.
    QPainterPath shape() const override;

private:
    void restyle();

    int m_index;
    QPointF m_from, m_to;
    bool m_error = false;
    int m_dragState = 0;
    std::optional<float> m_flow;
};

}  // namespace throng::editor
