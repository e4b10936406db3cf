#include "editor/simulation/SteeringWatch.h"

#include "simcore/world/World.h"

#include <algorithm>
#include <unordered_map>
#include <utility>

namespace throng::editor {

void SteeringWatch::set(std::vector<sim::AgentId> ids)
{
    if (ids.size() > kMaxWatched)
        ids.resize(kMaxWatched);
    std::lock_guard lock(m_mutex);
    if (ids == m_ids)
        return;
    m_ids = std::move(ids);
    ++m_generation;
}

std::vector<sim::AgentId> SteeringWatch::ids() const
{
    std::lock_guard lock(m_mutex);
    return m_ids;
}

bool SteeringWatch::empty() const
{
    std::lock_guard lock(m_mutex);
    return m_ids.empty();
}

std::vector<std::size_t> SteeringWatch::indicesOf(const sim::World& world, const std::vector<sim::AgentId>& ids)
{
    std::unordered_map<sim::AgentId, std::size_t> wanted;
    for (std::size_t k = 0; k < ids.size(); ++k)
        wanted.emplace(ids[k], k);
    std::vector<std::size_t> found(ids.size(), world.agentCount());
    std::size_t left = wanted.size();
    for (std::size_t i = 0; i < world.agentCount() && left > 0; ++i)
        if (const auto it = wanted.find(world.id(i)); it != wanted.end()) {
            found[it->second] = i;
            --left;
        }
    found.erase(std::remove(found.begin(), found.end(), world.agentCount()), found.end());
    return found;
}

std::vector<sim::AgentDebug> SteeringWatch::describe(const sim::World& world, const std::vector<sim::AgentId>& ids)
{
    sim::DebugRecorder recorder;
    for (const std::size_t i : indicesOf(world, ids))
        world.describeAgent(i, recorder);
    return std::move(recorder.agents());
}

std::vector<sim::AgentDebug> SteeringWatch::describe(const sim::World& world)
{
    std::vector<sim::AgentId> ids;
    std::uint64_t generation = 0;
    {
        std::lock_guard lock(m_mutex);
        if (m_ids.empty())
            return {};
        generation = m_generation;
        if (generation != m_resolvedGeneration || &world != m_world || world.agentCount() != m_worldAgents)
            ids = m_ids;
    }
    if (!ids.empty()) {
        m_indices = indicesOf(world, ids);
        m_world = &world;
        m_worldAgents = world.agentCount();
        m_resolvedGeneration = generation;
    }
    sim::DebugRecorder recorder;
    for (const std::size_t i : m_indices)
        world.describeAgent(i, recorder);
    return std::move(recorder.agents());
}

}  // namespace throng::editor
