#pragma once
// Analyses a recorded run (sim::analyseRun) on its own thread, reading the frame cache in
// place: a copy of 10,000 walkers over 2,400 frames would take 0.8 GB. Whoever owns the
// cache keeps it still until the job is done or stopped (SimulationController's cache
// reader). Progress and the result are read from the GUI thread; never touches widgets.

#include "simcore/analysis/RunAnalysis.h"
#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"

#include <atomic>
#include <thread>

namespace throng::editor {

class AnalysisJob {
public:
    // Starts analysing every frame of `cache`, with `scene`'s measurements (copied).
    AnalysisJob(sim::Scene scene, const sim::FrameCache& cache, sim::AnalysisOptions options = {});
    ~AnalysisJob();  // stops and waits
    AnalysisJob(const AnalysisJob&) = delete;
    AnalysisJob& operator=(const AnalysisJob&) = delete;

    // Asks the analysis to stop and returns once it no longer reads the cache (within a
    // frame's worth of work); the result is then incomplete.
    void stop();
    double progress() const { return m_progress.load(); }  // 0 to 1
    bool isDone() const { return m_done.load(); }
    // Valid once isDone(); `complete` is false when it was stopped.
    const sim::RunAnalysis& result() const { return m_result; }

private:
    std::atomic<double> m_progress{0.0};
    std::atomic<bool> m_stop{false};
    std::atomic<bool> m_done{false};
    sim::RunAnalysis m_result;
    std::thread m_thread;
};

}  // namespace throng::editor
