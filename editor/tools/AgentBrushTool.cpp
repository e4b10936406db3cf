#include "editor/tools/AgentBrushTool.h"

#include "editor/SceneDocument.h"
#include "editor/commands/ChangeAgentsCommand.h"
#include "editor/tools/BrushOverlay.h"

#include <glm/geometric.hpp>

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>

#include <algorithm>

namespace throng::editor {

namespace {
// A new dab every fifth of the radius: a comb follows the stroke's bends closely.
constexpr float kDabSpacingRadii = 0.2f;
int g_nextAgentStrokeId = 1;
}  // namespace

void AgentBrushTool::mousePressed(const ToolMouse& mouse)
{
    m_cursor = mouse.ground;
    if (!mouse.ground)
        return;
    setState(State::Dragging);
    m_strokeId = g_nextAgentStrokeId++;
    m_lastDab = {mouse.ground->x, mouse.ground->z};
    m_dabs = {m_lastDab};
    dab(m_lastDab, glm::vec2(0.0f));
    emit overlayChanged();
}

void AgentBrushTool::mouseMoved(const ToolMouse& mouse)
{
    m_cursor = mouse.ground;
    if (state() == State::Dragging && mouse.ground) {
        const glm::vec2 p(mouse.ground->x, mouse.ground->z);
        const float step = std::max(0.05f, m_radiusM * kDabSpacingRadii);
        while (glm::length(p - m_lastDab) >= step) {
            m_lastDab += glm::normalize(p - m_lastDab) * step;
            // Measured over a radius of stroke, so the mouse's pixel steps do not wobble it.
            std::size_t back = m_dabs.size() - 1;
            while (back > 0 && glm::length(m_lastDab - m_dabs[back]) < m_radiusM)
                --back;
            m_dabs.push_back(m_lastDab);
            dab(m_lastDab, glm::normalize(m_lastDab - m_dabs[back]));
        }
    } else if (state() != State::Dragging) {
        setState(mouse.ground ? State::Hover : State::Idle);
    }
    emit overlayChanged();
}

void AgentBrushTool::mouseReleased(const ToolMouse& mouse)
{
    mouseMoved(mouse);
    setState(State::Hover);
    emit overlayChanged();
}

void AgentBrushTool::cancel()
{
    setState(State::Idle);
    m_cursor.reset();
    emit overlayChanged();
}

void AgentBrushTool::dab(glm::vec2 centre, glm::vec2 direction)
{
    std::vector<std::size_t> indices;
    std::vector<sim::Agent> edited;
    const std::vector<sim::Agent>& agents = document().scene().agents;
    for (std::size_t i = 0; i < agents.size(); ++i) {
        if (glm::length(glm::vec2(agents[i].position.x, agents[i].position.z) - centre) > m_radiusM)
            continue;
        sim::Agent copy = agents[i];
        if (editAgent(copy, centre, direction, m_strokeId)) {
            indices.push_back(i);
            edited.push_back(std::move(copy));
        }
    }
    if (!indices.empty())
        document().undoStack()->push(new ChangeAgentsCommand(document(), indices, edited, m_strokeId, verb()));
}

void AgentBrushTool::drawOverlay(QPainter& painter) const
{
    if (m_cursor)
        drawBrushCircle(painter, viewport(), *m_cursor, m_radiusM, brushColour());
}

void AgentBrushTool::addRadiusOption(QWidget* box, QHBoxLayout* row)
{
    auto* spin = new QDoubleSpinBox(box);
    spin->setObjectName(objectKey() + "Radius");
    spin->setRange(0.1, 100.0);
    spin->setValue(double(m_radiusM));
    spin->setToolTip(tr("Brush radius in metres"));
    connect(spin, &QDoubleSpinBox::valueChanged, this, [this](double v) { m_radiusM = float(v); });
    row->addWidget(new QLabel(tr("Radius"), box));
    row->addWidget(spin);
}

}  // namespace throng::editor
