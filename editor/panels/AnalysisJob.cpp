#include "editor/panels/AnalysisJob.h"

#include <utility>

namespace throng::editor {

AnalysisJob::AnalysisJob(sim::Scene scene, const sim::FrameCache& cache, sim::AnalysisOptions options)
{
    m_thread = std::thread([this, scene = std::move(scene), &cache, options] {
        sim::AnalysisControl control;
        control.progress = [this](double done, const std::string&) { m_progress = done; };
        control.stop = &m_stop;
        m_result = sim::analyseRun(scene, cache, options, control);
        m_done = true;
    });
}

AnalysisJob::~AnalysisJob()
{
    stop();
}

void AnalysisJob::stop()
{
    m_stop = true;
    if (m_thread.joinable())
        m_thread.join();
}

}  // namespace throng::editor
