#include "export/AgentTextCache.h"

#include "export/detail/StagingDirectory.h"
#include "export/detail/TextFields.h"

#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace throng::exporting {

namespace {

std::string agentFileName(sim::AgentId id) { return "agent_" + std::to_string(id) + ".txt"; }

bool writeAgentFile(const sim::FrameCache& cache, std::size_t agent, const std::string& path)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out)
        return false;
    std::string text;
    text.reserve(cache.frameCount() * 48);
    const glm::dvec3 origin = cache.origin();
    // Starts where an edit added it (a first line names that frame), ends where it left
    // or where an edit removed it (present before, not now).
    std::size_t first = 0;
    while (first < cache.frameCount() && !cache.at(first, agent).present)
        ++first;
    if (first > 0 && first < cache.frameCount())
        text += "# first_frame " + std::to_string(first) + "\n";
    for (std::size_t f = first; f < cache.frameCount() && !cache.at(f, agent).out; ++f) {
        const sim::AgentFrame& a = cache.at(f, agent);
        if (!a.present)
            break;
        detail::appendCoordinate(text, a.position.x, origin.x);
        text += ' ';
        detail::appendCoordinate(text, a.position.y, origin.y);
        text += ' ';
        detail::appendCoordinate(text, a.position.z, origin.z);
        text += ' ';
        detail::appendFloat(text, detail::headingDegrees(a.headingRad));
        text += ' ';
        detail::appendFloat(text, a.speed);
        text += ' ';
        text += sim::toString(a.clip);
        text += '\n';
    }
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();
    return !out.fail();
}

ExportResult stageAndPublish(const sim::FrameCache& cache, const std::string& directory, const ProgressFn& progress)
{
    namespace fs = std::filesystem;
    ExportResult result;
    auto cancelled = [&] {
        result.cancelled = true;
        result.error = "export to '" + directory + "' cancelled";
        return result;
    };
    detail::StagingDirectory staging((fs::path(directory) / "agents").string());
    if (!staging.create()) {
        result.error = staging.error();
        return result;
    }
    const auto& agents = cache.agents();
    // Write every file before publishing any: a cancel or a full disk leaves the
    // directory exactly as it was.
    for (std::size_t i = 0; i < agents.size(); ++i) {
        if (progress && !progress(0.9f * static_cast<float>(i) / static_cast<float>(agents.size())))
            return cancelled();
        const std::string name = agentFileName(agents[i].id);
        if (!writeAgentFile(cache, i, staging.filePath(name))) {
            result.error = "could not write all of '" + (fs::path(directory) / name).string() + "' (disk full?)";
            return result;
        }
    }
    if (progress && !progress(0.9f))
        return cancelled();
    if (!staging.syncToDisk()) {
        result.error = staging.error();
        return result;
    }
    for (const sim::AgentInfo& agent : agents) {
        const std::string name = agentFileName(agent.id);
        const std::string target = (fs::path(directory) / name).string();
        if (!staging.publish(name, target)) {
            result.error = staging.error();
            result.writtenPaths.clear();
            return result;
        }
        result.writtenPaths.push_back(target);
    }
    return result;
}

}  // namespace

ExportResult writeAgentTextCache(const sim::FrameCache& cache, const std::string& directory,
                                 const ProgressFn& progress)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    const bool createdDirectory = fs::create_directories(directory, ec);
    if (ec || !fs::is_directory(directory, ec)) {
        ExportResult result;
        result.error = "cannot create directory '" + directory + "'" + (ec ? ": " + ec.message() : "");
        return result;
    }
    ExportResult result = stageAndPublish(cache, directory, progress);
    if (!result.ok() && createdDirectory)
        fs::remove(directory, ec);  // removes it only while it is still empty
    if (result.ok() && progress)
        progress(1.0f);
    return result;
}

}  // namespace throng::exporting
