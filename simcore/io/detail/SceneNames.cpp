#include "simcore/io/detail/SceneNames.h"

namespace throng::sim::detail {

bool SceneNames::checkRef(const YAML::Node& map, const char* field, const std::string& key, const std::string& value,
                          bool exists, const char* what)
{
    if (exists)
        return true;
    m_f.error(map[field].Mark(), childKey(key, field), std::string("no ") + what + " named '" + value + "'");
    return false;
}

bool SceneNames::claim(const YAML::Node& map, const std::string& key, const std::string& name, const char* what)
{
    if (m_names[what].insert(name).second)
        return true;
    m_f.error(map["name"].Mark(), key + ".name", std::string("another ") + what + " is already named '" + name + "'");
    return false;
}

bool SceneNames::known(const char* what, const std::string& name) const
{
    const auto it = m_names.find(what);
    return it != m_names.end() && it->second.count(name) > 0;
}

bool SceneNames::claimId(const YAML::Node& at, const std::string& key, std::uint32_t id)
{
    if (id == 0) {
        m_f.error(at.Mark(), key, "ids start at 1");
        return false;
    }
    if (m_ids.insert(id).second)
        return true;
    m_f.error(at.Mark(), key, "id " + std::to_string(id) + " is already used by another agent, vehicle or hero");
    return false;
}

void SceneNames::assignMissingIds(Scene& scene)
{
    std::uint32_t next = m_ids.empty() ? 1 : *m_ids.rbegin() + 1;
    for (Agent& a : scene.agents)
        if (a.id == 0) a.id = next++;
    for (Vehicle& v : scene.vehicles)
        if (v.id == 0) v.id = next++;
    for (Hero& h : scene.heroes)
        if (h.id == 0) h.id = next++;
}

void SceneNames::checkLeaders(const Scene& scene)
{
    // Any placed agent, vehicle or hero may lead.
    std::set<std::uint32_t> all;
    for (const Agent& a : scene.agents) all.insert(a.id);
    for (const Vehicle& v : scene.vehicles) all.insert(v.id);
    for (const Hero& h : scene.heroes) all.insert(h.id);
    for (const LeaderRef& r : m_leaders)
        if (!all.count(r.id))
            m_f.error(r.at, r.key, "no agent, vehicle or hero with id " + std::to_string(r.id) + " to lead");
}

}  // namespace throng::sim::detail
