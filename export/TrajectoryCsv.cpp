#include "export/TrajectoryCsv.h"

#include "simcore/base/AtomicFile.h"
#include "export/detail/ExportCancel.h"
#include "export/detail/TextFields.h"

namespace throng::exporting {

namespace {

void appendRow(std::string& out, std::size_t frame, sim::AgentId id, const sim::AgentFrame& a,
               glm::dvec3 origin)
{
    detail::appendUnsigned(out, frame);
    out += ',';
    detail::appendUnsigned(out, id);
    out += ',';
    detail::appendCoordinate(out, a.position.x, origin.x);
    out += ',';
    detail::appendCoordinate(out, a.position.y, origin.y);
    out += ',';
    detail::appendCoordinate(out, a.position.z, origin.z);
    out += ',';
    detail::appendFloat(out, detail::headingDegrees(a.headingRad));
    out += ',';
    detail::appendFloat(out, a.speed);
    out += ',';
    out += sim::toString(a.clip);
    out += ',';
    detail::appendFloat(out, a.phase);
    out += '\n';
}

}  // namespace

ExportResult writeTrajectoryCsv(const sim::FrameCache& cache, const std::string& path, const ProgressFn& progress)
{
    ExportResult result;
    sim::AtomicFile file(path);
    if (!file.open()) {
        result.error = file.error();
        return result;
    }
    std::string text = "frame,agent,x,y,z,heading,speed,clip,phase\n";
    text.reserve(detail::kFlushBytes + 256);
    const std::size_t frames = cache.frameCount();
    const auto& agents = cache.agents();
    for (std::size_t f = 0; f < frames; ++f) {
        if (detail::cancelledAt(progress, static_cast<float>(f) / static_cast<float>(frames)))
            return detail::cancelledExport(path);
        for (std::size_t i = 0; i < agents.size(); ++i) {
            if (cache.at(f, i).out || !cache.at(f, i).present)
                continue;  // left, or not there on this frame (an edit added or removed it)
            appendRow(text, f, agents[i].id, cache.at(f, i), cache.origin());
            if (text.size() >= detail::kFlushBytes) {
                file.stream().write(text.data(), static_cast<std::streamsize>(text.size()));
                text.clear();
            }
        }
    }
    file.stream().write(text.data(), static_cast<std::streamsize>(text.size()));
    if (!file.commit()) {
        result.error = file.error();
        return result;
    }
    result.writtenPaths.push_back(path);
    if (progress)
        progress(1.0f);
    return result;
}

}  // namespace throng::exporting
