#pragma once
// The QGraphicsScene of the brain editor: one NodeItem per node and one LinkItem per
// link of the model's graph, rebuilt from the model's signal. Turns mouse input into
// model edits: links dragged from port to port (refused visibly when the rules say no),
// moved nodes (one undo step per drag), parameters edited inline. Never writes the scene.

#include "editor/brain/BrainGraphModel.h"
#include "simcore/brain/BrainCompiler.h"
#include "simcore/brain/BrainEvaluator.h"
#include "simcore/brain/NodeCatalogue.h"

#include <QGraphicsScene>

#include <map>
#include <vector>

class QGraphicsProxyWidget;

namespace throng::editor {

class LinkItem;
class NodeItem;
class PortItem;

class BrainScene : public QGraphicsScene {
    Q_OBJECT

public:
    explicit BrainScene(BrainGraphModel& model, QObject* parent = nullptr);

    BrainGraphModel& model() { return m_model; }
    NodeItem* nodeItem(sim::NodeId id) const;
    std::vector<NodeItem*> nodeItems() const;
    const std::vector<LinkItem*>& linkItems() const { return m_links; }
    std::vector<sim::NodeId> selectedNodes() const;

    // Marks the nodes and links the compiler blamed (message as tooltip); empty clears.
    void setErrors(const std::vector<sim::BrainError>& errors);
    // Shows the picked agent's node values on nodes and links; empty clears them.
    void setLiveValues(const std::vector<sim::BrainNodeValue>& values);
    // Opens the inline editor of a node's parameter row (double-click does this).
    QWidget* editParam(NodeItem* node, int row);
    // The open inline parameter editor, null when none.
    QWidget* paramEditor() const;
    // Deletes the selected nodes and links as one undo step.
    bool deleteSelection();

    // Called by NodeItem while it moves: its links follow.
    void nodeMoved(NodeItem* node);

signals:
    // A dragged link was refused; `reason` says why.
    void linkRefused(const QString& reason);
    // A link was added by dragging.
    void linkAdded();
    // A link from `port` (an output unless `fromInput`) was dropped on empty space.
    void linkDroppedOnEmpty(sim::NodeId node, int port, bool fromInput, sim::PortKind kind, QPointF scenePos);
    // A parameter typed inline was refused.
    void paramRefused(const QString& reason);

protected:
    void mousePressEvent(QGraphicsSceneMouseEvent* event) override;
    void mouseMoveEvent(QGraphicsSceneMouseEvent* event) override;
    void mouseReleaseEvent(QGraphicsSceneMouseEvent* event) override;
    void mouseDoubleClickEvent(QGraphicsSceneMouseEvent* event) override;

private:
    void sync();
    void updateLinkEnds(LinkItem* link);
    PortItem* portNear(QPointF scenePos, const PortItem* except) const;
    sim::BrainLink linkBetween(const PortItem* a, const PortItem* b) const;
    void commitParam(sim::NodeId node, const sim::ParamSpec& spec, const QString& text);
    void closeEditor();

    BrainGraphModel& m_model;
    std::map<sim::NodeId, NodeItem*> m_nodes;
    std::vector<LinkItem*> m_links;
    PortItem* m_dragFrom = nullptr;
    PortItem* m_dragOver = nullptr;
    LinkItem* m_dragLink = nullptr;
    QGraphicsProxyWidget* m_editor = nullptr;
    std::vector<sim::BrainError> m_errors;
    std::vector<sim::BrainNodeValue> m_live;
};

}  // namespace throng::editor
