#pragma once
// Reads who is in the scene and where they come from: placed agents (`agents`, as a list
// of maps or as the compact table painted crowds use), spawn groups (`groups`), sources
// that bring agents in during the run (`sources`) and heroes on their keyframed ways
// (`heroes`), with their types, routes, exits and leaders checked against what was read
// before them.
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include "simcore/io/detail/SceneNames.h"
#include "simcore/io/detail/YamlFields.h"
#include "simcore/scene/Scene.h"

#include <string>
#include <string_view>
#include <vector>

namespace throng::sim::detail {

class CrowdReader {
public:
    // `source` is the document's text, used to locate rows inside agent tables; a hero's
    // keyframes file named relative to the scene is looked for in baseDir.
    CrowdReader(YamlFields& fields, SceneNames& names, const std::string& baseDir, std::string_view source)
        : m_f(fields), m_names(names), m_baseDir(baseDir), m_source(source) {}

    void readAgents(const YAML::Node& node, Scene& scene);
    void readGroups(const YAML::Node& node, Scene& scene);
    void readSources(const YAML::Node& node, Scene& scene);
    void readHeroes(const YAML::Node& node, Scene& scene);

private:
    void readAgentTable(const YAML::Node& node, const std::string& key, Scene& scene);
    // The hand-set variation of one agent (look, tint, height), checked against its type.
    void readAgentVariation(const YAML::Node& item, const std::string& key, const Scene& scene, Agent& a);
    // A group's or source's `exits`: at least two exit goals, none twice, and no other route
    // (`routed`: the item gives one too, named `route` in the message).
    void readExits(const YAML::Node& item, const std::string& key, std::vector<std::string>& names, bool routed,
                   const char* route, const Scene& scene);
    // `{min: [x, z], max: [x, z]}` at `key` (a map already), min not above max.
    void readRect(const YAML::Node& rect, const std::string& key, glm::vec2& min, glm::vec2& max);
    // The spawn area of group `item`: exactly one of rect, circle and shape: polygon.
    void readGroupArea(const YAML::Node& item, const std::string& key, SpawnGroup& g);
    void readGroupPolygon(const YAML::Node& item, const std::string& key, SpawnGroup& g);
    void readKeepingTogether(const YAML::Node& item, const std::string& key, const Scene& scene, SpawnGroup& g);
    void readSourceTypes(const YAML::Node& item, const std::string& key, Source& s);
    void readSourcePlace(const YAML::Node& item, const std::string& key, Source& s);
    void readSourceWindows(const YAML::Node& item, const std::string& key, Source& s);
    void readHeroKeyframesFile(const YAML::Node& at, const std::string& key, float fps, Hero& hero);

    YamlFields& m_f;
    SceneNames& m_names;
    const std::string& m_baseDir;
    std::string_view m_source;
};

}  // namespace throng::sim::detail
