#pragma once
// Applies a scene's layout layer (LayoutLayer.h) to a recording: the agents each enabled
// operation selects, on the frames it names, moved, turned, retimed, mirrored, removed or
// spread, operation after operation. Agents no operation selects keep their frames byte
// for byte. Reads Scene and FrameCache; never simulates.

#include "simcore/layout/LayoutLayer.h"
#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"

#include <array>
#include <span>
#include <string>
#include <vector>

namespace throng::sim {

// A copy a duplicate makes: of cache agent `source` (a recorded agent, or an earlier copy),
// with id `id`. Copies follow the recorded agents in the laid-out frames, in the order the
// operations make them: copy c is cache agent recorded.agentCount() + c.
struct LayoutCopy {
    std::size_t op = 0, source = 0;
    AgentId id = 0;
};
// Copies' ids count up from here (past the recording's highest id, if that is higher), so
// that a copy keeps its id when a re-simulation changes the crowd around it.
inline constexpr AgentId kFirstCopyId = 1'000'000'000;

// The cache agents (indices) each operation of `layer` selects in `recorded` (and among the
// copies earlier operations made, by id or type), the copies its enabled duplicates make,
// and what the user should hear about: an operation that selects nobody (its agents no
// longer exist after a re-simulation, say), ids the recording lacks, names no group or
// type has.
struct LayoutSelection {
    std::vector<std::vector<std::size_t>> agents;  // per operation, sorted
    std::vector<LayoutCopy> copies;
    std::vector<std::string> messages;
};
LayoutSelection selectLayoutAgents(const Scene& scene, const LayoutLayer& layer, const FrameCache& recorded);

// The layer applied to a recording: one frame at a time, as the viewport shows them
// (frame f costs what its operations touch; a time offset also evaluates the frames it
// shows), or every frame at once, operation after operation, as the exports write them.
// Both go through the same per-operation code. Keeps references to `scene`'s layer and to
// `recorded`, which must outlive it.
class LayoutEvaluator {
public:
    LayoutEvaluator(const Scene& scene, const FrameCache& recorded);
    const std::vector<std::string>& messages() const { return m_selection.messages; }
    // The laid-out agents: the recording's, then the copies, with what swaps show instead
    // (type, look, tint).
    const std::vector<AgentInfo>& agents() const { return m_agents; }
    // Frame f with every enabled operation applied, one entry per laid-out agent.
    void frame(std::size_t f, std::vector<AgentFrame>& out) const;
    // Every frame so: a copy of the recording, edited (one agent set: the laid-out agents).
    FrameCache allFrames() const;

private:
    // What a time offset shows of agent i on frame f: the frame of the stage before it,
    // and whether it stands there (a held pose) or, before its start, may be absent.
    struct Shown {
        std::size_t frame = 0;
        bool standing = false;
        bool beforeStart = false;
    };
    Shown shown(std::size_t op, std::size_t f, std::size_t agent) const;
    AgentFrame showing(std::size_t op, const Shown& s, const AgentFrame& there) const;
    // Operation `op` (any but a time offset) on frame f's agents, in place.
    void applyInFrame(std::size_t op, std::size_t f, std::span<AgentFrame> frame) const;
    // A resolve on frame f (LayoutResolve.h).
    void resolveInFrame(std::size_t op, std::size_t f, std::span<AgentFrame> frame) const;
    struct Memo;
    // Frame f after the first `ops` operations.
    const std::vector<AgentFrame>& evaluate(std::size_t ops, std::size_t f, Memo& memo) const;

    const LayoutLayer& m_layer;
    const FrameCache& m_recorded;
    LayoutSelection m_selection;
    std::vector<AgentInfo> m_agents;                                     // laid-out agents
    std::vector<std::vector<std::pair<std::size_t, std::size_t>>> m_copiesOf;  // per operation: (source, copy)
    std::vector<glm::vec2> m_pivots;          // per operation: rotate's pivot, in the cache's coordinates
    std::vector<std::size_t> m_firstPresent;  // time offsets: per laid-out agent, its first frame (frames: never)
    glm::vec2 m_shift{0.0f};                  // scene coordinates -> the cache's
    std::vector<float> m_radius;              // per laid-out agent, its type's body radius, m
    std::vector<std::array<glm::vec2, 2>> m_walls;  // wall segments, in the cache's coordinates
};

// `recorded` with `scene.layout` applied; `messages` (when given) gets selectLayoutAgents'.
FrameCache applyLayout(const Scene& scene, const FrameCache& recorded, std::vector<std::string>* messages = nullptr);

}  // namespace throng::sim
