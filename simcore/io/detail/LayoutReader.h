#pragma once
// Reads the scene's layout layer (`layout`): edits to the recorded crowd, applied after
// the simulation (LayoutLayer.h). Checks each operation's kind, agents, frames and
// parameters; reports through YamlFields; never throws.
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include "simcore/io/detail/YamlFields.h"
#include "simcore/scene/Scene.h"

#include <set>
#include <string>

namespace throng::sim::detail {

class LayoutReader {
public:
    explicit LayoutReader(YamlFields& fields) : m_f(fields) {}
    // Appends the operations of `node` to scene.layout; its agent types are already read.
    void read(const YAML::Node& node, Scene& scene);

private:
    void readAgents(const YAML::Node& item, const std::string& key, const Scene& scene, AgentSelector& s);
    // A swap's look, tint and type, checked against the type it shows when it names one.
    void readSwap(const YAML::Node& item, const std::string& key, const Scene& scene, LayoutOp& op);
    YamlFields& m_f;
    std::set<std::string> m_names;
};

}  // namespace throng::sim::detail
