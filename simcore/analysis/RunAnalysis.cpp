#include "simcore/analysis/RunAnalysis.h"

#include "simcore/analysis/RecordedPositions.h"

#include <algorithm>
#include <utility>

namespace throng::sim {

namespace {

std::vector<Trajectory> sampleTrajectories(const Scene& scene, const FrameCache& cache, const AnalysisOptions& options,
                                           std::size_t& walkers)
{
    const WalkerTypes walker(scene);
    std::vector<const std::vector<AgentInfo>*> agentsAt(cache.frameCount());
    for (std::size_t f = 0; f < agentsAt.size(); ++f)
        agentsAt[f] = &cache.agentsAt(f);
    auto isWalker = [&](std::size_t f, std::size_t i) { return walker(*agentsAt[f], i); };
    std::vector<std::uint32_t> seen;
    for (std::size_t i = 0; i < cache.agentCount(); ++i)
        for (std::size_t f = 0; f < cache.frameCount(); ++f)
            if (inShot(cache.at(f, i)) && isWalker(f, i)) {
                seen.push_back(std::uint32_t(i));
                break;
            }
    walkers = seen.size();
    std::vector<Trajectory> out;
    const std::size_t take = std::min(seen.size(), std::max<std::size_t>(options.maxTrajectories, 1));
    const std::size_t frames = cache.frameCount();
    const std::size_t stride = std::max<std::size_t>(1, frames / std::max<std::size_t>(options.maxTrajectoryPoints, 2));
    for (std::size_t k = 0; k < take; ++k) {
        const std::uint32_t agent = seen[k * seen.size() / take];
        Trajectory t{agent, {}};
        for (std::size_t f = 0; f < frames; ++f) {
            const bool here = inShot(cache.at(f, agent)) && isWalker(f, agent);
            if (!here) {
                if (!t.points.empty())
                    out.push_back(std::exchange(t, Trajectory{agent, {}}));
                continue;
            }
            const bool last = f + 1 == frames || !inShot(cache.at(f + 1, agent));
            if (f % stride == 0 || last || t.points.empty())
                t.points.push_back(groundPosition(cache, f, agent));
        }
        if (!t.points.empty())
            out.push_back(std::move(t));
    }
    return out;
}

}  // namespace

RunAnalysis analyseRun(const Scene& scene, const FrameCache& cache, const AnalysisOptions& options)
{
    RunAnalysis a;
    a.fps = cache.fps();
    a.frames = cache.frameCount();
    a.durationS = a.frames > 0 ? double(a.frames - 1) / double(a.fps) : 0.0;
    a.boundsMin = glm::dvec2(scene.settings.boundsMin);
    a.boundsMax = glm::dvec2(scene.settings.boundsMax);
    a.trajectories = sampleTrajectories(scene, cache, options, a.walkers);
    a.density = densityMap(scene, cache, options.densityCellM, 0, a.frames);
    a.speedDensity = measureSpeedDensity(scene, cache, 1);
    a.lines = countLineCrossings(scene, cache);
    a.flowBinS = options.flowBinS;
    if (a.flowBinS <= 0.0) {
        a.flowBinS = 10.0;
        for (double bin : {1.0, 2.0, 5.0})
            if (a.durationS / bin <= 80.0) {
                a.flowBinS = bin;
                break;
            }
    }
    for (const LineFlow& l : a.lines)
        a.lineFlowPerSecond.push_back(flowPerSecond(l, a.fps, a.frames, a.flowBinS));
    a.occupancy = measureOccupancy(scene, cache);
    return a;
}

}  // namespace throng::sim
