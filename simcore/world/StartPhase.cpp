#include "simcore/world/StartPhase.h"

#include <algorithm>
#include <numeric>

namespace throng::sim {

void StartPhase::build(std::vector<std::uint32_t> agents, std::vector<double> startS)
{
    std::vector<std::size_t> order(agents.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return startS[a] != startS[b] ? startS[a] < startS[b] : agents[a] < agents[b];
    });
    m_agent.clear();
    m_startS.clear();
    for (std::size_t k : order) {
        m_agent.push_back(agents[k]);
        m_startS.push_back(startS[k]);
    }
    m_done = 0;
}

void StartPhase::holdAll(AgentColumns& agents) const
{
    for (std::uint32_t i : m_agent)
        agents.unstarted[i] = agents.stopped[i] = agents.stoppedBefore[i] = 1;
}

std::size_t StartPhase::release(double timeS, AgentColumns& agents)
{
    // Small slack: a time that is a whole number of steps is let go on that step.
    const double now = timeS + 1e-9;
    std::size_t released = 0;
    for (; m_done < m_agent.size() && m_startS[m_done] <= now; ++m_done) {
        const std::uint32_t i = m_agent[m_done];
        if (!agents.unstarted[i])
            continue;  // let go before a checkpoint was put back
        agents.unstarted[i] = 0;
        agents.stopped[i] = agents.stoppedBefore[i] = 0;
        ++released;
    }
    return released;
}

double StartPhase::startS(std::size_t i) const
{
    for (std::size_t k = 0; k < m_agent.size(); ++k)
        if (m_agent[k] == i)
            return m_startS[k];
    return 0.0;
}

}  // namespace throng::sim
