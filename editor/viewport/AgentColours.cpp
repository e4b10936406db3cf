#include "editor/viewport/AgentColours.h"

#include "editor/viewport/ViewportPalette.h"
#include "export/character/AgentVariation.h"

#include <algorithm>

namespace throng::editor {

void AgentColours::setScene(const sim::Scene& scene)
{
    m_variations.clear();
    for (const sim::AgentType& t : scene.agentTypes)
        m_variations.push_back(t.variation);
    m_handTint.clear();
    for (const sim::Agent& a : scene.agents)
        if (a.tint >= 0)
            m_handTint[a.id] = a.tint;
    m_seed = scene.settings.seed;
    m_cachedFor.clear();
    m_colours.clear();
}

const std::vector<glm::vec3>& AgentColours::coloursFor(std::span<const sim::AgentInfo> agents)
{
    const bool same = agents.size() == m_cachedFor.size() &&
                      std::equal(agents.begin(), agents.end(), m_cachedFor.begin(), [](const auto& a, const auto& b) {
                          return a.id == b.id && a.typeIndex == b.typeIndex;
                      });
    if (same)
        return m_colours;
    m_cachedFor.assign(agents.begin(), agents.end());
    m_colours.resize(agents.size());
    for (std::size_t i = 0; i < agents.size(); ++i) {
        const std::size_t type = agents[i].typeIndex;
        const std::vector<glm::vec3>* tints = type < m_variations.size() ? &m_variations[type].tints : nullptr;
        if (!tints || tints->empty()) {
            m_colours[i] = glm::vec3(palette::agentColour(type));
            continue;
        }
        const auto hand = m_handTint.find(agents[i].id);
        int tint = hand != m_handTint.end() ? hand->second
                                             : exporting::drawVariation(m_variations[type], m_seed, agents[i].id, 1).tint;
        tint = std::clamp(tint, 0, int(tints->size()) - 1);
        m_colours[i] = (*tints)[std::size_t(tint)];
    }
    return m_colours;
}

}  // namespace throng::editor
