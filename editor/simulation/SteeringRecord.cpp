#include "editor/simulation/SteeringRecord.h"

#include <algorithm>
#include <utility>

namespace throng::editor {

void SteeringRecord::clear()
{
    m_frames.clear();
    m_asked.clear();
}

void SteeringRecord::dropFrom(std::size_t frame)
{
    m_frames.erase(m_frames.lower_bound(frame), m_frames.end());
    m_asked.erase(m_asked.lower_bound(frame), m_asked.end());
}

void SteeringRecord::take(std::vector<SimulationRunner::FrameSteering>&& steering)
{
    for (SimulationRunner::FrameSteering& s : steering)
        m_frames[s.frame] = std::move(s.agents);
}

std::vector<sim::AgentDebug> SteeringRecord::watchedAt(std::size_t frame) const
{
    std::vector<sim::AgentDebug> out;
    const auto it = m_frames.find(frame);
    if (it == m_frames.end())
        return out;
    for (const sim::AgentDebug& a : it->second)
        if (watched(a.id))
            out.push_back(a);
    return out;
}

void SteeringRecord::setWatched(std::vector<sim::AgentId> ids)
{
    if (ids == m_watched)
        return;
    m_watched = std::move(ids);
    m_asked.clear();
}

bool SteeringRecord::covers(std::size_t frame) const
{
    const auto it = m_frames.find(frame);
    if (it == m_frames.end())
        return false;
    // Described for exactly the watched agents (those the frame's World held).
    for (const sim::AgentDebug& a : it->second)
        if (!watched(a.id))
            return false;
    return it->second.size() == m_watched.size();
}

bool SteeringRecord::watched(sim::AgentId id) const
{
    return std::find(m_watched.begin(), m_watched.end(), id) != m_watched.end();
}

bool SteeringRecord::wantsDescribing(std::size_t frame)
{
    if (m_watched.empty() || covers(frame) || m_asked.count(frame))
        return false;
    m_asked.insert(frame);
    return true;
}

}  // namespace throng::editor
