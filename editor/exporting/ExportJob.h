#pragma once
// Runs one export (any row of exporting::exportFormats()) of a frame range on its own
// thread, with progress and cancel readable from the GUI thread. Copies what it exports,
// so the recording may change meanwhile; never touches widgets.

#include "export/ExportFormats.h"
#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"

#include <atomic>
#include <cstddef>
#include <string>
#include <thread>

namespace throng::editor {

struct ExportJobRequest {
    const exporting::ExportFormat* format = nullptr;  // a row of exporting::exportFormats()
    exporting::ExportRequest output;                  // path and the format's choices
    std::size_t firstFrame = 0, lastFrame = 0;        // inclusive, < cache.frameCount()
};

class ExportJob {
public:
    // Starts exporting frames first..last of `cache` (copied) on a new thread.
    ExportJob(const sim::Scene& scene, const sim::FrameCache& cache, ExportJobRequest request);
    ~ExportJob();  // cancels and waits

    float progress() const { return m_progress.load(); }
    bool isDone() const { return m_done.load(); }
    void cancel() { m_cancel = true; }
    const exporting::ExportFormat& format() const { return *m_format; }
    // Valid once isDone().
    const exporting::ExportResult& result() const { return m_result; }

private:
    void run(sim::Scene scene, sim::FrameCache frames, ExportJobRequest request);

    const exporting::ExportFormat* m_format = nullptr;
    std::atomic<float> m_progress{0.0f};
    std::atomic<bool> m_cancel{false};
    std::atomic<bool> m_done{false};
    exporting::ExportResult m_result;
    std::thread m_thread;
};

// The frames first..last (inclusive) of `cache` as a cache of their own.
sim::FrameCache sliceFrames(const sim::FrameCache& cache, std::size_t first, std::size_t last);

}  // namespace throng::editor
