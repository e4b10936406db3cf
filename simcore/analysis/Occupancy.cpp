#include "simcore/analysis/Occupancy.h"

#include "simcore/analysis/RecordedPositions.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>

namespace throng::sim {

namespace {

struct ExitPlace {
    glm::dvec2 position{0.0};
    double radiusM = 0.0;
};

// The exit an agent that left on a frame stood at: the exit goal or exit path end whose
// area it is nearest to entering (it is inside one, or within a step of it).
std::size_t nearestExit(const std::vector<ExitPlace>& places, glm::dvec2 p)
{
    std::size_t best = 0;
    double bestGap = std::numeric_limits<double>::max();
    for (std::size_t e = 0; e < places.size(); ++e) {
        const double gap = glm::length(p - places[e].position) - places[e].radiusM;
        if (gap < bestGap) {
            bestGap = gap;
            best = e;
        }
    }
    return best;
}

}  // namespace

Occupancy measureOccupancy(const Scene& scene, const FrameCache& cache, StopFlag stop)
{
    Occupancy o;
    std::vector<ExitPlace> places;
    for (const Goal& g : scene.goals)
        if (g.exit) {
            o.exits.push_back({g.name, {}});
            places.push_back({glm::dvec2(g.position), double(g.radiusM)});
        }
    for (const Path& p : scene.paths)
        if (p.exit && !p.closed && !p.points.empty()) {
            o.exits.push_back({p.name, {}});
            places.push_back({glm::dvec2(p.points.back()), double(p.radiusM)});
        }
    std::size_t frames = cache.frameCount();
    o.inScene.assign(frames, 0);
    o.out.assign(frames, 0);
    for (std::size_t f = 0; f < frames; ++f) {
        if (stopRequested(stop)) {
            frames = f;
            o.inScene.resize(f);
            o.out.resize(f);
            break;
        }
        for (std::size_t i = 0; i < cache.agentCount(); ++i) {
            const AgentFrame& a = cache.at(f, i);
            if (!a.present)
                continue;
            if (!a.out) {
                ++o.inScene[f];
                continue;
            }
            ++o.out[f];
            const bool leftNow = f == 0 || !cache.at(f - 1, i).out || !cache.at(f - 1, i).present;
            if (leftNow && !places.empty())
                o.exits[nearestExit(places, groundPosition(cache, f, i))].frames.push_back(f);
        }
    }
    for (std::uint32_t n : o.inScene)
        o.peakInScene = std::max<std::uint64_t>(o.peakInScene, n);
    if (frames > 0 && o.inScene.back() == 0 && o.out.back() > 0) {
        std::size_t f = frames;
        while (f > 0 && o.inScene[f - 1] == 0)
            --f;
        o.evacuationS = double(f) / double(cache.fps());
    }
    return o;
}

}  // namespace throng::sim
