#include "simcore/analysis/SpeedDensity.h"

#include "simcore/analysis/RecordedPositions.h"
#include "simcore/scene/GroundPolygon.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace throng::sim {

std::vector<AreaSpeedDensity> measureSpeedDensity(const Scene& scene, const FrameCache& cache, std::size_t everyFrames,
                                                  StopFlag stop)
{
    std::vector<AreaSpeedDensity> out;
    everyFrames = std::max<std::size_t>(everyFrames, 1);
    const WalkerTypes walker(scene);
    for (const Measurement& m : scene.measurements) {
        if (m.shape != MeasurementShape::Area || m.points.size() < 3)
            continue;
        AreaSpeedDensity series;
        series.name = m.name;
        series.areaM2 = polygonArea(m.points);
        glm::dvec2 lo(m.points[0]), hi(m.points[0]);
        for (const glm::vec2& c : m.points) {
            lo = glm::min(lo, glm::dvec2(c));
            hi = glm::max(hi, glm::dvec2(c));
        }
        for (std::size_t f = 0; f < cache.frameCount() && series.areaM2 > 0.0 && !stopRequested(stop);
             f += everyFrames) {
            std::uint32_t walkers = 0;
            double speed = 0.0;
            const std::vector<AgentInfo>& agents = cache.agentsAt(f);
            for (std::size_t i = 0; i < cache.agentCount(); ++i) {
                const AgentFrame& a = cache.at(f, i);
                if (!inShot(a) || !walker(agents, i))
                    continue;
                const glm::dvec2 p = groundPosition(cache, f, i);
                if (p.x < lo.x || p.y < lo.y || p.x > hi.x || p.y > hi.y ||
                    !polygonContains(m.points, glm::vec2(p)))
                    continue;
                ++walkers;
                speed += double(a.speed);
            }
            if (walkers > 0)
                series.samples.push_back({f, double(walkers) / series.areaM2, speed / double(walkers), walkers});
        }
        out.push_back(std::move(series));
    }
    return out;
}

double weidmannSpeed(double densityPerM2)
{
    constexpr double kFreeSpeed = 1.34, kGamma = 1.913, kJam = 5.4;
    if (densityPerM2 <= 0.0)
        return kFreeSpeed;
    if (densityPerM2 >= kJam)
        return 0.0;
    return kFreeSpeed * (1.0 - std::exp(-kGamma * (1.0 / densityPerM2 - 1.0 / kJam)));
}

}  // namespace throng::sim
