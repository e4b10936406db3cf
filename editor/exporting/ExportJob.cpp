#include "editor/exporting/ExportJob.h"

#include "simcore/layout/LayoutApply.h"

#include <algorithm>

namespace throng::editor {

sim::FrameCache sliceFrames(const sim::FrameCache& cache, std::size_t first, std::size_t last)
{
    sim::FrameCache out;
    out.reset(cache.agents(), cache.fps(), cache.origin());  // a far scene's frames stay relative to it
    const std::size_t end = std::min(last + 1, cache.frameCount());
    for (std::size_t f = first; f < end; ++f)
        out.append(cache.frame(f));
    return out;
}

ExportJob::ExportJob(const sim::Scene& scene, const sim::FrameCache& cache, ExportJobRequest request)
    : m_format(request.format)
{
    // The layout layer edits what is exported (its frames are the recording's: applied
    // before the range is cut out).
    sim::FrameCache frames = scene.layout.ops.empty()
                                 ? sliceFrames(cache, request.firstFrame, request.lastFrame)
                                 : sliceFrames(sim::applyLayout(scene, cache), request.firstFrame, request.lastFrame);
    m_thread = std::thread([this, scene, frames = std::move(frames), request]() mutable {
        run(std::move(scene), std::move(frames), std::move(request));
    });
}

ExportJob::~ExportJob()
{
    m_cancel = true;
    if (m_thread.joinable())
        m_thread.join();
}

void ExportJob::run(sim::Scene scene, sim::FrameCache frames, ExportJobRequest request)
{
    const exporting::ProgressFn progress = [this](float fraction) {
        m_progress = fraction;
        return !m_cancel.load();
    };
    m_result = request.format->write(scene, frames, request.output, progress);
    m_progress = 1.0f;
    m_done = true;
}

}  // namespace throng::editor
