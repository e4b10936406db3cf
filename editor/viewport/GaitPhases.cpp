#include "editor/viewport/GaitPhases.h"

#include <algorithm>

namespace throng::editor {

namespace {

// Checkpoints take at most about this many bytes for a long shot (10 minutes at 24 fps):
// a bigger crowd keeps them further apart, and a jump back steps further.
constexpr std::size_t kCheckpointBytes = std::size_t(64) << 20;
constexpr std::size_t kLongShotFrames = 10 * 60 * 24;
constexpr std::size_t kMinStride = 16;

}  // namespace

void GaitPhases::forget()
{
    m_cache = nullptr;
    m_clocks.clear();
    m_gait.clear();
    m_kept.clear();
    m_valid = false;
}

void GaitPhases::restart(const sim::FrameCache& cache, std::span<const Walker> walkers)
{
    m_cache = &cache;
    m_revision = cache.revision();
    const std::size_t agents = walkers.size();
    const std::size_t perCheckpoint = std::max<std::size_t>(1, agents * sizeof(exporting::GaitClock));
    const std::size_t checkpoints = std::max<std::size_t>(1, kCheckpointBytes / perCheckpoint);
    m_stride = std::max(kMinStride, (kLongShotFrames + checkpoints - 1) / checkpoints);
    m_clocks.resize(agents);
    for (std::size_t i = 0; i < agents; ++i)
        m_clocks[i] = exporting::startGait(walkers[i].variation);
    m_gait.assign(agents, exporting::GaitFrame{});
    m_kept.assign(1, m_clocks);
    m_next = 0;
    m_valid = true;
}

void GaitPhases::step(const sim::FrameCache& cache, std::span<const Walker> walkers)
{
    if (m_next % m_stride == 0 && m_next / m_stride == m_kept.size())
        m_kept.push_back(m_clocks);
    for (std::size_t i = 0; i < walkers.size(); ++i) {
        const Walker& w = walkers[i];
        if (!w.character)
            continue;
        exporting::GaitClock& clock = m_clocks[i];
        const sim::AgentFrame& a = cache.at(m_next, i);
        // As the export reads the recording: where absent, at rest where it was last; before
        // it first appears, nothing moves it (the export holds it where it will appear).
        if (a.present)
            m_gait[i] = exporting::advanceGait(*w.character, w.variation, clock, a.position, a.speed);
        else if (clock.started)
            m_gait[i] = exporting::advanceGait(*w.character, w.variation, clock, clock.position, 0.0f);
        else
            m_gait[i].phase = clock.phase;
    }
    ++m_next;
}

void GaitPhases::gaitAt(const sim::FrameCache& cache, std::size_t frame, std::span<const Walker> walkers,
                        std::vector<exporting::GaitFrame>& out)
{
    // Walkers for another agent set than the cache's: no gait (the caller draws the frames'
    // own phases) rather than frames read past their width.
    if (cache.agentCount() != walkers.size()) {
        forget();
        out.clear();
        return;
    }
    if (&cache != m_cache || walkers.size() != m_clocks.size()) {
        restart(cache, walkers);
    } else if (cache.revision() != m_revision) {
        // Frames from `kept` on were recorded again: what was stepped over them is stale.
        const std::size_t kept = cache.framesKeptSince(m_revision);
        while (m_kept.size() > 1 && (m_kept.size() - 1) * m_stride > kept)
            m_kept.pop_back();
        if (m_next > kept)
            m_valid = false;
        m_revision = cache.revision();
    }
    if (cache.frameCount() == 0) {
        out.assign(walkers.size(), exporting::GaitFrame{});
        for (std::size_t i = 0; i < walkers.size(); ++i)
            out[i].phase = exporting::startGait(walkers[i].variation).phase;
        return;
    }
    frame = std::min(frame, cache.frameCount() - 1);
    // From the clocks where they are when they are on or before the frame, unless a
    // checkpoint is nearer; else from the last checkpoint before it.
    const std::size_t c = std::min(frame / m_stride, m_kept.size() - 1);
    const bool current = m_valid && m_next >= 1 && m_next - 1 <= frame;
    if (!current || c * m_stride > m_next) {
        m_clocks = m_kept[c];
        m_next = c * m_stride;
        m_valid = true;
    }
    while (m_next <= frame)
        step(cache, walkers);
    out = m_gait;
}

}  // namespace throng::editor
