// Each agent's start in a World: when a source lets it in (its arrival, off stage until
// then), when it sets off (its reaction time, StartPhase.h), which exit it takes
// (ExitChoice.h) and its age (WalkingAge.h).
#include "simcore/world/World.h"

#include "simcore/base/Rng.h"
#include "simcore/scene/WalkingAge.h"
#include "simcore/world/detail/AgentStreams.h"
#include "simcore/world/detail/NameIndex.h"
#include "simcore/world/detail/StepGeometry.h"

#include <glm/vec3.hpp>

namespace throng::sim {

using enum detail::AgentStream;
using detail::NameIndex;

// The sources' arrivals (Sources.h): agents after the groups', off stage until due.
void World::addSourceAgents(const Scene& scene, AgentId& nextId, std::vector<std::int32_t>& choosesFrom,
                            std::vector<std::vector<std::int32_t>>& exitSets)
{
    const NameIndex goals(scene.goals), paths(scene.paths);
    std::vector<std::uint32_t> agents, sources;
    std::vector<double> times;
    std::vector<std::uint8_t> brainPicks;  // per type: its brain picks goals, not an exit choice
    for (const AgentType& t : scene.agentTypes)
        brainPicks.push_back(scene.brainPicksGoals(t.name) ? 1 : 0);
    for (std::size_t s = 0; s < scene.sources.size(); ++s) {
        const Source& source = scene.sources[s];
        const std::int32_t set = source.exits.empty() ? -1 : std::int32_t(exitSets.size());
        if (set >= 0) {
            exitSets.emplace_back();
            for (const std::string& e : source.exits)
                exitSets.back().push_back(goals(e));
        }
        for (const SourceArrival& a : sourceArrivals(scene, s, m_seed)) {
            agents.push_back(std::uint32_t(m_agents.info.size()));
            times.push_back(a.timeS);
            sources.push_back(a.source);
            addAgent(scene, nextId++, a.type, glm::vec3(a.place.x, 0.0f, a.place.y), a.headingRad,
                     source.exits.empty() ? goals(source.goal) : goals(source.exits[0]), paths(source.path), 0);
            choosesFrom.push_back(brainPicks[a.type] ? -1 : set);
        }
    }
    m_sources.build(std::move(agents), std::move(times), std::move(sources));
}

void World::takeExits(const std::vector<ExitChoice::Switch>& choices)
{
    for (const ExitChoice::Switch& c : choices) {
        const Goal& g = m_set.goals[std::size_t(c.goal)];
        const AgentId id = m_agents.info[c.agent].id;
        m_agents.goal[c.agent] = c.goal;
        const float u = rngUniform(m_seed, id, 0, kSpotR), v = rngUniform(m_seed, id, 0, kSpotA);
        m_agents.goalSpot[c.agent] = detail::goalSpot(g.position, g.radiusM, g.exit, m_agents.radius[c.agent], u, v);
    }
}

float World::ageYears(std::size_t i) const
{
    return agentAgeYears(m_types.ageYears[m_agents.info[i].typeIndex], m_seed, m_agents.info[i].id);
}

void World::scheduleReactions(const Scene& scene, bool hold)
{
    std::vector<std::uint32_t> agents;
    std::vector<double> times;
    for (std::size_t i = 0; i < m_agents.size(); ++i) {
        const AgentType& t = scene.agentTypes[m_agents.info[i].typeIndex];
        // Walkers only; a driven vehicle or hero and a source's agent are already stopped.
        if (t.kind != AgentKind::Pedestrian || (hold && m_agents.stopped[i]) || t.variation.reactionS.y <= 0.0f)
            continue;
        const float r = rngRange(m_seed, m_agents.info[i].id, 0, kReaction, t.variation.reactionS.x,
                                 t.variation.reactionS.y);
        if (r <= 0.0f)
            continue;
        agents.push_back(std::uint32_t(i));
        times.push_back(double(r));
    }
    // Adopting a checkpoint: one that still waits but whose type no longer sets a reaction
    // time goes now.
    for (std::size_t i = 0, k = 0; !hold && i < m_agents.size(); ++i) {
        const bool scheduled = k < agents.size() && agents[k] == i;
        k += scheduled ? 1 : 0;
        if (!scheduled && m_agents.unstarted[i])
            m_agents.unstarted[i] = m_agents.stopped[i] = m_agents.stoppedBefore[i] = 0;
    }
    m_starts.build(std::move(agents), std::move(times));
    if (hold)
        m_starts.holdAll(m_agents);
}

}  // namespace throng::sim
