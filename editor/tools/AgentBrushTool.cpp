#include "editor/tools/AgentBrushTool.h"

#include "editor/SceneDocument.h"
#include "editor/commands/ChangeAgentsCommand.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace throng::editor {

namespace {
// A new dab every fifth of the radius: a comb follows the stroke's bends closely.
constexpr float kAgentDabSpacingRadii = 0.2f;
constexpr float kAgentBrushRadiusM = 3.0f;
int g_nextAgentStrokeId = 1;
}  // namespace

AgentBrushTool::AgentBrushTool(SceneDocument& document, Viewport& viewport, QObject* parent)
    : BrushTool(document, viewport, kAgentBrushRadiusM, parent)
{
}

void AgentBrushTool::strokeBegan(glm::vec2 point)
{
    m_strokeId = g_nextAgentStrokeId++;
    m_lastDab = m_lastPoint = point;
    m_dabs = {m_lastDab};
    dab(m_lastDab, glm::vec2(0.0f));
}

void AgentBrushTool::strokeMoved(glm::vec2 point)
{
    m_lastPoint = point;
    const float step = std::max(0.05f, radiusM() * kAgentDabSpacingRadii);
    while (glm::length(point - m_lastDab) >= step)
        dabAt(m_lastDab + glm::normalize(point - m_lastDab) * step);
}

// The stroke reaches where the mouse let go, not only its last whole step before it.
void AgentBrushTool::strokeEnded()
{
    if (glm::length(m_lastPoint - m_lastDab) > 0.01f)
        dabAt(m_lastPoint);
}

void AgentBrushTool::dabAt(glm::vec2 point)
{
    m_lastDab = point;
    // Measured over a radius of stroke, so the mouse's pixel steps do not wobble it.
    std::size_t back = m_dabs.size() - 1;
    while (back > 0 && glm::length(m_lastDab - m_dabs[back]) < radiusM())
        --back;
    m_dabs.push_back(m_lastDab);
    dab(m_lastDab, glm::normalize(m_lastDab - m_dabs[back]));
}

void AgentBrushTool::dab(glm::vec2 centre, glm::vec2 direction)
{
    std::vector<std::size_t> indices;
    std::vector<sim::Agent> edited;
    const std::vector<sim::Agent>& agents = document().scene().agents;
    for (std::size_t i = 0; i < agents.size(); ++i) {
        if (glm::length(glm::vec2(agents[i].position.x, agents[i].position.z) - centre) > radiusM())
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

}  // namespace throng::editor
