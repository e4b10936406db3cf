#include "export/detail/CrowdSetup.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

namespace throng::exporting::detail {

std::string checkCrowdInput(const sim::Scene& scene, const sim::FrameCache& cache, const std::string& path,
                            const std::vector<std::string_view>& suffixes, int jointFrameStep)
{
    const std::string where = "cannot export '" + path + "': ";
    if (path.empty())
        return "cannot export: no output path given";
    std::string suffix = std::filesystem::path(path).extension().string();
    std::transform(suffix.begin(), suffix.end(), suffix.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    if (!suffixes.empty() && std::find(suffixes.begin(), suffixes.end(), suffix) == suffixes.end()) {
        std::string known;
        for (const std::string_view s : suffixes)
            known += (known.empty() ? "" : " or ") + std::string(s);
        return where + "the file must end in " + known;
    }
    if (cache.agentCount() == 0 || cache.frameCount() == 0)
        return where + "nothing recorded (" + std::to_string(cache.agentCount()) + " agents, " +
               std::to_string(cache.frameCount()) + " frames)";
    if (!(cache.fps() > 0.0f) || !std::isfinite(cache.fps()))
        return where + "the frame cache's fps (" + std::to_string(cache.fps()) + ") is not > 0";
    if (jointFrameStep < 1)
        return where + "the joint frame step must be at least 1";
    for (const sim::AgentInfo& agent : cache.agents())
        if (agent.typeIndex >= scene.agentTypes.size())
            return where + "agent " + std::to_string(agent.id) + " has type index " + std::to_string(agent.typeIndex) +
                   " but the scene has " + std::to_string(scene.agentTypes.size()) + " agent types";
    return {};
}

std::string checkCrowdInput(const sim::Scene& scene, const sim::FrameCache& cache, const std::string& path,
                            const std::vector<std::string_view>& suffixes, int jointFrameStep,
                            std::initializer_list<float> tolerances)
{
    if (std::string error = checkCrowdInput(scene, cache, path, suffixes, jointFrameStep); !error.empty())
        return error;
    for (const float tolerance : tolerances)
        if (!(tolerance >= 0.0f))
            return "cannot export '" + path + "': key tolerances must be >= 0";
    return {};
}

std::vector<float> frameTimes(const sim::FrameCache& cache)
{
    std::vector<float> times(cache.frameCount());
    for (std::size_t f = 0; f < times.size(); ++f)
        times[f] = static_cast<float>(static_cast<double>(f) / static_cast<double>(cache.fps()));
    return times;
}

JointClock jointFrames(const std::vector<float>& times, int step)
{
    JointClock clock;
    for (std::size_t f = 0; f < times.size(); f += static_cast<std::size_t>(step))
        clock.frames.push_back(static_cast<std::uint32_t>(f));
    if (clock.frames.back() != times.size() - 1)
        clock.frames.push_back(static_cast<std::uint32_t>(times.size() - 1));
    for (const std::uint32_t f : clock.frames)
        clock.clock.times.push_back(times[f]);
    return clock;
}

std::string resolveCharacters(const sim::Scene& scene, const sim::FrameCache& cache, Lod lod,
                              const std::string& sceneDirectory, const std::string& path, CharacterLibrary& library)
{
    std::vector<bool> typeUsed(scene.agentTypes.size(), false);
    for (const sim::AgentInfo& agent : cache.agents())
        typeUsed[agent.typeIndex] = true;
    library.setLod(lod);
    if (std::string error = library.resolve(scene, sceneDirectory, typeUsed); !error.empty())
        return "cannot export '" + path + "': " + error;
    return {};
}

}  // namespace throng::exporting::detail
