#include "editor/tools/BrushTool.h"

#include "editor/tools/BrushOverlay.h"
#include "editor/viewport/Viewport.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QSignalBlocker>

#include <algorithm>
#include <cmath>

namespace throng::editor {

BrushTool::BrushTool(SceneDocument& document, Viewport& viewport, float radiusM, QObject* parent)
    : ViewportTool(document, viewport, parent), m_radiusM(std::clamp(radiusM, kMinRadiusM, kMaxRadiusM))
{
}

void BrushTool::setRadiusM(float radiusM)
{
    radiusM = std::clamp(radiusM, kMinRadiusM, kMaxRadiusM);
    if (radiusM == m_radiusM)
        return;
    m_radiusM = radiusM;
    emit radiusChanged(m_radiusM);
    emit overlayChanged();
}

std::optional<glm::vec3> BrushTool::diskCentre() const
{
    return m_resizing ? std::optional(m_resizeCentre) : m_cursor;
}

void BrushTool::mousePressed(const ToolMouse& mouse)
{
    m_cursor = mouse.ground;
    if (!mouse.ground)
        return;
    if (mouse.modifiers & Qt::ControlModifier) {
        m_resizing = true;
        m_resizeCentre = *mouse.ground;
        m_resizeStartX = mouse.pixel.x();
        m_resizeStartRadiusM = m_radiusM;
        // One metre on the ground at the disk's centre, in pixels, the way the screen shows
        // it best: the rim then keeps up with the mouse in the top view and in 3D.
        const QPointF c = viewport().worldToPixel(m_resizeCentre);
        const QPointF dx = viewport().worldToPixel(m_resizeCentre + glm::vec3(1.0f, 0.0f, 0.0f)) - c;
        const QPointF dz = viewport().worldToPixel(m_resizeCentre + glm::vec3(0.0f, 0.0f, 1.0f)) - c;
        m_pixelsPerM = std::max({std::abs(dx.x()), std::abs(dz.x()), 1e-3});
        setState(State::Dragging);
        emit overlayChanged();
        return;
    }
    if (!strokeAllowed())
        return;
    setState(State::Dragging);
    strokeBegan({mouse.ground->x, mouse.ground->z});
    emit overlayChanged();
}

void BrushTool::mouseMoved(const ToolMouse& mouse)
{
    if (m_resizing) {
        resizeTo(mouse.pixel);
        return;
    }
    m_cursor = mouse.ground;
    if (state() == State::Dragging && mouse.ground)
        strokeMoved({mouse.ground->x, mouse.ground->z});
    else if (state() != State::Dragging)
        setState(mouse.ground ? State::Hover : State::Idle);
    emit overlayChanged();
}

void BrushTool::mouseReleased(const ToolMouse& mouse)
{
    if (m_resizing) {
        resizeTo(mouse.pixel);
        endResize(true);
        m_cursor = mouse.ground;
        emit overlayChanged();
        return;
    }
    const bool stroking = state() == State::Dragging;
    mouseMoved(mouse);
    if (stroking)
        strokeEnded();
    setState(mouse.ground ? State::Hover : State::Idle);
    emit overlayChanged();
}

void BrushTool::resizeTo(QPointF pixel)
{
    setRadiusM(m_resizeStartRadiusM + float((pixel.x() - m_resizeStartX) / m_pixelsPerM));
}

void BrushTool::endResize(bool keep)
{
    if (!keep)
        setRadiusM(m_resizeStartRadiusM);
    m_resizing = false;
    setState(State::Idle);
}

bool BrushTool::keyPressed(QKeyEvent* event)
{
    const bool grow = event->key() == Qt::Key_BracketRight, shrink = event->key() == Qt::Key_BracketLeft;
    if ((grow || shrink) && !m_resizing) {
        setRadiusM(grow ? m_radiusM * kRadiusStep : m_radiusM / kRadiusStep);
        return true;
    }
    if (event->key() == Qt::Key_Escape && m_resizing) {
        endResize(false);
        emit overlayChanged();
        return true;
    }
    return ViewportTool::keyPressed(event);
}

void BrushTool::cancel()
{
    if (m_resizing)
        endResize(false);
    setState(State::Idle);
    m_cursor.reset();
    emit overlayChanged();
}

void BrushTool::drawOverlay(QPainter& painter) const
{
    if (const std::optional<glm::vec3> centre = diskCentre())
        drawBrushCircle(painter, viewport(), *centre, m_radiusM, brushColour());
}

void BrushTool::addRadiusOption(QWidget* box, QHBoxLayout* row, const QString& objectName)
{
    auto* spin = new QDoubleSpinBox(box);
    spin->setObjectName(objectName);
    spin->setRange(double(kMinRadiusM), double(kMaxRadiusM));
    spin->setSingleStep(0.5);
    spin->setDecimals(2);
    spin->setValue(double(m_radiusM));
    spin->setToolTip(tr("Brush radius in metres; [ and ] or Ctrl+drag in the viewport change it"));
    connect(spin, &QDoubleSpinBox::valueChanged, this, [this](double v) { setRadiusM(float(v)); });
    // Blocked, so the field's two decimals do not round the radius the keys set.
    connect(this, &BrushTool::radiusChanged, spin, [spin](float r) {
        const QSignalBlocker block(spin);
        spin->setValue(double(r));
    });
    row->addWidget(new QLabel(tr("Radius"), box));
    row->addWidget(spin);
}

}  // namespace throng::editor
