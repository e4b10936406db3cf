#include "simcore/world/FrameCache.h"

#include <algorithm>
#include <atomic>
#include <cassert>
#include <cstring>
#include <limits>

namespace throng::sim {

namespace {

// Revisions are counted over every cache of the process, so a reader that kept one cache's
// revision never takes another cache (one made where the first was) for it.
std::uint64_t nextRevision()
{
    static std::atomic<std::uint64_t> last{0};
    return ++last;
}

AgentFrame absentFrame()
{
    AgentFrame f;
    f.present = false;
    return f;
}

}  // namespace

void FrameCache::reset(std::vector<AgentInfo> agents, float fps, glm::dvec3 origin)
{
    m_origin = origin;
    m_count = agents.size();
    Epoch e;
    e.width = m_count;
    e.slot.resize(m_count);
    for (std::size_t i = 0; i < m_count; ++i)
        e.slot[i] = std::uint32_t(i);
    e.agents = std::move(agents);
    m_epochs.assign(1, std::move(e));
    m_frames.clear();
    m_fps = fps;
    m_revision = nextRevision();
    m_rewrites.assign(1, {m_revision, 0});
}

// Re-lays the recorded frames out for `width` cache agents: new columns absent, dropped
// columns (only ever the last ones) gone.
void FrameCache::setWidth(std::size_t width)
{
    if (width == m_count)
        return;
    const std::size_t frames = frameCount();
    std::vector<AgentFrame> out(frames * width, absentFrame());
    const std::size_t keep = std::min(width, m_count);
    for (std::size_t f = 0; f < frames; ++f)
        std::copy_n(m_frames.begin() + std::ptrdiff_t(f * m_count), keep, out.begin() + std::ptrdiff_t(f * width));
    m_frames = std::move(out);
    m_count = width;
}

void FrameCache::changeAgents(std::span<const AgentInfo> worldAgents, std::span<const std::int32_t> previous)
{
    assert(previous.size() == worldAgents.size());
    const Epoch& last = m_epochs.back();
    Epoch e;
    e.firstFrame = frameCount();
    e.agents = last.agents;
    e.slot.resize(worldAgents.size());
    for (std::size_t i = 0; i < worldAgents.size(); ++i) {
        const std::int32_t p = previous[i];
        if (p >= 0 && std::size_t(p) < last.slot.size()) {
            e.slot[i] = last.slot[std::size_t(p)];
            e.agents[e.slot[i]].typeIndex = worldAgents[i].typeIndex;
        } else {
            e.slot[i] = std::uint32_t(e.agents.size());
            e.agents.push_back(worldAgents[i]);
        }
    }
    e.width = e.agents.size();
    bool same = e.slot == last.slot && e.width == last.agents.size();
    for (std::size_t k = 0; same && k < e.width; ++k)
        same = e.agents[k].id == last.agents[k].id && e.agents[k].typeIndex == last.agents[k].typeIndex;
    if (same)
        return;  // the same agents with the same types: nothing changes
    // Earlier sets know the new agents too (absent there), so every list is full width.
    for (Epoch& old : m_epochs)
        for (std::size_t k = old.agents.size(); k < e.width; ++k)
            old.agents.push_back(e.agents[k]);
    setWidth(e.width);
    if (!m_epochs.empty() && m_epochs.back().firstFrame == e.firstFrame && m_epochs.size() > 1)
        m_epochs.back() = std::move(e);  // two changes before any frame: the later one holds
    else
        m_epochs.push_back(std::move(e));
}

void FrameCache::append(std::span<const AgentFrame> frame)
{
    const Epoch& e = m_epochs.back();
    assert(frame.size() == e.slot.size());
    const std::size_t begin = m_frames.size();
    if (e.slot.size() == m_count && m_epochs.size() == 1) {
        m_frames.insert(m_frames.end(), frame.begin(), frame.end());
        return;
    }
    m_frames.resize(begin + m_count, absentFrame());
    for (std::size_t i = 0; i < frame.size() && i < e.slot.size(); ++i)
        m_frames[begin + e.slot[i]] = frame[i];
}

std::size_t FrameCache::framesKeptSince(std::uint64_t revision) const
{
    std::size_t kept = std::numeric_limits<std::size_t>::max();
    if (!m_rewrites.empty() && revision < m_rewrites.front().first)
        return 0;  // from before the last reset
    for (const auto& [made, frames] : m_rewrites)
        if (made > revision)
            kept = std::min(kept, frames);
    return std::min(kept, frameCount());
}

void FrameCache::truncate(std::size_t firstFrameToDrop)
{
    if (firstFrameToDrop < frameCount()) {
        m_frames.resize(firstFrameToDrop * m_count);
        m_revision = nextRevision();
        m_rewrites.emplace_back(m_revision, firstFrameToDrop);
    }
    // Sets that began at a dropped frame go (the first one always stays).
    while (m_epochs.size() > 1 && m_epochs.back().firstFrame >= firstFrameToDrop)
        m_epochs.pop_back();
    const std::size_t width = m_epochs.back().width;
    if (width < m_count) {
        setWidth(width);
        for (Epoch& e : m_epochs)
            e.agents.resize(width);
    }
}

void FrameCache::swapAgent(std::size_t i, std::optional<std::uint16_t> type, std::uint8_t look, std::int8_t tint)
{
    for (Epoch& e : m_epochs) {
        if (i >= e.agents.size())
            continue;
        if (type)
            e.agents[i].typeIndex = *type;
        e.agents[i].look = look;
        e.agents[i].tint = tint;
    }
}

const FrameCache::Epoch& FrameCache::epochAt(std::size_t f) const
{
    for (std::size_t k = m_epochs.size(); k-- > 1;)
        if (m_epochs[k].firstFrame <= f)
            return m_epochs[k];
    return m_epochs.front();
}

std::ptrdiff_t FrameCache::worldIndexOf(std::size_t agent) const
{
    const std::vector<std::uint32_t>& slot = m_epochs.back().slot;
    for (std::size_t i = 0; i < slot.size(); ++i)
        if (slot[i] == agent)
            return std::ptrdiff_t(i);
    return -1;
}

std::vector<std::size_t> FrameCache::agentSetChanges() const
{
    std::vector<std::size_t> out;
    for (const Epoch& e : m_epochs)
        out.push_back(e.firstFrame);
    return out;
}

namespace {

struct Fnv {
    std::uint64_t h = 1469598103934665603ull;
    void mix(const void* data, std::size_t n)
    {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < n; ++i)
            h = (h ^ p[i]) * 1099511628211ull;
    }
    void frame(const AgentFrame& f)
    {
        // Field by field: padding bytes are not part of the result.
        const std::uint8_t present = f.present ? 1 : 0;
        mix(&present, sizeof present);
        if (!f.present)
            return;
        mix(&f.position, sizeof f.position);
        mix(&f.headingRad, sizeof f.headingRad);
        mix(&f.speed, sizeof f.speed);
        mix(&f.phase, sizeof f.phase);
        mix(&f.clip, sizeof f.clip);
        const std::uint8_t out = f.out ? 1 : 0;
        mix(&out, sizeof out);
    }
};

}  // namespace

std::uint64_t FrameCache::hash() const
{
    Fnv h;
    for (const Epoch& e : m_epochs) {
        const std::uint64_t first = e.firstFrame;
        h.mix(&first, sizeof first);
        for (const AgentInfo& a : e.agents) {
            h.mix(&a.id, sizeof a.id);
            h.mix(&a.typeIndex, sizeof a.typeIndex);
        }
    }
    for (const AgentFrame& f : m_frames)
        h.frame(f);
    // Only a far scene's origin is mixed in, so every hash near (0, 0) stays as it was.
    if (m_origin != glm::dvec3(0.0))
        h.mix(&m_origin, sizeof m_origin);
    return h.h;
}

std::uint64_t FrameCache::hashFrames(std::size_t first, std::size_t last) const
{
    Fnv h;
    last = std::min(last, frameCount());
    for (std::size_t f = first; f < last; ++f)
        for (const AgentFrame& a : frame(f))
            if (a.present)
                h.frame(a);
    return h.h;
}

void addOrigin(std::span<AgentFrame> frames, glm::dvec3 origin)
{
    if (origin == glm::dvec3(0.0))
        return;
    for (AgentFrame& f : frames)
        f.position = glm::vec3(glm::dvec3(f.position) + origin);
}

}  // namespace throng::sim
