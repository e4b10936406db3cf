#pragma once
// Which spawn group or agent group, goal, path and brain each agent of a scene was given:
// a placed agent by its own keys (its brain, or its type's), a spawn group's member by
// its group's (the type's brain), vehicles and heroes by none. For colouring agents by
// them and for the legend that names them. Plain scene data; no GL, no Qt.

#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"

#include <array>
#include <cstddef>
#include <string>
#include <unordered_map>
#include <vector>

namespace throng::editor {

class AgentCategories {
public:
    enum class Key { Group, Goal, Path, Brain };
    static constexpr std::size_t kKeys = 4;

    void setScene(const sim::Scene& scene);
    // Agent `id`'s category under `key`: an index into names(key), or -1 (none).
    int of(Key key, sim::AgentId id) const;
    // The categories agents were given, in the scene's order of first use.
    const std::vector<std::string>& names(Key key) const { return m_names[std::size_t(key)]; }

private:
    using Indices = std::array<int, kKeys>;
    int indexOf(Key key, const std::string& name);

    std::unordered_map<sim::AgentId, Indices> m_placed;
    struct Members {
        sim::AgentId first = 0, end = 0;  // ids [first, end)
        Indices categories{};
    };
    std::vector<Members> m_groups;  // in id order
    std::array<std::vector<std::string>, kKeys> m_names;
};

}  // namespace throng::editor
