#include "editor/brain/LiveBrainValues.h"

#include "simcore/world/World.h"

#include <exception>

namespace throng::editor {

LiveBrainValues::LiveBrainValues() = default;
LiveBrainValues::~LiveBrainValues() = default;

void LiveBrainValues::setScene(const sim::Scene& scene)
{
    m_scene = &scene;
    m_world.reset();
    m_values.clear();
}

void LiveBrainValues::pick(std::ptrdiff_t agent)
{
    if (agent == m_agent)
        return;
    m_agent = agent;
    m_world.reset();
    m_values.clear();
    m_type = -1;
}

void LiveBrainValues::restart()
{
    m_world.reset();
    m_values.clear();
    m_step = 0;
    m_type = -1;
    if (m_agent < 0 || !m_scene)
        return;
    try {
        m_world = std::make_unique<sim::World>(*m_scene);
    } catch (const std::exception&) {
        return;  // The playback reports why the scene cannot run.
    }
    if (std::size_t(m_agent) >= m_world->agentCount()) {
        m_world.reset();
        return;
    }
    m_type = int(m_world->agentInfo()[std::size_t(m_agent)].typeIndex);
    m_world->pickBrainAgent(m_agent);
}

const std::vector<sim::BrainNodeValue>& LiveBrainValues::valuesAt(std::size_t frame)
{
    if (m_agent < 0) {
        m_values.clear();
        return m_values;
    }
    if (!m_world || frame < m_step)
        restart();
    if (!m_world)
        return m_values;
    while (m_step < frame) {
        m_world->step();
        ++m_step;
    }
    m_values.clear();
    if (frame > 0)
        if (const sim::BrainEvaluator* e = m_world->brainEvaluator(std::size_t(m_type)))
            m_values = e->pickedValues();
    return m_values;
}

}  // namespace throng::editor
