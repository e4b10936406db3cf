#include "editor/brain/BrainScene.h"

#include "editor/brain/BrainLinkRules.h"
#include "editor/brain/FuzzCurveItem.h"
#include "editor/brain/LinkItem.h"
#include "editor/brain/NodeItem.h"
#include "editor/brain/ParamText.h"
#include "editor/brain/PortItem.h"

#include <QComboBox>
#include <QGraphicsProxyWidget>
#include <QGraphicsSceneMouseEvent>
#include <QGraphicsView>
#include <QLineEdit>

#include <set>

namespace throng::editor {

BrainScene::BrainScene(BrainGraphModel& model, QObject* parent) : QGraphicsScene(parent), m_model(model)
{
    setBackgroundBrush(QColor(34, 36, 40));
    connect(&m_model, &BrainGraphModel::graphChanged, this, &BrainScene::sync);
    sync();
}

NodeItem* BrainScene::nodeItem(sim::NodeId id) const
{
    auto it = m_nodes.find(id);
    return it == m_nodes.end() ? nullptr : it->second;
}

std::vector<NodeItem*> BrainScene::nodeItems() const
{
    std::vector<NodeItem*> out;
    for (const auto& [id, item] : m_nodes)
        out.push_back(item);
    return out;
}

std::vector<sim::NodeId> BrainScene::selectedNodes() const
{
    std::vector<sim::NodeId> out;
    for (const auto& [id, item] : m_nodes)
        if (item->isSelected())
            out.push_back(id);
    return out;
}

void BrainScene::sync()
{
    closeEditor();
    const sim::BrainGraph& g = m_model.graph();
    std::set<sim::NodeId> present;
    for (const sim::BrainNode& n : g.nodes) {
        present.insert(n.id);
        NodeItem* item = nodeItem(n.id);
        if (item) {
            item->setNode(g, n, &m_model.document().scene().brains);
        } else {
            item = new NodeItem(g, n, &m_model.document().scene().brains);
            addItem(item);
            m_nodes[n.id] = item;
        }
        // A kept item may have gained its curve just now (another node took its id).
        if (FuzzCurveItem* curve = item->fuzzCurve()) {
            const sim::NodeId id = n.id;
            curve->setCommit([this, id](const std::vector<sim::BrainParam>& params) {
                m_model.setParams(id, params, false);
            });
        }
    }
    for (auto it = m_nodes.begin(); it != m_nodes.end();) {
        if (present.count(it->first)) {
            ++it;
            continue;
        }
        delete it->second;
        it = m_nodes.erase(it);
    }
    for (LinkItem* link : m_links)
        delete link;
    m_links.clear();
    for (std::size_t i = 0; i < g.links.size(); ++i) {
        auto* link = new LinkItem(int(i));
        addItem(link);
        m_links.push_back(link);
        updateLinkEnds(link);
    }
    const QRectF bounds = itemsBoundingRect();
    setSceneRect(bounds.adjusted(-3000, -3000, 3000, 3000));
    setErrors(m_errors);
    setLiveValues(m_live);
}

void BrainScene::updateLinkEnds(LinkItem* link)
{
    const sim::BrainGraph& g = m_model.graph();
    if (link->index() < 0 || std::size_t(link->index()) >= g.links.size())
        return;
    const sim::BrainLink& l = g.links[std::size_t(link->index())];
    NodeItem* from = nodeItem(l.fromNode);
    NodeItem* to = nodeItem(l.toNode);
    PortItem* out = from ? from->outputPort(int(l.fromPort)) : nullptr;
    PortItem* in = to ? to->inputPort(int(l.toPort)) : nullptr;
    if (out && in)
        link->setEnds(out->centre(), in->centre());
}

void BrainScene::nodeMoved(NodeItem* node)
{
    // During sync() the link items may still be those of the previous graph.
    const sim::BrainGraph& g = m_model.graph();
    for (LinkItem* link : m_links) {
        if (std::size_t(link->index()) >= g.links.size())
            continue;
        const sim::BrainLink& l = g.links[std::size_t(link->index())];
        if (l.fromNode == node->id() || l.toNode == node->id())
            updateLinkEnds(link);
    }
}

void BrainScene::setErrors(const std::vector<sim::BrainError>& errors)
{
    m_errors = errors;
    std::map<sim::NodeId, QStringList> byNode;
    std::map<int, QStringList> byLink;
    for (const sim::BrainError& e : errors) {
        if (e.link >= 0)
            byLink[e.link] << QString::fromStdString(e.message);
        else if (e.node != 0)
            byNode[e.node] << QString::fromStdString(e.message);
    }
    for (const auto& [id, item] : m_nodes)
        item->setError(byNode.count(id) ? byNode[id].join('\n') : QString());
    for (LinkItem* link : m_links)
        link->setError(byLink.count(link->index()) ? byLink[link->index()].join('\n') : QString());
}

void BrainScene::setLiveValues(const std::vector<sim::BrainNodeValue>& values)
{
    m_live = values;
    std::map<std::pair<sim::NodeId, std::uint32_t>, const std::vector<float>*> byPort;
    for (const sim::BrainNodeValue& v : values)
        byPort[{v.node, v.port}] = &v.values;
    auto valueOf = [&](sim::NodeId n, std::uint32_t p) -> std::optional<std::vector<float>> {
        auto it = byPort.find({n, p});
        if (it == byPort.end())
            return std::nullopt;
        return *it->second;
    };
    for (const auto& [id, item] : m_nodes) {
        std::vector<std::optional<std::vector<float>>> outs;
        if (!values.empty())
            for (int p = 0; p < item->outputCount(); ++p)
                outs.push_back(valueOf(id, std::uint32_t(p)));
        item->setLiveValues(outs);
        if (item->fuzzCurve())
            item->fuzzCurve()->setInputValue(std::nullopt);
    }
    const sim::BrainGraph& g = m_model.graph();
    for (LinkItem* link : m_links) {
        const sim::BrainLink& l = g.links[std::size_t(link->index())];
        const std::optional<std::vector<float>> v = valueOf(l.fromNode, l.fromPort);
        const std::optional<float> flow = v && !v->empty() ? std::optional<float>((*v)[0]) : std::nullopt;
        link->setFlow(flow);
        if (NodeItem* to = nodeItem(l.toNode); to && to->fuzzCurve() && l.toPort == 0)
            to->fuzzCurve()->setInputValue(flow);
    }
}

bool BrainScene::deleteSelection()
{
    std::vector<std::size_t> links;
    for (LinkItem* link : m_links)
        if (link->isSelected())
            links.push_back(std::size_t(link->index()));
    const std::vector<sim::NodeId> nodes = selectedNodes();
    if (nodes.empty() && links.empty())
        return false;
    return m_model.remove(nodes, links);
}

PortItem* BrainScene::portNear(QPointF scenePos, const PortItem* except) const
{
    double scale = 1.0;
    if (!views().isEmpty())
        scale = std::max(0.05, views().front()->transform().m11());
    const double r = 10.0 / scale;
    PortItem* best = nullptr;
    double bestD = r * r;
    for (QGraphicsItem* item : items(QRectF(scenePos - QPointF(r, r), QSizeF(2 * r, 2 * r)))) {
        auto* port = qgraphicsitem_cast<PortItem*>(item);
        if (!port || port == except)
            continue;
        const QPointF d = port->centre() - scenePos;
        if (QPointF::dotProduct(d, d) <= bestD) {
            bestD = QPointF::dotProduct(d, d);
            best = port;
        }
    }
    return best;
}

sim::BrainLink BrainScene::linkBetween(const PortItem* a, const PortItem* b) const
{
    const PortItem* out = a->isInput() ? b : a;
    const PortItem* in = a->isInput() ? a : b;
    return {out->node()->id(), std::uint32_t(out->index()), in->node()->id(), std::uint32_t(in->index())};
}

void BrainScene::mousePressEvent(QGraphicsSceneMouseEvent* event)
{
    if (event->button() == Qt::LeftButton && !m_editor) {
        if (PortItem* port = portNear(event->scenePos(), nullptr)) {
            m_dragFrom = port;
            m_dragLink = new LinkItem(-1);
            addItem(m_dragLink);
            m_dragLink->setEnds(port->centre(), port->centre());
            event->accept();
            return;
        }
    }
    if (m_editor && !m_editor->geometry().contains(event->scenePos()))
        closeEditor();
    QGraphicsScene::mousePressEvent(event);
}

void BrainScene::mouseMoveEvent(QGraphicsSceneMouseEvent* event)
{
    if (!m_dragFrom) {
        QGraphicsScene::mouseMoveEvent(event);
        return;
    }
    if (m_dragOver)
        m_dragOver->setDropState(0);
    m_dragOver = portNear(event->scenePos(), m_dragFrom);
    if (m_dragOver && m_dragOver->isInput() == m_dragFrom->isInput())
        m_dragOver = nullptr;
    int state = 0;
    QPointF end = event->scenePos();
    if (m_dragOver) {
        state = linkProblem(m_model.graph(), linkBetween(m_dragFrom, m_dragOver), &m_model.document().scene().brains)
                        .empty() ? 1 : -1;
        m_dragOver->setDropState(state);
        end = m_dragOver->centre();
    }
    m_dragLink->setDragState(state);
    if (m_dragFrom->isInput())
        m_dragLink->setEnds(end, m_dragFrom->centre());
    else
        m_dragLink->setEnds(m_dragFrom->centre(), end);
}

void BrainScene::mouseReleaseEvent(QGraphicsSceneMouseEvent* event)
{
    if (m_dragFrom) {
        PortItem* from = std::exchange(m_dragFrom, nullptr);
        PortItem* over = std::exchange(m_dragOver, nullptr);
        delete std::exchange(m_dragLink, nullptr);
        if (over) {
            over->setDropState(0);
            std::string problem;
            if (m_model.addLink(linkBetween(from, over), &problem))
                emit linkAdded();
            else
                emit linkRefused(QString::fromStdString(problem));
        } else if (!portNear(event->scenePos(), from)) {
            emit linkDroppedOnEmpty(from->node()->id(), from->index(), from->isInput(), from->kind(), event->scenePos());
        }
        return;
    }
    QGraphicsScene::mouseReleaseEvent(event);
    std::map<sim::NodeId, QPointF> moved;
    for (const auto& [id, item] : m_nodes)
        if (item->pos() != QPointF(item->node().position.x, item->node().position.y))
            moved[id] = item->pos();
    if (!moved.empty())
        m_model.moveNodes(moved);
}

void BrainScene::mouseDoubleClickEvent(QGraphicsSceneMouseEvent* event)
{
    for (QGraphicsItem* item : items(event->scenePos())) {
        auto* node = qgraphicsitem_cast<NodeItem*>(item);
        if (!node)
            continue;
        const int row = node->paramAt(node->mapFromScene(event->scenePos()));
        if (row >= 0 && editParam(node, row)) {
            event->accept();
            return;
        }
    }
    QGraphicsScene::mouseDoubleClickEvent(event);
}

QWidget* BrainScene::editParam(NodeItem* node, int row)
{
    const sim::ParamSpec* spec = node->paramSpec(row);
    if (!spec)
        return nullptr;
    closeEditor();
    const sim::NodeId id = node->id();
    const sim::ParamSpec paramSpec = *spec;
    QWidget* editor = nullptr;
    if (spec->type == sim::ParamType::Choice) {
        auto* combo = new QComboBox;
        for (const std::string& c : spec->choices)
            combo->addItem(QString::fromStdString(c));
        combo->setCurrentText(node->paramText(row));
        connect(combo, &QComboBox::activated, this, [this, combo, id, paramSpec] {
            commitParam(id, paramSpec, combo->currentText());
        });
        editor = combo;
    } else {
        auto* line = new QLineEdit(node->paramText(row));
        line->selectAll();
        connect(line, &QLineEdit::returnPressed, this, [this, line, id, paramSpec] {
            commitParam(id, paramSpec, line->text());
        });
        editor = line;
    }
    editor->setObjectName("brainParamEditor");
    const QRectF rect = node->paramRect(row);
    editor->setFixedSize(int(rect.width()), std::max(22, int(rect.height()) + 4));
    m_editor = addWidget(editor);
    m_editor->setZValue(10);
    m_editor->setPos(node->mapToScene(rect.topLeft()));
    editor->setFocus();
    setFocusItem(m_editor);
    return editor;
}

void BrainScene::commitParam(sim::NodeId node, const sim::ParamSpec& spec, const QString& text)
{
    sim::BrainParam param;
    const QString problem = parseParamText(spec, text, param);
    if (!problem.isEmpty()) {
        emit paramRefused(problem);  // The editor stays open to fix the text.
        return;
    }
    closeEditor();
    m_model.setParam(node, param);
}

QWidget* BrainScene::paramEditor() const
{
    return m_editor ? m_editor->widget() : nullptr;
}

void BrainScene::closeEditor()
{
    if (!m_editor)
        return;
    QGraphicsProxyWidget* editor = std::exchange(m_editor, nullptr);
    removeItem(editor);
    editor->deleteLater();
}

}  // namespace throng::editor
