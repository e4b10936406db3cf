#include "editor/brain/NodeItem.h"

#include "editor/brain/BrainLinkRules.h"
#include "editor/brain/BrainScene.h"
#include "editor/brain/FuzzCurve.h"
#include "editor/brain/FuzzCurveItem.h"
#include "editor/brain/PortItem.h"

#include <QPainter>
#include <QStyleOptionGraphicsItem>

#include <algorithm>
#include <utility>

namespace throng::editor {

namespace {
constexpr double kTitle = 24.0, kPortRow = 20.0, kParamRow = 18.0, kCurve = 74.0;
constexpr double kNoteW = 320.0, kNoteH = 150.0;

QColor categoryColour(const std::string& category)
{
    if (category == "input") return {60, 110, 170};
    if (category == "fuzz") return {60, 140, 90};
    if (category == "rule") return {150, 100, 50};
    if (category == "defuzz") return {130, 70, 140};
    if (category == "math") return {90, 90, 110};
    if (category == "filter") return {40, 130, 140};
    if (category == "state") return {150, 130, 40};
    if (category == "output") return {170, 60, 60};
    return {100, 100, 100};
}

QString formatValue(float v)
{
    return QString::number(double(v), 'g', 3);
}
}  // namespace

NodeItem::NodeItem(const sim::BrainGraph& graph, const sim::BrainNode& node,
                   const std::vector<sim::BrainGraph>* library)
{
    setFlags(ItemIsMovable | ItemIsSelectable | ItemSendsScenePositionChanges);
    setNode(graph, node, library);
}

void NodeItem::setNode(const sim::BrainGraph& graph, const sim::BrainNode& node,
                       const std::vector<sim::BrainGraph>* library)
{
    prepareGeometryChange();
    m_node = node;
    m_spec = sim::findNodeSpec(node.type);
    setZValue(isNote() ? -1 : 0);
    const std::size_t params = m_spec ? m_spec->params.size() : 0;
    rebuildPorts(graph, library);
    const double paramsTop = portRowsBottom();
    m_height = isNote() ? kNoteH : paramsTop + double(params) * kParamRow + 6.0;
    // An item is reused for whatever node has its id next, in this brain or in another
    // scene's, so the curve must follow the node's type and row count, not the item's past.
    if (isFuzzType(node.type)) {
        const QRectF rect(8.0, m_height, kWidth - 16.0, kCurve - 8.0);
        if (!m_curve)
            m_curve = new FuzzCurveItem(this, rect);
        m_curve->setRect(rect);
        m_curve->setCurve(node.type, node.params);
        m_height += kCurve;
    } else {
        delete std::exchange(m_curve, nullptr);
    }
    setPos(node.position.x, node.position.y);
    update();
}

void NodeItem::rebuildPorts(const sim::BrainGraph& graph, const std::vector<sim::BrainGraph>* library)
{
    const int inputs = m_spec ? inputPortCount(graph, m_node) : 0;
    const int outputs = m_spec ? outputPortCount(graph, m_node, library) : 0;
    std::vector<sim::PortKind> outKinds;
    for (int i = 0; i < outputs; ++i)
        outKinds.push_back(outputKind(graph, m_node.id, i));
    bool same = int(m_inputs.size()) == inputs && int(m_outputs.size()) == outputs;
    for (int i = 0; same && i < outputs; ++i)
        same = m_outputs[std::size_t(i)]->kind() == outKinds[std::size_t(i)];
    if (same)
        return;
    for (PortItem* p : m_inputs)
        delete p;
    for (PortItem* p : m_outputs)
        delete p;
    m_inputs.clear();
    m_outputs.clear();
    for (int i = 0; i < inputs; ++i) {
        const sim::PortSpec* spec = inputPortSpec(*m_spec, i);
        auto* port = new PortItem(this, true, i, spec->kind, QString::fromStdString(spec->name));
        port->setParentItem(this);
        port->setPos(0.0, kTitle + kPortRow * (i + 0.5));
        m_inputs.push_back(port);
    }
    for (int i = 0; i < outputs; ++i) {
        const sim::PortSpec* spec = outputPortSpec(*m_spec, i);
        auto* port = new PortItem(this, false, i, outKinds[std::size_t(i)], QString::fromStdString(spec->name));
        port->setParentItem(this);
        port->setPos(kWidth, kTitle + kPortRow * (i + 0.5));
        m_outputs.push_back(port);
    }
}

double NodeItem::portRowsBottom() const
{
    return kTitle + kPortRow * double(std::max(m_inputs.size(), m_outputs.size())) + 2.0;
}

PortItem* NodeItem::inputPort(int index) const
{
    return index >= 0 && std::size_t(index) < m_inputs.size() ? m_inputs[std::size_t(index)] : nullptr;
}

PortItem* NodeItem::outputPort(int index) const
{
    return index >= 0 && std::size_t(index) < m_outputs.size() ? m_outputs[std::size_t(index)] : nullptr;
}

QRectF NodeItem::boundingRect() const
{
    return QRectF(-2.0, -2.0, (isNote() ? kNoteW : kWidth) + 4.0, m_height + 4.0);
}

QRectF NodeItem::paramRect(int row) const
{
    if (isNote())
        return QRectF(6.0, kTitle, kNoteW - 12.0, kNoteH - kTitle - 6.0);
    return QRectF(8.0, portRowsBottom() + kParamRow * row, kWidth - 16.0, kParamRow);
}

int NodeItem::paramAt(QPointF local) const
{
    const int rows = m_spec ? int(m_spec->params.size()) : 0;
    for (int r = 0; r < rows; ++r)
        if (paramRect(r).contains(local))
            return r;
    return -1;
}

const sim::ParamSpec* NodeItem::paramSpec(int row) const
{
    return m_spec && row >= 0 && std::size_t(row) < m_spec->params.size() ? &m_spec->params[std::size_t(row)] : nullptr;
}

QString NodeItem::paramText(int row) const
{
    const sim::ParamSpec* spec = paramSpec(row);
    if (!spec)
        return {};
    for (const sim::BrainParam& p : m_node.params)
        if (p.key == spec->key) {
            if (!p.text.empty())
                return QString::fromStdString(p.text);
            QStringList parts;
            for (float v : p.numbers)
                parts << formatValue(v);
            return parts.join(' ');
        }
    return {};
}

void NodeItem::setError(const QString& message)
{
    m_error = message;
    setToolTip(message);
    update();
}

void NodeItem::setLiveValues(const std::vector<std::optional<std::vector<float>>>& outputs)
{
    m_live = outputs;
    update();
}

bool NodeItem::showsBars() const
{
    return m_spec && (m_spec->category == "fuzz" || m_spec->category == "rule");
}

QString NodeItem::liveText(int port) const
{
    if (port < 0 || std::size_t(port) >= m_live.size() || !m_live[std::size_t(port)] ||
        m_live[std::size_t(port)]->empty())
        return {};
    const std::vector<float>& v = *m_live[std::size_t(port)];
    return v.size() == 1 ? formatValue(v[0]) : QStringLiteral("%1 (%2)").arg(formatValue(v[0])).arg(v.size());
}

void NodeItem::paint(QPainter* painter, const QStyleOptionGraphicsItem* option, QWidget*)
{
    const double w = isNote() ? kNoteW : kWidth;
    const QRectF body(0.0, 0.0, w, m_height);
    const QColor head = categoryColour(m_spec ? m_spec->category : std::string());
    QPen outline(isSelected() ? QColor(255, 210, 80) : QColor(15, 15, 15), isSelected() ? 2.5 : 1.0);
    if (!m_error.isEmpty())
        outline = QPen(QColor(235, 40, 40), 3.0);
    painter->setPen(outline);
    painter->setBrush(isNote() ? QColor(200, 180, 90, 70) : QColor(48, 50, 56));
    painter->drawRoundedRect(body, 5.0, 5.0);
    painter->setBrush(isNote() ? QColor(200, 180, 90, 140) : head);
    painter->drawRoundedRect(QRectF(0.0, 0.0, w, kTitle), 5.0, 5.0);
    const double lod = option->levelOfDetailFromTransform(painter->worldTransform());
    if (lod < 0.35)
        return;  // Too small to read: boxes and links are enough (keeps big graphs fluid).
    painter->setPen(Qt::white);
    const QString title = m_node.label.empty() ? QString::fromStdString(m_node.type) : QString::fromStdString(m_node.label);
    painter->drawText(QRectF(8.0, 0.0, w - 16.0, kTitle), Qt::AlignVCenter | Qt::AlignLeft,
                      QStringLiteral("%1  #%2").arg(title).arg(m_node.id));
    if (isNote()) {
        painter->drawText(paramRect(0), Qt::TextWordWrap, paramText(0));
        return;
    }
    QFont small = painter->font();
    small.setPointSizeF(small.pointSizeF() * 0.85);
    painter->setFont(small);
    painter->setPen(QColor(210, 210, 210));
    for (std::size_t i = 0; i < m_inputs.size(); ++i)
        painter->drawText(QRectF(10.0, kTitle + kPortRow * double(i), w / 2.0, kPortRow), Qt::AlignVCenter,
                          QString::fromStdString(inputPortSpec(*m_spec, int(i))->name));
    for (std::size_t i = 0; i < m_outputs.size(); ++i) {
        const QRectF row(w / 2.0, kTitle + kPortRow * double(i), w / 2.0 - 10.0, kPortRow);
        const QString live = liveText(int(i));
        if (!live.isEmpty() && showsBars()) {
            const float v = std::clamp((*m_live[i])[0], 0.0f, 1.0f);
            const QRectF bar(row.left(), row.top() + 4.0, row.width() * 0.6, row.height() - 8.0);
            painter->fillRect(bar, QColor(30, 30, 30));
            painter->fillRect(QRectF(bar.topLeft(), QSizeF(bar.width() * double(v), bar.height())), QColor(250, 200, 60));
        }
        painter->drawText(row, Qt::AlignVCenter | Qt::AlignRight,
                          live.isEmpty() ? QString::fromStdString(outputPortSpec(*m_spec, int(i))->name) : live);
    }
    for (int r = 0; r < int(m_spec->params.size()); ++r) {
        const QString value = paramText(r);
        painter->setPen(value.isEmpty() ? QColor(130, 130, 130) : QColor(235, 235, 235));
        painter->drawText(paramRect(r), Qt::AlignVCenter,
                          QStringLiteral("%1: %2").arg(QString::fromStdString(m_spec->params[std::size_t(r)].key),
                                                       value.isEmpty() ? QStringLiteral("-") : value));
    }
}

QVariant NodeItem::itemChange(GraphicsItemChange change, const QVariant& value)
{
    if (change == ItemScenePositionHasChanged)
        if (auto* s = dynamic_cast<BrainScene*>(scene()))
            s->nodeMoved(this);
    return QGraphicsItem::itemChange(change, value);
}

}  // namespace throng::editor
