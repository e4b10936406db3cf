#include "editor/brain/FuzzCurveItem.h"

#include "editor/brain/FuzzCurve.h"

#include <QGraphicsSceneMouseEvent>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>

namespace throng::editor {

namespace {
constexpr double kHandleHalf = 5.0;
constexpr double kPad = 6.0;
}

FuzzCurveItem::FuzzCurveItem(QGraphicsItem* parent, QRectF rect) : QGraphicsItem(parent), m_rect(rect)
{
    setAcceptedMouseButtons(Qt::LeftButton);
    setToolTip(QObject::tr("Drag a handle to change the membership function"));
}

void FuzzCurveItem::setCurve(const std::string& nodeType, const std::vector<sim::BrainParam>& params)
{
    m_type = nodeType;
    m_params = params;
    if (m_drag < 0)
        fuzzDomain(m_type, m_params, m_lo, m_hi);
    update();
}

void FuzzCurveItem::setRect(QRectF rect)
{
    if (rect == m_rect)
        return;
    prepareGeometryChange();
    m_rect = rect;
}

void FuzzCurveItem::setInputValue(std::optional<float> x)
{
    m_input = x;
    update();
}

int FuzzCurveItem::handleCount() const
{
    return int(fuzzHandles(m_type, m_params).size());
}

QPointF FuzzCurveItem::toLocal(float x, float truth) const
{
    const QRectF r = m_rect.adjusted(kPad, kPad, -kPad, -kPad);
    const double u = m_hi > m_lo ? double(x - m_lo) / double(m_hi - m_lo) : 0.5;
    return {r.left() + u * r.width(), r.bottom() - double(truth) * r.height()};
}

float FuzzCurveItem::toValue(double localX) const
{
    const QRectF r = m_rect.adjusted(kPad, kPad, -kPad, -kPad);
    return m_lo + float((localX - r.left()) / r.width()) * (m_hi - m_lo);
}

QPointF FuzzCurveItem::handleScenePos(int handle) const
{
    const std::vector<FuzzHandle> h = fuzzHandles(m_type, m_params);
    if (handle < 0 || std::size_t(handle) >= h.size())
        return {};
    return mapToScene(toLocal(h[std::size_t(handle)].x, h[std::size_t(handle)].truth));
}

void FuzzCurveItem::paint(QPainter* painter, const QStyleOptionGraphicsItem*, QWidget*)
{
    painter->setPen(Qt::NoPen);
    painter->setBrush(QColor(25, 28, 32));
    painter->drawRect(m_rect);
    QPainterPath curve;
    constexpr int kSamples = 64;
    for (int i = 0; i <= kSamples; ++i) {
        const float x = m_lo + (m_hi - m_lo) * float(i) / kSamples;
        const QPointF p = toLocal(x, fuzzTruth(m_type, m_params, x));
        i == 0 ? curve.moveTo(p) : curve.lineTo(p);
    }
    painter->setBrush(Qt::NoBrush);
    painter->setPen(QPen(QColor(120, 220, 140), 2.0));
    painter->drawPath(curve);
    if (m_input && *m_input >= m_lo && *m_input <= m_hi) {
        painter->setPen(QPen(QColor(250, 200, 60), 1.5, Qt::DashLine));
        painter->drawLine(toLocal(*m_input, 0.0f), toLocal(*m_input, 1.0f));
    }
    painter->setPen(QPen(QColor(20, 20, 20), 1.0));
    painter->setBrush(QColor(240, 240, 240));
    for (const FuzzHandle& h : fuzzHandles(m_type, m_params)) {
        const QPointF c = toLocal(h.x, h.truth);
        painter->drawRect(QRectF(c.x() - kHandleHalf, c.y() - kHandleHalf, 2 * kHandleHalf, 2 * kHandleHalf));
    }
    painter->setPen(QColor(160, 160, 160));
    QFont font = painter->font();
    font.setPointSizeF(7.0);
    painter->setFont(font);
    const QRectF r = m_rect.adjusted(2, 0, -2, 0);
    painter->drawText(r, Qt::AlignLeft | Qt::AlignBottom, QString::number(double(m_lo), 'g', 3));
    painter->drawText(r, Qt::AlignRight | Qt::AlignBottom, QString::number(double(m_hi), 'g', 3));
}

void FuzzCurveItem::mousePressEvent(QGraphicsSceneMouseEvent* event)
{
    const std::vector<FuzzHandle> h = fuzzHandles(m_type, m_params);
    m_drag = -1;
    double best = 2.0 * kHandleHalf;
    for (std::size_t i = 0; i < h.size(); ++i) {
        const QPointF d = toLocal(h[i].x, h[i].truth) - event->pos();
        const double dist = std::max(std::abs(d.x()), std::abs(d.y()));
        if (dist <= best) {
            best = dist;
            m_drag = int(i);
        }
    }
    if (m_drag < 0)
        event->ignore();
}

void FuzzCurveItem::mouseMoveEvent(QGraphicsSceneMouseEvent* event)
{
    if (m_drag < 0)
        return;
    m_params = moveFuzzHandle(m_type, m_params, m_drag, toValue(event->pos().x()));
    update();
}

void FuzzCurveItem::mouseReleaseEvent(QGraphicsSceneMouseEvent* event)
{
    if (m_drag < 0)
        return;
    m_params = moveFuzzHandle(m_type, m_params, m_drag, toValue(event->pos().x()));
    m_drag = -1;
    // The commit rebuilds the scene, which hands this item a new commit: call a copy.
    if (const Commit commit = m_commit)
        commit(m_params);
}

}  // namespace throng::editor
