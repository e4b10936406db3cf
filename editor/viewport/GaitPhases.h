#pragma once
// Each recorded agent's gait as the glTF export computes it (exporting::advanceGait over
// the agent's frames from the first, held where it is absent), at any frame of a frame
// cache: the viewport's legs then cycle, and its horses change gait, as the exported
// file's do. Playing forward steps one frame; a jump back restarts from the checkpoint
// kept every few frames before it. Never simulates; no GL.

#include "export/character/AgentVariation.h"
#include "export/character/Character.h"
#include "export/character/Gait.h"
#include "simcore/world/FrameCache.h"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace throng::editor {

class GaitPhases {
public:
    // Who walks how, per cache agent: its character (nullptr: no gait, left at frame 0's)
    // and its variation (phase offset, height and pace).
    struct Walker {
        const exporting::Character* character = nullptr;
        exporting::AgentVariation variation;
    };

    // Per cache agent, its gait on `frame` (< cache.frameCount()). `walkers` must stay the
    // same between calls for the same recording (forget() when they change); the cache may
    // grow, and it may be truncated and recorded again (revision() tells). Walkers that are
    // not one per cache agent give an empty `out`.
    void gaitAt(const sim::FrameCache& cache, std::size_t frame, std::span<const Walker> walkers,
                std::vector<exporting::GaitFrame>& out);
    // Drops every clock: the walkers or the recording changed.
    void forget();

    // Frames between two checkpoints (for tests).
    std::size_t checkpointStride() const { return m_stride; }

private:
    // Starts over: every clock at its phase offset, before frame 0.
    void restart(const sim::FrameCache& cache, std::span<const Walker> walkers);
    // Steps every clock over frame m_next (keeping a checkpoint before it on multiples of
    // the stride).
    void step(const sim::FrameCache& cache, std::span<const Walker> walkers);

    const sim::FrameCache* m_cache = nullptr;
    std::uint64_t m_revision = 0;                          // the cache's, when the clocks were last checked
    std::size_t m_stride = 16;
    std::size_t m_next = 0;                                // the frame m_clocks step over next
    bool m_valid = false;                                  // m_clocks hold the state before m_next
    std::vector<exporting::GaitClock> m_clocks;            // per cache agent
    std::vector<exporting::GaitFrame> m_gait;              // per cache agent, on frame m_next - 1
    std::vector<std::vector<exporting::GaitClock>> m_kept; // clocks before frames 0, stride, 2 * stride, ...
};

}  // namespace throng::editor
