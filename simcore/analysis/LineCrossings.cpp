#include "simcore/analysis/LineCrossings.h"

#include "simcore/analysis/RecordedPositions.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace throng::sim {

namespace {

// The step p -> q crosses the line a-b: the two ends lie on different sides (a point on
// the line counts on the forward side, so a walker standing on it crosses once), and the
// step meets the line between its ends.
int crossingSign(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p, glm::dvec2 q)
{
    const glm::dvec2 n(b.y - a.y, a.x - b.x);
    const double dp = glm::dot(n, p - a), dq = glm::dot(n, q - a);
    const bool before = dp >= 0.0, after = dq >= 0.0;
    if (before == after)
        return 0;
    const double t = dp / (dp - dq);
    const glm::dvec2 hit = p + (q - p) * t;
    const glm::dvec2 ab = b - a;
    const double along = glm::dot(hit - a, ab) / glm::dot(ab, ab);
    if (along < 0.0 || along > 1.0)
        return 0;
    return after ? 1 : -1;
}

}  // namespace

std::vector<LineFlow> countLineCrossings(const Scene& scene, const FrameCache& cache, StopFlag stop)
{
    std::vector<LineFlow> flows;
    std::vector<const Measurement*> lines;
    for (const Measurement& m : scene.measurements)
        if (m.shape == MeasurementShape::Line && m.points.size() == 2) {
            LineFlow flow;
            flow.name = m.name;
            flow.lengthM = glm::length(m.points[1] - m.points[0]);
            flows.push_back(std::move(flow));
            lines.push_back(&m);
        }
    if (lines.empty())
        return flows;
    const WalkerTypes walker(scene);
    for (std::size_t f = 1; f < cache.frameCount() && !stopRequested(stop); ++f) {
        const std::vector<AgentInfo>& agents = cache.agentsAt(f);
        for (std::size_t i = 0; i < cache.agentCount(); ++i) {
            const AgentFrame& before = cache.at(f - 1, i);
            if (!inShot(before) || !cache.at(f, i).present || !walker(agents, i))
                continue;
            const glm::dvec2 p = groundPosition(cache, f - 1, i), q = groundPosition(cache, f, i);
            for (std::size_t l = 0; l < lines.size(); ++l) {
                const int sign = crossingSign(glm::dvec2(lines[l]->points[0]), glm::dvec2(lines[l]->points[1]), p, q);
                if (sign == 0)
                    continue;
                flows[l].crossings.push_back({f, std::uint32_t(i), sign > 0});
                ++(sign > 0 ? flows[l].forward : flows[l].backward);
            }
        }
    }
    return flows;
}

std::vector<double> flowPerSecond(const LineFlow& line, float fps, std::size_t frameCount, double binS)
{
    if (fps <= 0.0f || binS <= 0.0 || frameCount == 0)
        return {};
    const double lengthS = double(frameCount) / double(fps);
    std::vector<double> bins(std::size_t(std::ceil(lengthS / binS - 1e-9)), 0.0);
    for (const LineCrossing& c : line.crossings) {
        const std::size_t k = std::size_t(double(c.frame) / double(fps) / binS);
        if (k < bins.size())
            bins[k] += 1.0;
    }
    for (double& b : bins)
        b /= binS;
    return bins;
}

}  // namespace throng::sim
