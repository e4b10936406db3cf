#include "editor/brain/BrainGraphModel.h"

#include "editor/brain/AutoLayout.h"
#include "editor/brain/BrainCommands.h"
#include "editor/brain/BrainLinkRules.h"
#include "simcore/brain/NodeCatalogue.h"

#include <algorithm>
#include <set>

namespace throng::editor {

BrainGraphModel::BrainGraphModel(SceneDocument& document, QObject* parent) : QObject(parent), m_document(document)
{
    // Only the brain list holds what the model shows.
    connect(&m_document, &SceneDocument::sceneChanged, this, [this](const SceneChange& change) {
        if (change.touches(ItemKind::Brain))
            refresh();
    });
    connect(&m_document, &SceneDocument::sceneReset, this, [this] {
        m_brain = -1;
        m_fresh = false;
        refresh();
    });
    refresh();
}

void BrainGraphModel::refresh()
{
    const int count = int(m_document.scene().brains.size());
    if (m_brain >= count || (m_brain < 0 && count > 0))
        m_brain = count > 0 ? std::clamp(m_brain, 0, count - 1) : -1;
    const sim::BrainGraph& source = hasBrain() ? m_document.scene().brains[std::size_t(m_brain)] : sim::BrainGraph{};
    // Most scene edits (a brush stroke, a moved wall) leave the brain alone: no rebuild.
    if (m_fresh && source == m_source && source.name == m_source.name && m_brainCount == std::size_t(count))
        return;
    m_brainCount = std::size_t(count);
    m_source = source;
    m_fresh = true;
    m_shown = source;
    if (needsLayout(m_shown))
        autoLayout(m_shown);
    emit graphChanged();
}

void BrainGraphModel::setBrainIndex(int index)
{
    const int count = int(m_document.scene().brains.size());
    m_brain = count == 0 ? -1 : std::clamp(index, 0, count - 1);
    m_fresh = false;
    refresh();
}

bool BrainGraphModel::hasBrain() const
{
    return m_brain >= 0 && std::size_t(m_brain) < m_document.scene().brains.size();
}

sim::NodeId BrainGraphModel::nextId() const
{
    sim::NodeId id = 0;
    for (const sim::BrainNode& n : graph().nodes)
        id = std::max(id, n.id);
    return id + 1;
}

bool BrainGraphModel::push(sim::BrainGraph after, const QString& text, bool merge)
{
    if (!hasBrain() || after == graph())
        return false;
    const sim::BrainGraph& before = m_document.scene().brains[std::size_t(m_brain)];
    m_document.undoStack()->push(new EditBrainCommand(m_document, std::size_t(m_brain), before, std::move(after), text, merge));
    return true;
}

sim::NodeId BrainGraphModel::addNode(const std::string& type, QPointF pos)
{
    const sim::NodeSpec* spec = sim::findNodeSpec(type);
    if (!spec || !hasBrain())
        return 0;
    sim::BrainGraph g = graph();
    sim::BrainNode node;
    node.id = nextId();
    node.type = type;
    node.position = {float(pos.x()), float(pos.y())};
    node.params = defaultParams(*spec);
    g.nodes.push_back(node);
    push(std::move(g), tr("Add %1 node").arg(QString::fromStdString(type)));
    return node.id;
}

bool BrainGraphModel::addLink(const sim::BrainLink& link, std::string* problem)
{
    const std::string why = hasBrain() ? linkProblem(graph(), link, &m_document.scene().brains) : "no brain is shown";
    if (problem)
        *problem = why;
    if (!why.empty())
        return false;
    sim::BrainGraph g = graph();
    g.links.push_back(link);
    return push(std::move(g), tr("Link node %1 to node %2").arg(link.fromNode).arg(link.toNode));
}

bool BrainGraphModel::remove(const std::vector<sim::NodeId>& nodes, const std::vector<std::size_t>& links)
{
    sim::BrainGraph g = graph();
    const std::set<sim::NodeId> gone(nodes.begin(), nodes.end());
    const std::set<std::size_t> goneLinks(links.begin(), links.end());
    std::erase_if(g.nodes, [&](const sim::BrainNode& n) { return gone.count(n.id) > 0; });
    std::vector<sim::BrainLink> kept;
    for (std::size_t i = 0; i < g.links.size(); ++i)
        if (!goneLinks.count(i) && !gone.count(g.links[i].fromNode) && !gone.count(g.links[i].toNode))
            kept.push_back(g.links[i]);
    g.links = std::move(kept);
    return push(std::move(g), nodes.empty() ? tr("Delete %n link(s)", nullptr, int(links.size()))
                                            : tr("Delete %n node(s)", nullptr, int(nodes.size())));
}

bool BrainGraphModel::moveNodes(const std::map<sim::NodeId, QPointF>& positions)
{
    sim::BrainGraph g = graph();
    for (sim::BrainNode& n : g.nodes)
        if (auto it = positions.find(n.id); it != positions.end())
            n.position = {float(it->second.x()), float(it->second.y())};
    return push(std::move(g), tr("Move %n node(s)", nullptr, int(positions.size())));
}

bool BrainGraphModel::setParam(sim::NodeId node, const sim::BrainParam& param, bool merge)
{
    const sim::BrainNode* n = graph().findNode(node);
    if (!n)
        return false;
    std::vector<sim::BrainParam> params = n->params;
    auto it = std::find_if(params.begin(), params.end(), [&](const sim::BrainParam& p) { return p.key == param.key; });
    if (it == params.end())
        params.push_back(param);
    else
        *it = param;
    return setParams(node, params, merge);
}

bool BrainGraphModel::setParams(sim::NodeId node, const std::vector<sim::BrainParam>& params, bool merge)
{
    sim::BrainGraph g = graph();
    for (sim::BrainNode& n : g.nodes)
        if (n.id == node)
            n.params = params;
    return push(std::move(g), tr("Edit node %1").arg(node), merge);
}

sim::BrainGraph BrainGraphModel::copy(const std::vector<sim::NodeId>& ids) const
{
    sim::BrainGraph out;
    const std::set<sim::NodeId> keep(ids.begin(), ids.end());
    for (const sim::BrainNode& n : graph().nodes)
        if (keep.count(n.id))
            out.nodes.push_back(n);
    for (const sim::BrainLink& l : graph().links)
        if (keep.count(l.fromNode) && keep.count(l.toNode))
            out.links.push_back(l);
    return out;
}

std::vector<sim::NodeId> BrainGraphModel::paste(const sim::BrainGraph& fragment, QPointF offset)
{
    if (!hasBrain() || fragment.nodes.empty())
        return {};
    sim::BrainGraph g = graph();
    std::map<sim::NodeId, sim::NodeId> ids;
    sim::NodeId next = nextId();
    std::vector<sim::NodeId> added;
    for (sim::BrainNode n : fragment.nodes) {
        ids[n.id] = next;
        n.id = next++;
        n.position += glm::vec2(float(offset.x()), float(offset.y()));
        added.push_back(n.id);
        g.nodes.push_back(std::move(n));
    }
    for (sim::BrainLink l : fragment.links) {
        l.fromNode = ids[l.fromNode];
        l.toNode = ids[l.toNode];
        g.links.push_back(l);
    }
    push(std::move(g), tr("Paste %n node(s)", nullptr, int(added.size())));
    return added;
}

bool BrainGraphModel::replace(const sim::BrainGraph& graph, const QString& text)
{
    return push(graph, text);
}

}  // namespace throng::editor
