#pragma once
// What a scene's sections name and number as they are read: the names of each kind (goal,
// path, agent type, ...), the ids of placed agents, vehicles and heroes, and the leaders
// they name. Reports, at the value's place in the file, a name or id used twice, a
// reference to a name not read, and (once all is read) a leader no one has; gives the
// agents read without an id the next free ones.
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include "simcore/io/detail/YamlFields.h"
#include "simcore/scene/Scene.h"

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace throng::sim::detail {

class SceneNames {
public:
    explicit SceneNames(YamlFields& fields) : m_f(fields) {}

    // Records `name` of a kind ("goal", "path", ...) read at map's `name`; reports a duplicate.
    bool claim(const YAML::Node& map, const std::string& key, const std::string& name, const char* what);
    // Whether a name of that kind was read (O(log n), for million-agent files).
    bool known(const char* what, const std::string& name) const;
    // Reports "no <what> named '<value>'" at map's `field` unless `exists`.
    bool checkRef(const YAML::Node& map, const char* field, const std::string& key, const std::string& value,
                  bool exists, const char* what);
    // checkRef for a reference to a name of kind `what` read before.
    bool checkKnown(const YAML::Node& map, const char* field, const std::string& key, const std::string& value,
                    const char* what)
    {
        return checkRef(map, field, key, value, known(what, value), what);
    }
    // Records the id of an agent, vehicle or hero read at `at`; reports 0 or a duplicate.
    bool claimId(const YAML::Node& at, const std::string& key, std::uint32_t id);
    // Records id (>= 1) unless it is taken: for the agent table, which reports its own errors.
    bool takeId(std::uint32_t id) { return m_ids.insert(id).second; }
    // The value at `at` names `id` as its leader, checked by checkLeaders.
    void leads(const YAML::Mark& at, const std::string& key, std::uint32_t id) { m_leaders.push_back({at, key, id}); }

    // Once every section is read: the agents, vehicles and heroes without an id get the
    // next free ones, in that order; then every leader named must be one of them.
    void assignMissingIds(Scene& scene);
    void checkLeaders(const Scene& scene);

private:
    YamlFields& m_f;
    std::set<std::uint32_t> m_ids;
    std::map<std::string, std::set<std::string>> m_names;  // kind -> names read
    struct LeaderRef {
        YAML::Mark at;
        std::string key;
        std::uint32_t id;
    };
    std::vector<LeaderRef> m_leaders;
};

}  // namespace throng::sim::detail
