#pragma once
// The colour each shown agent is drawn in: its tint from the type's palette (set by hand
// with the variation brush, else drawn per agent id as export draws it), or the type's
// colour when the type has no tints. Cached while the same agents are shown. No GL.

#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

namespace throng::editor {

class AgentColours {
public:
    void setScene(const sim::Scene& scene);
    // One colour per agent of `agents`, in order.
    const std::vector<glm::vec3>& coloursFor(std::span<const sim::AgentInfo> agents);

private:
    std::vector<sim::Variation> m_variations;         // by type index
    std::unordered_map<std::uint32_t, int> m_handTint; // agent id -> tint index
    std::uint64_t m_seed = 1;
    std::vector<sim::AgentInfo> m_cachedFor;
    std::vector<glm::vec3> m_colours;
};

}  // namespace throng::editor
