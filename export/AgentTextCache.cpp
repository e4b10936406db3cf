#include "export/AgentTextCache.h"

#include "export/detail/StagingDirectory.h"
#include "export/detail/TextFields.h"

#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace throng::exporting {

namespace {

std::string agentFileName(sim::AgentId id) { return "agent_" + std::to_string(id) + ".txt"; }

// The frames agent `agent`'s file holds: from where an edit added it to where it left or an
// edit removed it ([first, end)).
std::pair<std::size_t, std::size_t> framesOf(const sim::FrameCache& cache, std::size_t agent)
{
    std::size_t first = 0;
    while (first < cache.frameCount() && !cache.at(first, agent).present)
        ++first;
    std::size_t end = first;
    while (end < cache.frameCount() && cache.at(end, agent).present && !cache.at(end, agent).out)
        ++end;
    return {first, end};
}

bool writeAgentFile(const sim::FrameCache& cache, std::size_t agent, const std::string& path, float rotYOffsetDeg)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out)
        return false;
    std::string text;
    text.reserve(cache.frameCount() * 48);
    const glm::dvec3 origin = cache.origin();
    // Starts where an edit added it (a first line names that frame), ends where it left
    // or where an edit removed it (present before, not now).
    const auto [first, end] = framesOf(cache, agent);
    if (first > 0 && first < cache.frameCount())
        text += "# first_frame " + std::to_string(first) + "\n";
    for (std::size_t f = first; f < end; ++f) {
        const sim::AgentFrame& a = cache.at(f, agent);
        detail::appendCoordinate(text, a.position.x, origin.x);
        text += ' ';
        detail::appendCoordinate(text, a.position.y, origin.y);
        text += ' ';
        detail::appendCoordinate(text, a.position.z, origin.z);
        text += ' ';
        detail::appendFloat(text, detail::headingDegrees(a.headingRad) + rotYOffsetDeg);
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

// The manifest (AgentCacheOptions::manifest): `key value` lines a script reads, then a line
// per agent: `agent <id> <file> <first frame> <frames>`.
bool writeManifest(const sim::FrameCache& cache, const std::string& path, ForwardAxis forward)
{
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out)
        return false;
    std::string text = "# Throng per-agent cache: one file per agent, a line per frame: x y z rotY speed clip\n"
                       "# (metres, degrees about +Y, m/s). An agent's lines start at its first frame.\n";
    text += "fps ";
    detail::appendFloat(text, cache.fps());
    text += "\nframes " + std::to_string(cache.frameCount()) + "\n";
    text += std::string("forward ") + (forward == ForwardAxis::PlusZ ? "+z" : "+x") + "\n";
    text += "unit m\nup +y\n";
    text += "agents " + std::to_string(cache.agents().size()) + "\n";
    for (std::size_t i = 0; i < cache.agents().size(); ++i) {
        const auto [first, end] = framesOf(cache, i);
        text += "agent " + std::to_string(cache.agents()[i].id) + " " + agentFileName(cache.agents()[i].id) + " " +
                std::to_string(first) + " " + std::to_string(end > first ? end - first : 0) + "\n";
    }
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();
    return !out.fail();
}

ExportResult stageAndPublish(const sim::FrameCache& cache, const std::string& directory, const ProgressFn& progress,
                             const AgentCacheOptions& options)
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
    const float rotYOffsetDeg = options.forward == ForwardAxis::PlusZ ? 90.0f : 0.0f;
    std::vector<std::string> names;
    for (const sim::AgentInfo& agent : agents)
        names.push_back(agentFileName(agent.id));
    // Write every file before publishing any: a cancel or a full disk leaves the
    // directory exactly as it was.
    for (std::size_t i = 0; i < agents.size(); ++i) {
        if (progress && !progress(0.9f * static_cast<float>(i) / static_cast<float>(agents.size())))
            return cancelled();
        const std::string& name = names[i];
        if (!writeAgentFile(cache, i, staging.filePath(name), rotYOffsetDeg)) {
            result.error = "could not write all of '" + (fs::path(directory) / name).string() + "' (disk full?)";
            return result;
        }
    }
    if (options.manifest) {
        names.push_back(kAgentCacheManifest);
        if (!writeManifest(cache, staging.filePath(names.back()), options.forward)) {
            result.error = "could not write all of '" + (fs::path(directory) / names.back()).string() + "' (disk full?)";
            return result;
        }
    }
    if (progress && !progress(0.9f))
        return cancelled();
    if (!staging.syncToDisk()) {
        result.error = staging.error();
        return result;
    }
    for (const std::string& name : names) {
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
                                 const ProgressFn& progress, const AgentCacheOptions& options)
{
    namespace fs = std::filesystem;
    std::error_code ec;
    const bool createdDirectory = fs::create_directories(directory, ec);
    if (ec || !fs::is_directory(directory, ec)) {
        ExportResult result;
        result.error = "cannot create directory '" + directory + "'" + (ec ? ": " + ec.message() : "");
        return result;
    }
    ExportResult result = stageAndPublish(cache, directory, progress, options);
    if (!result.ok() && createdDirectory)
        fs::remove(directory, ec);  // removes it only while it is still empty
    if (result.ok() && progress)
        progress(1.0f);
    return result;
}

}  // namespace throng::exporting
