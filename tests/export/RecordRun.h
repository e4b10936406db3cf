#pragma once
// A World's run recorded as the editor and throng-cli record it: frame 0 as built, then
// one frame per step, `frames` in all. For the tests that export or read back a run.

#include "simcore/world/FrameCache.h"
#include "simcore/world/World.h"

#include <cstddef>
#include <vector>

namespace throng::test {

inline void recordRun(sim::World& world, std::size_t frames, sim::FrameCache& cache)
{
    world.startRecording(cache);
    std::vector<sim::AgentFrame> frame;
    for (std::size_t f = 1; f < frames; ++f) {
        world.step();
        world.snapshot(frame);
        cache.append(frame);
    }
}

}  // namespace throng::test
