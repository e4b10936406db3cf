#include "editor/exporting/ExportJob.h"

#include "export/GltfExporter.h"
#include "export/TrajectoryCsv.h"

#include <algorithm>

namespace throng::editor {

sim::FrameCache sliceFrames(const sim::FrameCache& cache, std::size_t first, std::size_t last)
{
    sim::FrameCache out;
    out.reset(cache.agents(), cache.fps());
    const std::size_t end = std::min(last + 1, cache.frameCount());
    for (std::size_t f = first; f < end; ++f)
        out.append(cache.frame(f));
    return out;
}

ExportJob::ExportJob(const sim::Scene& scene, const sim::FrameCache& cache, ExportRequest request)
{
    sim::FrameCache frames = sliceFrames(cache, request.firstFrame, request.lastFrame);
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

void ExportJob::run(sim::Scene scene, sim::FrameCache frames, ExportRequest request)
{
    const exporting::ProgressFn progress = [this](float fraction) {
        m_progress = fraction;
        return !m_cancel.load();
    };
    if (request.format == ExportFormat::TrajectoryCsv) {
        m_result = exporting::writeTrajectoryCsv(frames, request.path, progress);
    } else {
        exporting::GltfOptions options;
        options.path = request.path;
        options.prettyJson = request.prettyJson;
        m_result = exporting::exportGltf(scene, frames, options, progress);
    }
    m_progress = 1.0f;
    m_done = true;
}

}  // namespace throng::editor
