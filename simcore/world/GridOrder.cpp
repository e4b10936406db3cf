#include "simcore/world/GridOrder.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

namespace throng::sim {

bool orderPlacedForGrid(Scene& scene, std::size_t from)
{
    const std::size_t n = scene.agents.size();
    const bool fliers = std::any_of(scene.agentTypes.begin(), scene.agentTypes.end(),
                                    [](const AgentType& t) { return t.kind == AgentKind::Flier; });
    if (!fliers || n < from || n < 2)
        return false;
    // The cells of a World with fliers: as large as the widest perception, 0.5 to 4 m
    // (World.cpp). Only the order of the cells matters here, not their exact edges.
    float cell = 0.0f;
    for (const AgentType& t : scene.agentTypes)
        cell = std::max(cell, t.perceptionM);
    cell = std::clamp(std::isfinite(cell) ? cell : 4.0f, 0.5f, 4.0f);
    const glm::vec2 min = scene.settings.boundsMin;
    auto cellOf = [&](float v, float lo) {
        const float c = std::floor((v - lo) / cell);
        return std::isfinite(c) ? std::int64_t(std::clamp(c, 0.0f, 1e9f)) : std::int64_t(0);
    };
    struct Key {
        std::int64_t row, col;
        float y;
        std::uint32_t index;
    };
    std::vector<Key> keys(n);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec3 p = scene.agents[i].position;
        keys[i] = {cellOf(p.z, min.y), cellOf(p.x, min.x), std::isfinite(p.y) ? p.y : 0.0f, std::uint32_t(i)};
    }
    std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) {
        return std::tie(a.row, a.col, a.y, a.index) < std::tie(b.row, b.col, b.y, b.index);
    });
    // Agent keys[k].index goes to place k: follow each cycle of the permutation, moving
    // every agent once (no second copy of a million agents).
    std::vector<std::uint32_t> source(n);
    for (std::size_t k = 0; k < n; ++k)
        source[k] = keys[k].index;
    keys = {};
    std::vector<bool> placed(n, false);
    for (std::size_t start = 0; start < n; ++start) {
        if (placed[start])
            continue;
        Agent held = std::move(scene.agents[start]);
        std::size_t k = start;
        while (source[k] != start) {
            scene.agents[k] = std::move(scene.agents[source[k]]);
            placed[k] = true;
            k = source[k];
        }
        scene.agents[k] = std::move(held);
        placed[k] = true;
    }
    return true;
}

}  // namespace throng::sim
