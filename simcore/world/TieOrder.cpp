#include "simcore/world/TieOrder.h"

#include <algorithm>
#include <numeric>

namespace throng::sim {

void TieOrder::build(std::span<const AgentInfo> agents)
{
    m_rank.clear();
    m_index.clear();
    const bool rising = std::adjacent_find(agents.begin(), agents.end(), [](const AgentInfo& a, const AgentInfo& b) {
                            return !(a.id < b.id);
                        }) == agents.end();
    if (rising)
        return;
    m_index.resize(agents.size());
    std::iota(m_index.begin(), m_index.end(), std::uint32_t(0));
    std::sort(m_index.begin(), m_index.end(),
              [&](std::uint32_t a, std::uint32_t b) { return agents[a].id < agents[b].id; });
    m_rank.resize(agents.size());
    for (std::size_t r = 0; r < m_index.size(); ++r)
        m_rank[m_index[r]] = std::uint32_t(r);
}

}  // namespace throng::sim
