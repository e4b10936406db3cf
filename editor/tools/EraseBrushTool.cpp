#include "editor/tools/EraseBrushTool.h"

#include "editor/SceneDocument.h"
#include "editor/commands/EraseAgentsCommand.h"
#include "editor/tools/BrushOverlay.h"

#include <glm/geometric.hpp>

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>

namespace throng::editor {

namespace {
int g_nextEraseStrokeId = 1;
}

void EraseBrushTool::mousePressed(const ToolMouse& mouse)
{
    m_cursor = mouse.ground;
    if (!mouse.ground)
        return;
    setState(State::Dragging);
    m_strokeId = g_nextEraseStrokeId++;
    dab({mouse.ground->x, mouse.ground->z});
    emit overlayChanged();
}

void EraseBrushTool::mouseMoved(const ToolMouse& mouse)
{
    m_cursor = mouse.ground;
    if (state() == State::Dragging && mouse.ground)
        dab({mouse.ground->x, mouse.ground->z});
    else if (state() != State::Dragging)
        setState(mouse.ground ? State::Hover : State::Idle);
    emit overlayChanged();
}

void EraseBrushTool::mouseReleased(const ToolMouse& mouse)
{
    mouseMoved(mouse);
    setState(State::Hover);
}

void EraseBrushTool::cancel()
{
    setState(State::Idle);
    m_cursor.reset();
    emit overlayChanged();
}

void EraseBrushTool::dab(glm::vec2 centre)
{
    std::vector<std::size_t> hit;
    const auto& agents = document().scene().agents;
    for (std::size_t i = 0; i < agents.size(); ++i)
        if (glm::length(glm::vec2(agents[i].position.x, agents[i].position.z) - centre) <= m_radiusM)
            hit.push_back(i);
    if (!hit.empty())
        document().undoStack()->push(new EraseAgentsCommand(document(), std::move(hit), m_strokeId));
}

void EraseBrushTool::drawOverlay(QPainter& painter) const
{
    if (m_cursor)
        drawBrushCircle(painter, viewport(), *m_cursor, m_radiusM, QColor(255, 110, 90));
}

QWidget* EraseBrushTool::createOptionsWidget(QWidget* parent)
{
    auto* box = new QWidget(parent);
    auto* row = new QHBoxLayout(box);
    row->setContentsMargins(4, 0, 4, 0);
    auto* spin = new QDoubleSpinBox(box);
    spin->setObjectName("eraseRadius");
    spin->setRange(0.1, 100.0);
    spin->setValue(double(m_radiusM));
    spin->setToolTip(tr("Brush radius in metres"));
    connect(spin, &QDoubleSpinBox::valueChanged, this, [this](double v) { m_radiusM = float(v); });
    row->addWidget(new QLabel(tr("Radius"), box));
    row->addWidget(spin);
    return box;
}

}  // namespace throng::editor
