#pragma once
// The recorded frames of a run: per frame and agent what playback and export need
// (position, heading, speed, clip, gait phase, whether it has left the shot). Filled by the simulation, read by the
// viewport and the exporters; never simulates.

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace throng::sim {

using AgentId = std::uint32_t;

enum class Clip : std::uint8_t { Idle = 0, Walk = 1, Run = 2 };
const char* toString(Clip clip);

struct AgentFrame {
    glm::vec3 position{0.0f};  // m
    float headingRad = 0.0f;   // yaw about +y, 0 = facing +x, counter-clockwise from above
    float speed = 0.0f;        // m/s
    float phase = 0.0f;        // gait cycle phase in [0, 1)
    Clip clip = Clip::Idle;
    // Left through an exit on or before this frame: no longer in the shot (the viewport
    // draws nothing, exports hide it); position and heading stay where it left.
    bool out = false;
};

struct AgentInfo {
    AgentId id = 0;
    std::uint16_t typeIndex = 0;  // index into Scene::agentTypes
};

class FrameCache {
public:
    // Starts an empty recording for these agents (dense index order).
    void reset(std::vector<AgentInfo> agents, float fps);
    // Appends one frame; `frame.size()` must equal agentCount().
    void append(std::span<const AgentFrame> frame);
    // Drops frames from `firstFrameToDrop` on (an edit invalidates the cache from there).
    void truncate(std::size_t firstFrameToDrop);

    std::size_t frameCount() const { return m_count == 0 ? 0 : m_frames.size() / m_count; }
    std::size_t agentCount() const { return m_count; }
    float fps() const { return m_fps; }
    std::span<const AgentFrame> frame(std::size_t f) const { return {m_frames.data() + f * m_count, m_count}; }
    const AgentFrame& at(std::size_t f, std::size_t agent) const { return m_frames[f * m_count + agent]; }
    const std::vector<AgentInfo>& agents() const { return m_agents; }
    // FNV-1a over every recorded byte that matters: equal hashes = identical frames.
    std::uint64_t hash() const;

private:
    std::vector<AgentInfo> m_agents;
    std::vector<AgentFrame> m_frames;  // frame-major
    std::size_t m_count = 0;
    float m_fps = 24.0f;
};

}  // namespace throng::sim
