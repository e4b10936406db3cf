// Adopting a checkpoint into a World with another agent set (WorldState.h): agents are
// matched by key, and the checkpoint is laid out in the new World's dense order.
#include "simcore/world/WorldState.h"

#include "simcore/world/Sources.h"
#include "simcore/world/World.h"
#include "simcore/world/detail/WorldStateColumns.h"

#include <map>
#include <tuple>

namespace throng::sim {

namespace {

// (kind, number, name): 0 = placed agent by id, 1 = member `number` (in spawn order) of
// group `name`, 2 = vehicle or hero by id, 3 = a member of a group that changed (never
// matches: the group spawns again), 4 = arrival `number` of source `name`, 5 = one of a
// source that changed (never matches: its stream starts again).
using Key = std::tuple<int, std::uint32_t, std::string>;

std::vector<Key> keysOf(const std::vector<AgentInfo>& agents, const Scene& scene, const Scene& other,
                        std::uint64_t seed)
{
    std::vector<Key> keys;
    keys.reserve(agents.size());
    std::size_t i = 0;
    for (; i < scene.agents.size() && i < agents.size(); ++i)
        keys.emplace_back(0, agents[i].id, std::string());
    for (const SpawnGroup& g : scene.groups) {
        bool same = false;
        for (const SpawnGroup& h : other.groups)
            same = same || (h == g);
        for (std::uint32_t k = 0; k < g.count && i < agents.size(); ++k, ++i)
            keys.emplace_back(same ? 1 : 3, k, g.name);
    }
    const std::vector<std::uint32_t> counts = sourceCounts(scene, seed);
    for (std::size_t s = 0; s < scene.sources.size(); ++s) {
        bool same = false;
        for (const Source& h : other.sources)
            same = same || (h == scene.sources[s]);
        for (std::uint32_t k = 0; k < counts[s] && i < agents.size(); ++k, ++i)
            keys.emplace_back(same ? 4 : 5, k, scene.sources[s].name);
    }
    for (; i < agents.size(); ++i)
        keys.emplace_back(2, agents[i].id, std::string());
    return keys;
}

}  // namespace

std::vector<std::int32_t> matchAgents(const std::vector<AgentInfo>& before, const Scene& beforeScene,
                                      const std::vector<AgentInfo>& after, const Scene& afterScene,
                                      std::uint64_t seed)
{
    std::map<Key, std::int32_t> index;
    const std::vector<Key> old = keysOf(before, beforeScene, afterScene, seed);
    for (std::size_t i = 0; i < old.size(); ++i)
        if (std::get<0>(old[i]) != 3 && std::get<0>(old[i]) != 5)
            index.emplace(old[i], std::int32_t(i));
    std::vector<std::int32_t> previous(after.size(), -1);
    const std::vector<Key> now = keysOf(after, afterScene, beforeScene, seed);
    for (std::size_t i = 0; i < now.size(); ++i)
        if (auto it = index.find(now[i]); it != index.end())
            previous[i] = it->second;
    return previous;
}

WorldState remapState(const WorldState& old, const WorldState& fresh, const std::vector<std::int32_t>& previous)
{
    const std::size_t n = previous.size();
    auto gather = [&](const auto& from, const auto& base) {
        auto out = base;
        for (std::size_t i = 0; i < n && i < out.size(); ++i)
            if (previous[i] >= 0 && std::size_t(previous[i]) < from.size())
                out[i] = from[std::size_t(previous[i])];
        return out;
    };
    WorldState s = old;  // the global state: step, counters, traffic, navigation grid, brains
    // Kept agents keep their id (what their random draws are keyed by: a stroke that adds
    // placed agents moves the ids of every group member); the type is fixed by adoptState.
    s.agents = gather(old.agents, fresh.agents);
#define THRONG_REMAP(name) s.name = gather(old.name, fresh.name);
    THRONG_AGENT_COLUMNS(THRONG_REMAP)
#undef THRONG_REMAP
#define THRONG_REMAP(world, name) s.name = gather(old.name, fresh.name);
    THRONG_NAV_COLUMNS(THRONG_REMAP)
#undef THRONG_REMAP
    s.signal = gather(old.signal, fresh.signal);
    // Recomputed by every step before they are read.
    s.pedestriansBefore = fresh.pedestriansBefore;
    s.pedestriansAfter = fresh.pedestriansAfter;
    // Whom each agent sensed: old indices to new ones, removed neighbours dropped.
    std::vector<std::int32_t> newIndex(old.agents.size(), -1);
    for (std::size_t i = 0; i < n; ++i)
        if (previous[i] >= 0)
            newIndex[std::size_t(previous[i])] = std::int32_t(i);
    const std::size_t k = World::kMaxNeighbours;
    s.nearIndex = fresh.nearIndex;
    s.nearCount = fresh.nearCount;
    for (std::size_t i = 0; i < n; ++i) {
        if (previous[i] < 0)
            continue;
        const std::size_t p = std::size_t(previous[i]);
        std::uint8_t count = 0;
        for (std::size_t j = 0; j < old.nearCount[p]; ++j) {
            const std::uint32_t was = old.nearIndex[p * k + j];
            if (const std::int32_t q = was < newIndex.size() ? newIndex[was] : -1; q >= 0)
                s.nearIndex[i * k + count++] = std::uint32_t(q);
        }
        s.nearCount[i] = count;
    }
    // The neighbour grid indexes the old order: the next step builds it again.
    s.grid = fresh.grid;
    s.gridCurrent = false;
    // Brains: per agent its old batch and index (into the old memory, which stays whole);
    // a new agent has none and starts with fresh memory.
    if (s.hasBrains && fresh.hasBrains) {
        s.brainBatch.assign(n, -1);
        s.brainLocal.assign(n, -1);
        s.brainAction = fresh.brainAction;
        for (std::size_t i = 0; i < n; ++i) {
            if (previous[i] < 0)
                continue;
            const std::size_t p = std::size_t(previous[i]);
            s.brainBatch[i] = p < old.brainBatch.size() ? old.brainBatch[p] : -1;
            s.brainLocal[i] = p < old.brainLocal.size() ? old.brainLocal[p] : -1;
            if (p < old.brainAction.size())
                s.brainAction[i] = old.brainAction[p];
        }
        s.tags = fresh.tags;
        s.tagValues = fresh.tagValues;
        for (std::size_t t = 0; t < fresh.tags.size(); ++t)
            for (std::size_t u = 0; u < old.tags.size(); ++u)
                if (old.tags[u] == fresh.tags[t])
                    s.tagValues[t] = gather(old.tagValues[u], fresh.tagValues[t]);
    } else {
        s.hasBrains = false;
    }
    return s;
}

}  // namespace throng::sim
