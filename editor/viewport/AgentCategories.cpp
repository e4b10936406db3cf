#include "editor/viewport/AgentCategories.h"

#include <algorithm>

namespace throng::editor {

int AgentCategories::indexOf(Key key, const std::string& name)
{
    if (name.empty())
        return -1;
    std::vector<std::string>& names = m_names[std::size_t(key)];
    const auto it = std::find(names.begin(), names.end(), name);
    if (it != names.end())
        return int(it - names.begin());
    names.push_back(name);
    return int(names.size()) - 1;
}

void AgentCategories::setScene(const sim::Scene& scene)
{
    m_placed.clear();
    m_groups.clear();
    for (auto& names : m_names)
        names.clear();
    const auto typeBrain = [&](const std::string& type) {
        const sim::AgentType* t = scene.findAgentType(type);
        return t ? t->brain : std::string();
    };
    for (const sim::Agent& a : scene.agents)
        m_placed[a.id] = {indexOf(Key::Group, a.group), indexOf(Key::Goal, a.goal), indexOf(Key::Path, a.path),
                          indexOf(Key::Brain, a.brain.empty() ? typeBrain(a.type) : a.brain)};
    // Members take consecutive ids, group after group (sim::firstSpawnedId).
    sim::AgentId first = sim::firstSpawnedId(scene);
    for (const sim::SpawnGroup& g : scene.groups) {
        m_groups.push_back({first, first + g.count,
                            {indexOf(Key::Group, g.name), indexOf(Key::Goal, g.goal), indexOf(Key::Path, g.path),
                             indexOf(Key::Brain, typeBrain(g.type))}});
        first += g.count;
    }
}

int AgentCategories::of(Key key, sim::AgentId id) const
{
    if (const auto placed = m_placed.find(id); placed != m_placed.end())
        return placed->second[std::size_t(key)];
    const auto after = std::upper_bound(m_groups.begin(), m_groups.end(), id,
                                        [](sim::AgentId v, const Members& m) { return v < m.first; });
    if (after == m_groups.begin())
        return -1;
    const Members& m = *(after - 1);
    return id < m.end ? m.categories[std::size_t(key)] : -1;
}

}  // namespace throng::editor
