#include "editor/brain/BrainView.h"

#include "editor/brain/BrainScene.h"
#include "editor/brain/NodeItem.h"

#include <QGraphicsProxyWidget>
#include <QKeyEvent>
#include <QPainter>
#include <QScrollBar>

#include <algorithm>
#include <cmath>

namespace throng::editor {

namespace {
constexpr double kMinZoom = 0.05, kMaxZoom = 4.0;

bool isGraphKey(const QKeyEvent* e)
{
    const int key = e->key();
    const Qt::KeyboardModifiers mods = e->modifiers() & ~Qt::KeypadModifier;
    if (mods == Qt::NoModifier || mods == Qt::ShiftModifier)
        return key == Qt::Key_Tab || key == Qt::Key_F || key == Qt::Key_Delete || key == Qt::Key_Backspace ||
               key == Qt::Key_Backtab;
    if (mods == Qt::ControlModifier || mods == (Qt::ControlModifier | Qt::ShiftModifier))
        return key == Qt::Key_C || key == Qt::Key_V || key == Qt::Key_D || key == Qt::Key_G;
    return false;
}
}  // namespace

BrainView::BrainView(BrainScene* scene, QWidget* parent) : QGraphicsView(scene, parent), m_scene(scene)
{
    setObjectName("brainView");
    setRenderHint(QPainter::Antialiasing);
    setDragMode(RubberBandDrag);
    setTransformationAnchor(AnchorUnderMouse);
    setViewportUpdateMode(SmartViewportUpdate);
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(320, 200);
}

void BrainView::fit(QRectF rect)
{
    if (rect.isEmpty())
        return;
    fitInView(rect.adjusted(-40, -40, 40, 40), Qt::KeepAspectRatio);
    const double z = std::clamp(transform().m11(), kMinZoom, 1.5);
    setTransform(QTransform::fromScale(z, z));
    centerOn(rect.center());
}

void BrainView::frameAll()
{
    QRectF r;
    for (NodeItem* n : m_scene->nodeItems())
        r |= n->sceneBoundingRect();
    fit(r);
}

void BrainView::frameSelection()
{
    QRectF r;
    for (NodeItem* n : m_scene->nodeItems())
        if (n->isSelected())
            r |= n->sceneBoundingRect();
    r.isEmpty() ? frameAll() : fit(r);
}

void BrainView::setHint(const QString& hint)
{
    if (hint == m_hint)
        return;
    m_hint = hint;
    viewport()->update();  // the whole view: the hint lies under no item's rectangle
}

void BrainView::drawForeground(QPainter* painter, const QRectF& rect)
{
    QGraphicsView::drawForeground(painter, rect);
    if (m_hint.isEmpty() || !m_scene->nodeItems().empty())
        return;
    painter->save();
    painter->resetTransform();  // the view's own pixels, whatever the zoom
    painter->setPen(QColor(160, 165, 172));  // the graph's own dark ground (BrainScene), whatever the theme
    const int margin = 32;
    const QRect box = viewport()->rect().adjusted(margin, margin, -margin, -margin);
    painter->drawText(box, Qt::AlignCenter | Qt::TextWordWrap, m_hint);
    painter->restore();
}

void BrainView::zoomBy(double factor)
{
    const double z = std::clamp(transform().m11() * factor, kMinZoom, kMaxZoom);
    const ViewportAnchor anchor = transformationAnchor();
    setTransformationAnchor(AnchorViewCenter);
    setTransform(QTransform::fromScale(z, z));
    setTransformationAnchor(anchor);
}

bool BrainView::event(QEvent* event)
{
    // The window's shortcuts (F frames the viewport, Delete, Ctrl+C...) must not steal
    // the graph's keys while the graph has the focus; Tab must not move the focus.
    if (event->type() == QEvent::ShortcutOverride && isGraphKey(static_cast<QKeyEvent*>(event)) &&
        !qobject_cast<QGraphicsProxyWidget*>(scene()->focusItem() ? scene()->focusItem()->toGraphicsObject() : nullptr)) {
        event->accept();
        return true;
    }
    if (event->type() == QEvent::KeyPress) {
        auto* key = static_cast<QKeyEvent*>(event);
        if (key->key() == Qt::Key_Tab && key->modifiers() == Qt::NoModifier && !scene()->focusItem()) {
            emit paletteRequested(viewport()->rect().contains(m_lastMouse) ? m_lastMouse : viewport()->rect().center());
            return true;
        }
    }
    return QGraphicsView::event(event);
}

void BrainView::keyPressEvent(QKeyEvent* event)
{
    if (scene()->focusItem()) {  // an inline parameter editor has the keys
        QGraphicsView::keyPressEvent(event);
        return;
    }
    const bool ctrl = event->modifiers() & Qt::ControlModifier;
    const bool shift = event->modifiers() & Qt::ShiftModifier;
    switch (event->key()) {
    case Qt::Key_F:
        shift ? frameSelection() : frameAll();
        return;
    case Qt::Key_Delete:
    case Qt::Key_Backspace:
        m_scene->deleteSelection();
        return;
    case Qt::Key_C:
        if (ctrl) { emit copyRequested(); return; }
        break;
    case Qt::Key_V:
        if (ctrl) { emit pasteRequested(); return; }
        break;
    case Qt::Key_D:
        if (ctrl) { emit duplicateRequested(); return; }
        break;
    case Qt::Key_G:
        if (ctrl) { shift ? emit expandRequested() : emit collapseRequested(); return; }
        break;
    default:
        break;
    }
    QGraphicsView::keyPressEvent(event);
}

void BrainView::wheelEvent(QWheelEvent* event)
{
    const double steps = event->angleDelta().y() / 120.0;
    const double z = std::clamp(transform().m11() * std::pow(1.2, steps), kMinZoom, kMaxZoom);
    setTransform(QTransform::fromScale(z, z));
    event->accept();
}

void BrainView::mousePressEvent(QMouseEvent* event)
{
    if (event->button() == Qt::MiddleButton ||
        (event->button() == Qt::LeftButton && event->modifiers() == Qt::AltModifier)) {
        m_panning = true;
        m_panFrom = event->position().toPoint();
        setCursor(Qt::ClosedHandCursor);
        event->accept();
        return;
    }
    QGraphicsView::mousePressEvent(event);
}

void BrainView::mouseMoveEvent(QMouseEvent* event)
{
    m_lastMouse = event->position().toPoint();
    if (m_panning) {
        const QPoint d = event->position().toPoint() - m_panFrom;
        m_panFrom = event->position().toPoint();
        horizontalScrollBar()->setValue(horizontalScrollBar()->value() - d.x());
        verticalScrollBar()->setValue(verticalScrollBar()->value() - d.y());
        event->accept();
        return;
    }
    QGraphicsView::mouseMoveEvent(event);
}

void BrainView::mouseReleaseEvent(QMouseEvent* event)
{
    if (m_panning) {
        m_panning = false;
        unsetCursor();
        event->accept();
        return;
    }
    QGraphicsView::mouseReleaseEvent(event);
}

}  // namespace throng::editor
