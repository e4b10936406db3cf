#pragma once
// The recorded frames of a run: per frame and agent what playback and export need
// (position, heading, speed, clip, gait phase, whether it has left the shot, whether it
// exists at all). Filled by the simulation, read by the viewport and the exporters;
// never simulates.
//
// The agent set may change during a recording (issue 6: a crowd-brush stroke at frame k
// resumes the run with more agents). The cache's agents are then the union of every
// agent the recording has seen, each frame has one entry per cache agent, and an agent
// that did not exist on a frame is marked not `present` there. The World's dense index
// maps to the cache's agent index (worldSlot); an "epoch" starts wherever the set or an
// agent's type changed, and agentsAt(f) gives each agent's type on frame f.

#include "simcore/scene/Clip.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace throng::sim {

using AgentId = std::uint32_t;

struct AgentFrame {
    glm::vec3 position{0.0f};  // m
    float headingRad = 0.0f;   // yaw about +y, 0 = facing +x, counter-clockwise from above
    float speed = 0.0f;        // m/s
    float phase = 0.0f;        // gait cycle phase in [0, 1) (an action's phase: actionPhase, Clip.h)
    Clip clip = Clip::Idle;
    // Left through an exit on or before this frame: no longer in the shot (the viewport
    // draws nothing, exports hide it); position and heading stay where it left.
    bool out = false;
    // False where the agent did not exist on this frame (added by an edit later, or
    // removed by an edit earlier): nothing is drawn or exported for it, and the other
    // fields mean nothing. Distinct from `out`: an agent that left is still in the run.
    bool present = true;
    // Entered its goal's area or reached its path's end on or before this frame (the
    // stats' "arrived"); it may still be standing in the shot.
    bool arrived = false;
};

struct AgentInfo {
    AgentId id = 0;
    std::uint16_t typeIndex = 0;  // index into Scene::agentTypes
    // What a layout layer's swap shows instead of the drawn look and tint (LayoutApply.h);
    // the simulation never sets them. In the 8 bytes the id and type leave.
    static constexpr std::uint8_t kDrawnLook = 0xff;
    static constexpr std::int8_t kDrawnTint = -2;
    std::uint8_t look = kDrawnLook;  // index into the type's looks
    std::int8_t tint = kDrawnTint;   // index into the type's tints, -1 = untinted
};
static_assert(sizeof(AgentInfo) == 8, "a World keeps one per agent");

class FrameCache {
public:
    // Starts an empty recording for these agents (dense index order). Frame positions are
    // relative to `origin` (World::origin): whoever writes them out adds it, in double.
    void reset(std::vector<AgentInfo> agents, float fps, glm::dvec3 origin = glm::dvec3(0.0));
    // From the next appended frame on, the World's agents are `worldAgents` (dense order);
    // previous[i] is the World index agent i had before (-1: a new agent, which gets a new
    // cache agent). Cache agents no World agent maps to are absent from then on.
    void changeAgents(std::span<const AgentInfo> worldAgents, std::span<const std::int32_t> previous);
    // Appends one frame in the World's dense order; `frame.size()` must equal worldAgentCount().
    void append(std::span<const AgentFrame> frame);
    // Drops frames from `firstFrameToDrop` on (an edit invalidates the cache from there);
    // agent sets that began there are dropped with them (the earlier set comes back).
    void truncate(std::size_t firstFrameToDrop);

    std::size_t frameCount() const { return m_count == 0 ? 0 : m_frames.size() / m_count; }
    // Cache agents: every agent of the recording (the width of a frame).
    std::size_t agentCount() const { return m_count; }
    float fps() const { return m_fps; }
    glm::dvec3 origin() const { return m_origin; }
    std::span<const AgentFrame> frame(std::size_t f) const { return {m_frames.data() + f * m_count, m_count}; }
    // For the layout layer's swap, on a copy of a recording: cache agent i shows `look` and
    // `tint` (AgentInfo's) on every frame, and, when given, the type `type` instead of the
    // one each agent set recorded.
    void swapAgent(std::size_t i, std::optional<std::uint16_t> type, std::uint8_t look, std::int8_t tint);
    const AgentFrame& at(std::size_t f, std::size_t agent) const { return m_frames[f * m_count + agent]; }
    // For the layout layer (LayoutApply.h), which edits a copy of a recording: agent
    // `agent`'s entry on frame f, to rewrite. The copy is not a new recording.
    AgentFrame& edit(std::size_t f, std::size_t agent) { return m_frames[f * m_count + agent]; }
    // Every cache agent, with the type of the latest agent set.
    const std::vector<AgentInfo>& agents() const { return m_epochs.back().agents; }
    // Every cache agent with the type it had on frame f (its last one where absent).
    const std::vector<AgentInfo>& agentsAt(std::size_t f) const { return epochAt(f).agents; }
    // The World's agent count and dense index -> cache agent, from the latest set on.
    std::size_t worldAgentCount() const { return m_epochs.back().slot.size(); }
    std::size_t cacheIndexOf(std::size_t worldIndex) const { return m_epochs.back().slot[worldIndex]; }
    // The World index of cache agent `agent` in the latest set; -1 when it is not there.
    std::ptrdiff_t worldIndexOf(std::size_t agent) const;
    // Frames where the agent set or a type changed (frame 0 first).
    std::vector<std::size_t> agentSetChanges() const;
    // Counts the changes that record frames again (reset, truncate). A reader that keeps
    // something made from the frames notes the revision, and later keeps what it made from
    // the first framesKeptSince(revision) frames: those are the same as they were then.
    std::uint64_t revision() const { return m_revision; }
    std::size_t framesKeptSince(std::uint64_t revision) const;
    // FNV-1a over every recorded byte that matters and the agent sets: equal hashes =
    // identical recordings.
    std::uint64_t hash() const;
    // The same over frames [first, last) only (the frames an edit must keep).
    std::uint64_t hashFrames(std::size_t first, std::size_t last) const;

private:
    struct Epoch {
        std::size_t firstFrame = 0;
        std::size_t width = 0;           // cache agents when it began
        std::vector<AgentInfo> agents;   // every cache agent (full width), with this epoch's types
        std::vector<std::uint32_t> slot; // World dense index -> cache agent
    };
    const Epoch& epochAt(std::size_t f) const;
    void setWidth(std::size_t width);

    std::vector<Epoch> m_epochs{1};
    std::vector<AgentFrame> m_frames;  // frame-major, m_count per frame
    std::size_t m_count = 0;
    float m_fps = 24.0f;
    glm::dvec3 m_origin{0.0};
    std::uint64_t m_revision = 0;
    // Since the last reset: per change, the revision it made and the frames it kept.
    std::vector<std::pair<std::uint64_t, std::size_t>> m_rewrites;
};

// Adds `origin` to each frame's position, in floats: for the viewport, which draws the
// set in the scene's coordinates at float precision anyway. Exports add it in double.
void addOrigin(std::span<AgentFrame> frames, glm::dvec3 origin);

}  // namespace throng::sim
