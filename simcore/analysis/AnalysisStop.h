#pragma once
// A flag another thread sets to stop an analysis early (the editor's Analysis dock, when the
// recording is about to change under it). The analyses look at it once a frame; null = never.

#include <atomic>

namespace throng::sim {

using StopFlag = const std::atomic<bool>*;

inline bool stopRequested(StopFlag stop)
{
    return stop != nullptr && stop->load(std::memory_order_relaxed);
}

}  // namespace throng::sim
