#pragma once
// The brain editor's adapter over one brain of the open scene: reads the graph from the
// SceneDocument and turns every edit (add/remove nodes and links, move, set a parameter,
// paste) into an EditBrainCommand on the document's undo stack. Holds no graph of its own.

#include "editor/SceneDocument.h"
#include "simcore/scene/BrainGraph.h"

#include <QObject>
#include <QPointF>

#include <map>
#include <string>
#include <vector>

namespace throng::editor {

class BrainGraphModel : public QObject {
    Q_OBJECT

public:
    explicit BrainGraphModel(SceneDocument& document, QObject* parent = nullptr);

    SceneDocument& document() { return m_document; }
    // The brain shown (index into Scene::brains), -1 when the scene has none.
    int brainIndex() const { return m_brain; }
    void setBrainIndex(int index);
    // The shown graph: the scene's, laid out (AutoLayout) when it has no positions; the
    // first edit stores those positions.
    const sim::BrainGraph& graph() const { return m_shown; }
    bool hasBrain() const;

    // Each returns false (and pushes nothing) when the edit is not possible; `problem`
    // says why for a refused link.
    sim::NodeId addNode(const std::string& type, QPointF pos);
    bool addLink(const sim::BrainLink& link, std::string* problem = nullptr);
    // Removes nodes with their links, and links by index, as one undo step.
    bool remove(const std::vector<sim::NodeId>& nodes, const std::vector<std::size_t>& links);
    bool moveNodes(const std::map<sim::NodeId, QPointF>& positions);
    // One parameter; with `merge` successive changes of the same drag are one undo step.
    bool setParam(sim::NodeId node, const sim::BrainParam& param, bool merge = false);
    bool setParams(sim::NodeId node, const std::vector<sim::BrainParam>& params, bool merge);
    // Adds copies of `fragment`'s nodes (new ids, shifted by `offset`) and its links
    // between them; returns the new ids in fragment order.
    std::vector<sim::NodeId> paste(const sim::BrainGraph& fragment, QPointF offset);
    // The nodes `ids` and the links among them, as a stand-alone fragment.
    sim::BrainGraph copy(const std::vector<sim::NodeId>& ids) const;
    // Replaces the whole graph (auto-layout, macro collapse) as one step.
    bool replace(const sim::BrainGraph& graph, const QString& text);

signals:
    // The shown graph changed (an edit, undo/redo, another brain shown, a new scene).
    void graphChanged();

private:
    sim::NodeId nextId() const;
    bool push(sim::BrainGraph after, const QString& text, bool merge = false);

    void refresh();

    SceneDocument& m_document;
    int m_brain = -1;
    sim::BrainGraph m_shown;
    sim::BrainGraph m_source;  // the scene's graph m_shown was made from
    bool m_fresh = false;      // m_shown is up to date with m_source
    std::size_t m_brainCount = 0;  // brains in the scene then (macro ports, errors)
};

}  // namespace throng::editor
