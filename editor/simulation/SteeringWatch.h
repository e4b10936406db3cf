#pragma once
// The agents whose steering the user watches (the selection, the focused and the
// inspected agent), and their annotations in a World (World::describeAgent through a
// DebugRecorder). Set from the GUI thread, read on the runner's; knows nothing of widgets.

#include "simcore/world/DebugSink.h"
#include "simcore/world/FrameCache.h"

#include <cstddef>
#include <cstdint>
#include <mutex>
#include <vector>

namespace throng::sim {
class World;
}

namespace throng::editor {

class SteeringWatch {
public:
    // More would flood the view and cost a scan per frame: the first ones are kept.
    static constexpr std::size_t kMaxWatched = 32;

    // Any thread. Empty: nobody is watched.
    void set(std::vector<sim::AgentId> ids);
    std::vector<sim::AgentId> ids() const;
    bool empty() const;

    // The watched agents' annotations in `world`'s current state, in the order of ids();
    // an agent the World does not hold is left out. Finds their indices again only when
    // the World or the ids changed.
    std::vector<sim::AgentDebug> describe(const sim::World& world);
    // The runner's World was replaced: indices are found again on the next describe.
    void forgetWorld() { m_world = nullptr; }
    // The same for any World and ids, finding the indices by a scan.
    static std::vector<sim::AgentDebug> describe(const sim::World& world, const std::vector<sim::AgentId>& ids);

private:
    static std::vector<std::size_t> indicesOf(const sim::World& world, const std::vector<sim::AgentId>& ids);

    mutable std::mutex m_mutex;
    std::vector<sim::AgentId> m_ids;
    std::uint64_t m_generation = 0;
    // The runner thread's: the indices found in the World last described.
    const sim::World* m_world = nullptr;
    std::size_t m_worldAgents = 0;
    std::uint64_t m_resolvedGeneration = ~std::uint64_t(0);
    std::vector<std::size_t> m_indices;
};

}  // namespace throng::editor
