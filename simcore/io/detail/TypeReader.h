#pragma once
// Reads `agent_types`: each type's kind, body, speeds, steering behaviours and their
// parameters, variation (looks, tints, heights), character, brain, sound it emits, car
// following, and how it makes way (priority and collision layers).
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include "simcore/io/detail/SceneNames.h"
#include "simcore/io/detail/YamlFields.h"
#include "simcore/scene/Scene.h"

#include <string>

namespace throng::sim::detail {

class TypeReader {
public:
    // Character files named relative to the scene are looked for in baseDir.
    TypeReader(YamlFields& fields, SceneNames& names, const std::string& baseDir)
        : m_f(fields), m_names(names), m_baseDir(baseDir) {}
    void read(const YAML::Node& node, Scene& scene);

private:
    void readVariation(const YAML::Node& node, const std::string& key, Variation& v);
    void readCollision(const YAML::Node& item, const std::string& key, AgentType& t);
    // A behaviour's value: a weight, or a map of weight and parameters.
    bool readBehaviour(const YAML::Node& node, const std::string& key, BehaviourWeight& out);

    YamlFields& m_f;
    SceneNames& m_names;
    const std::string& m_baseDir;
};

}  // namespace throng::sim::detail
