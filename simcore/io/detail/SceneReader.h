#pragma once
// Turns a parsed YAML document into a Scene, section by section, checking types,
// ranges and references: the settings and brains itself, the other sections through the
// readers of agent types, the set, the traffic, the crowd and the layout, which share one
// SceneNames. Reports through YamlFields; never throws.
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include "simcore/io/detail/SceneNames.h"
#include "simcore/io/detail/YamlFields.h"
#include "simcore/scene/Scene.h"

#include <string>
#include <string_view>

namespace throng::sim::detail {

class SceneReader {
public:
    // `source` is the document's text, used to locate rows inside agent tables.
    SceneReader(YamlFields& fields, std::string baseDir, std::string_view source)
        : m_f(fields), m_baseDir(std::move(baseDir)), m_source(source), m_names(fields) {}

    // Reads the whole document into scene: the sections in the order their references
    // need (TypeReader, SetReader, TrafficReader, CrowdReader, LayoutReader read them),
    // then the ids not given and the leaders named.
    void read(const YAML::Node& root, Scene& scene);

private:
    void readSettings(const YAML::Node& node, Settings& s);
    void readBrains(const YAML::Node& node, Scene& scene);

    YamlFields& m_f;
    std::string m_baseDir;
    std::string_view m_source;
    SceneNames m_names;
};

// Reads a brain graph map: the inline form in a scene, or (isFile) a .brain.yaml file's
// root, which must start with `throng_brain: 1`.
void readBrainGraph(YamlFields& f, const YAML::Node& node, const std::string& key, BrainGraph& brain, bool isFile);
// Resolves a path relative to a base directory (absolute paths pass through).
std::string resolvePath(const std::string& baseDir, const std::string& path);

}  // namespace throng::sim::detail
