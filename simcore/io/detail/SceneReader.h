#pragma once
// Turns a parsed YAML document into a Scene, section by section, checking types,
// ranges and references. Reports through YamlFields; never throws.
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include "simcore/io/detail/YamlFields.h"
#include "simcore/scene/Scene.h"

#include <map>
#include <set>
#include <string>
#include <string_view>

namespace throng::sim::detail {

class SceneReader {
public:
    // `source` is the document's text, used to locate rows inside agent tables.
    SceneReader(YamlFields& fields, std::string baseDir, std::string_view source)
        : m_f(fields), m_baseDir(std::move(baseDir)), m_source(source) {}

    // Reads the whole document into scene.
    void read(const YAML::Node& root, Scene& scene);

private:
    void readSettings(const YAML::Node& node, Settings& s);
    void readBrains(const YAML::Node& node, Scene& scene);
    void readAgentTypes(const YAML::Node& node, Scene& scene);
    void readVariation(const YAML::Node& node, const std::string& key, Variation& v);
    void readCollision(const YAML::Node& item, const std::string& key, AgentType& t);
    void readAgents(const YAML::Node& node, Scene& scene);
    void readAgentTable(const YAML::Node& node, const std::string& key, Scene& scene);
    // The hand-set variation of one agent (look, tint, height), checked against its type.
    void readAgentVariation(const YAML::Node& item, const std::string& key, const Scene& scene, Agent& a);
    void readGroups(const YAML::Node& node, Scene& scene);
    // A group's or source's `exits`: at least two exit goals, none twice, and no other route
    // (`routed`: the item gives one too, named `route` in the message).
    void readExits(const YAML::Node& item, const std::string& key, std::vector<std::string>& names, bool routed,
                   const char* route, const Scene& scene);
    // The spawn area of group `item`: exactly one of rect, circle and shape: polygon.
    // `{min: [x, z], max: [x, z]}` at `key` (a map already), min not above max.
    void readRect(const YAML::Node& rect, const std::string& key, glm::vec2& min, glm::vec2& max);
    void readGroupArea(const YAML::Node& item, const std::string& key, SpawnGroup& g);
    void readGroupPolygon(const YAML::Node& item, const std::string& key, SpawnGroup& g);
    void readKeepingTogether(const YAML::Node& item, const std::string& key, const Scene& scene, SpawnGroup& g);
    void readPaths(const YAML::Node& node, Scene& scene);
    void readWalls(const YAML::Node& node, Scene& scene);
    void readObstacles(const YAML::Node& node, Scene& scene);
    void readGoals(const YAML::Node& node, Scene& scene);
    void readTerrain(const YAML::Node& node, Terrain& t);
    void readFlowStrokes(const YAML::Node& node, Scene& scene);
    void readTraffic(const YAML::Node& node, TrafficSettings& t);
    // `name` of map `item` into `out` when present; `inherit` allows "inherit".
    void readCarFollowing(const YAML::Node& item, const std::string& key, CarFollowing& out, bool inherit);
    void readLanes(const YAML::Node& node, Scene& scene);
    void readCrosswalks(const YAML::Node& node, Scene& scene);
    void readTrafficLights(const YAML::Node& node, Scene& scene);
    void readVehicles(const YAML::Node& node, Scene& scene);
    void readHeroes(const YAML::Node& node, Scene& scene);
    void readSoundSources(const YAML::Node& node, Scene& scene);
    void readEmission(const YAML::Node& node, const std::string& key, SoundEmission& e);
    void readActionPoints(const YAML::Node& node, Scene& scene);
    void readSources(const YAML::Node& node, Scene& scene);
    void readMeasurements(const YAML::Node& node, Scene& scene);
    void readSourceTypes(const YAML::Node& item, const std::string& key, Source& s);
    void readSourcePlace(const YAML::Node& item, const std::string& key, Source& s);
    void readSourceWindows(const YAML::Node& item, const std::string& key, Source& s);
    void readHeroKeyframesFile(const YAML::Node& at, const std::string& key, float fps, Hero& hero);

    // Reference checks: report "no X named 'y'" at the value's location.
    bool checkRef(const YAML::Node& map, const char* name, const std::string& key, const std::string& value,
                  bool exists, const char* what);
    // Records a name of a kind ("goal", "path", ...); reports a duplicate.
    bool claimName(const YAML::Node& map, const std::string& key, const std::string& name, const char* what);
    // Whether a name of that kind was read (O(log n), for million-agent files).
    bool known(const char* what, const std::string& name) const;
    bool claimId(const YAML::Node& at, const std::string& key, std::uint32_t id);
    // A behaviour's value: a weight, or a map of weight and parameters.
    bool readBehaviour(const YAML::Node& node, const std::string& key, BehaviourWeight& out);
    void assignMissingIds(Scene& scene);

    YamlFields& m_f;
    std::string m_baseDir;
    std::string_view m_source;
    std::set<std::uint32_t> m_ids;
    std::map<std::string, std::set<std::string>> m_names;  // kind -> names read
    struct LeaderRef {
        YAML::Mark at;
        std::string key;
        std::uint32_t id;
    };
    std::vector<LeaderRef> m_leaderRefs;
};

// Reads a brain graph map: the inline form in a scene, or (isFile) a .brain.yaml file's
// root, which must start with `throng_brain: 1`.
void readBrainGraph(YamlFields& f, const YAML::Node& node, const std::string& key, BrainGraph& brain, bool isFile);
// Resolves a path relative to a base directory (absolute paths pass through).
std::string resolvePath(const std::string& baseDir, const std::string& path);

}  // namespace throng::sim::detail
