#pragma once
// One brain node drawn on the graph: title, typed input and output ports, its
// parameters inline, the membership curve of a fuzz node, a compiler error (red, with
// the message as tooltip) and the picked agent's live values. Never edits the graph.

#include "simcore/brain/NodeCatalogue.h"
#include "simcore/scene/BrainGraph.h"

#include <QGraphicsItem>

#include <optional>
#include <vector>

namespace throng::editor {

class FuzzCurveItem;
class PortItem;

class NodeItem : public QGraphicsItem {
public:
    enum { Type = UserType + 1 };
    static constexpr double kWidth = 200.0;

    // `library`: the scene's brains (a macro node's outputs); may be null.
    NodeItem(const sim::BrainGraph& graph, const sim::BrainNode& node, const std::vector<sim::BrainGraph>* library);
    int type() const override { return Type; }

    // Takes the node's new state (ports, params, position) from the graph.
    void setNode(const sim::BrainGraph& graph, const sim::BrainNode& node, const std::vector<sim::BrainGraph>* library);
    const sim::BrainNode& node() const { return m_node; }
    sim::NodeId id() const { return m_node.id; }

    PortItem* inputPort(int index) const;
    PortItem* outputPort(int index) const;
    int inputCount() const { return int(m_inputs.size()); }
    int outputCount() const { return int(m_outputs.size()); }
    FuzzCurveItem* fuzzCurve() const { return m_curve; }
    // The parameter row under a point (item coordinates), or -1.
    int paramAt(QPointF local) const;
    QRectF paramRect(int row) const;
    // The parameter spec shown in row `row`.
    const sim::ParamSpec* paramSpec(int row) const;
    QString paramText(int row) const;

    void setError(const QString& message);
    QString error() const { return m_error; }
    // Live values of each output for the picked agent; empty clears them.
    void setLiveValues(const std::vector<std::optional<std::vector<float>>>& outputs);
    // What the node shows for output `port`, as text ("0.73", "3.2 (4)"), empty = nothing.
    QString liveText(int port) const;

    QRectF boundingRect() const override;
    void paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget* widget) override;

protected:
    QVariant itemChange(GraphicsItemChange change, const QVariant& value) override;

private:
    void rebuildPorts(const sim::BrainGraph& graph, const std::vector<sim::BrainGraph>* library);
    double portRowsBottom() const;
    bool isNote() const { return m_node.type == "note"; }
    bool showsBars() const;

    sim::BrainNode m_node;
    const sim::NodeSpec* m_spec = nullptr;
    std::vector<PortItem*> m_inputs, m_outputs;
    FuzzCurveItem* m_curve = nullptr;
    QString m_error;
    std::vector<std::optional<std::vector<float>>> m_live;
    double m_height = 60.0;
};

}  // namespace throng::editor
