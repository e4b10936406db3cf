#include "simcore/analysis/DensityMap.h"

#include "simcore/analysis/RecordedPositions.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace throng::sim {

double DensityMap::totalPersons() const
{
    return std::accumulate(persons.begin(), persons.end(), 0.0);
}

double DensityMap::peakDensity() const
{
    double peak = 0.0;
    for (double p : persons)
        peak = std::max(peak, p);
    return peak / (cellM * cellM);
}

DensityMap densityMap(const Scene& scene, const FrameCache& cache, double cellM, std::size_t firstFrame,
                      std::size_t lastFrame, std::size_t maxCells, StopFlag stop)
{
    DensityMap map;
    const glm::dvec2 lo(scene.settings.boundsMin), hi(scene.settings.boundsMax);
    const glm::dvec2 size = glm::max(hi - lo, glm::dvec2(1e-6));
    map.min = lo;
    map.cellM = cellM > 0.0 ? cellM : 1.0;
    // Coarser cells where the bounds hold too many: the heatmap is a picture, not a grid to
    // simulate on.
    while (std::ceil(size.x / map.cellM) * std::ceil(size.y / map.cellM) > double(std::max<std::size_t>(maxCells, 1)))
        map.cellM *= 2.0;
    map.cols = std::size_t(std::ceil(size.x / map.cellM));
    map.rows = std::size_t(std::ceil(size.y / map.cellM));
    map.persons.assign(map.cols * map.rows, 0.0);
    lastFrame = std::min(lastFrame, cache.frameCount());
    if (firstFrame >= lastFrame)
        return map;
    std::vector<std::uint64_t> counts(map.persons.size(), 0);
    std::uint64_t outside = 0;
    const WalkerTypes walker(scene);
    for (std::size_t f = firstFrame; f < lastFrame; ++f) {
        if (stopRequested(stop)) {
            lastFrame = std::max(f, firstFrame + 1);
            break;
        }
        const std::vector<AgentInfo>& agents = cache.agentsAt(f);
        for (std::size_t i = 0; i < cache.agentCount(); ++i) {
            if (!inShot(cache.at(f, i)) || !walker(agents, i))
                continue;
            const glm::dvec2 p = groundPosition(cache, f, i);
            const double cx = std::floor((p.x - lo.x) / map.cellM), cz = std::floor((p.y - lo.y) / map.cellM);
            if (cx < 0.0 || cz < 0.0 || cx >= double(map.cols) || cz >= double(map.rows)) {
                ++outside;
                continue;
            }
            ++counts[std::size_t(cz) * map.cols + std::size_t(cx)];
        }
    }
    map.frames = lastFrame - firstFrame;
    for (std::size_t c = 0; c < counts.size(); ++c)
        map.persons[c] = double(counts[c]) / double(map.frames);
    map.outsidePersons = double(outside) / double(map.frames);
    return map;
}

}  // namespace throng::sim
