#include "simcore/world/FrameCache.h"

#include <cassert>
#include <cstring>

namespace throng::sim {

const char* toString(Clip clip)
{
    switch (clip) {
    case Clip::Idle: return "idle";
    case Clip::Walk: return "walk";
    case Clip::Run: return "run";
    }
    return "idle";
}

void FrameCache::reset(std::vector<AgentInfo> agents, float fps)
{
    m_agents = std::move(agents);
    m_count = m_agents.size();
    m_frames.clear();
    m_fps = fps;
}

void FrameCache::append(std::span<const AgentFrame> frame)
{
    assert(frame.size() == m_count);
    m_frames.insert(m_frames.end(), frame.begin(), frame.end());
}

void FrameCache::truncate(std::size_t firstFrameToDrop)
{
    if (firstFrameToDrop < frameCount())
        m_frames.resize(firstFrameToDrop * m_count);
}

std::uint64_t FrameCache::hash() const
{
    std::uint64_t h = 1469598103934665603ull;
    auto mix = [&](const void* data, std::size_t n) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < n; ++i)
            h = (h ^ p[i]) * 1099511628211ull;
    };
    for (const AgentFrame& f : m_frames) {
        // Field by field: padding bytes are not part of the result.
        mix(&f.position, sizeof f.position);
        mix(&f.headingRad, sizeof f.headingRad);
        mix(&f.speed, sizeof f.speed);
        mix(&f.phase, sizeof f.phase);
        mix(&f.clip, sizeof f.clip);
        const std::uint8_t out = f.out ? 1 : 0;
        mix(&out, sizeof out);
    }
    return h;
}

}  // namespace throng::sim
