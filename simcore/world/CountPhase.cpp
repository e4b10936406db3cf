// CountPhase: the step's quality figures (StepCounters.h) on the positions it ended at.
#include "simcore/world/CountPhase.h"

#include "simcore/traffic/LightPhase.h"
#include "simcore/world/LocalDensity.h"
#include "simcore/world/detail/StepGeometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <mutex>

namespace throng::sim {

using namespace detail;

namespace {
// The density sum's unit: 2^-40 of a person per square metre, far below a float's
// rounding at any density, and 2^23 persons per square metre before it overflows.
constexpr double kDensityFixedPoint = 1099511627776.0;
}  // namespace

int StepView::lightState(std::size_t light) const
{
    return int(lightPhaseAt(set.lights[light], clock.timeS()));
}

void CountPhase::count(const StepView& v, std::vector<std::uint8_t>& onCrosswalk, std::uint64_t nonFinite)
{
    const std::size_t n = v.agents.size();
    const std::uint64_t overlaps = overlappingPairs(v, nonFinite);
    m_counters.overlappingPairs += overlaps;
    m_counters.nonFiniteValues += nonFinite;
    m_counters.agentSteps += n;
    if (v.allFliers)
        return;
    if (densitySampleDue(v.clock.step, double(v.clock.dt)))
        samplePeakDensity(v);
    countGround(v, onCrosswalk);
    countLeaderOvertakes(v);
}

std::uint64_t CountPhase::overlappingPairs(const StepView& v, std::uint64_t nonFinite)
{
    const std::size_t n = v.agents.size();
    // Overlapping pairs in the grid's order when it holds every agent: each close pair is
    // met once, from the earlier of the two (NeighbourGrid::forEachLaterNear), and the
    // positions are read in the grid's copy, near each other in memory. A position that
    // is not a number breaks the order by height, so then they are counted by index.
    // Each chunk tallies its pairs' depths; the few chunks that found any add them in
    // (integer counts and a maximum: the same total in any order).
    const bool inGridOrder = v.grid.order().size() == n;
    std::mutex depthsLock;
    auto tally = [&](const OverlapDepths& local, std::uint64_t count) {
        if (count > 0) {
            const std::lock_guard<std::mutex> lock(depthsLock);
            m_counters.overlapDepths.add(local);
        }
        return count;
    };
    if (inGridOrder && nonFinite == 0) {
        const std::size_t run = std::max<std::size_t>(1024, n / (std::size_t(v.team.size()) * 16));
        return v.team.sumChunks(n, run, [&](std::size_t begin, std::size_t end, int) {
            OverlapDepths local;
            return tally(local, laterOverlaps(v, begin, end, local));
        });
    }
    return v.team.sumChunks(n, 1024, [&](std::size_t begin, std::size_t end, int) {
        OverlapDepths local;
        std::uint64_t count = 0;
        for (std::size_t i = begin; i < end; ++i)
            count += v.agents.out[i] ? 0 : overlapsAfter(v, i, local);  // out: left through an exit
        return tally(local, count);
    });
}

void CountPhase::countGround(const StepView& v, std::vector<std::uint8_t>& onCrosswalk)
{
    const AgentColumns& a = v.agents;
    const StaticSet& set = v.set;
    // Nothing to stand in or step onto (an open field like `cross`): no agent's flag can
    // be set, so all are as they were, clear.
    if (set.circles.empty() && set.boxes.empty() && set.crosswalks.empty())
        return;
    std::atomic<std::uint64_t> inObstacleAll{0}, redAll{0};
    v.team.forChunks(a.size(), 1024, [&](std::size_t begin, std::size_t end, int) {
        std::uint64_t inObstacle = 0, red = 0;
        for (std::size_t i = begin; i < end; ++i) {
            if (a.out[i])
                continue;  // left through an exit: no longer in the scene
            const glm::vec2 p = xz(a.pos[i]);
            const float r = a.radius[i];
            const AgentKind kind = v.type(i).kind;
            if (kind == AgentKind::Flier)
                continue;
            // In an obstacle: the body reaches more than the tolerance into a circle or a box
            // (boxes are walls too, but an agent inside one crosses none of them).
            set.obstacleGrid.forEachNear(p, r, [&](std::uint32_t k) {
                if (k < set.circles.size()) {
                    if (glm::distance(p, xz(set.circles[k].centre)) < set.circles[k].radius + r - kOverlapToleranceM)
                        ++inObstacle;
                    return;
                }
                const BoxObstacle& b = set.boxes[k - set.circles.size()];
                const glm::vec2 d = p - xz(b.centre), ax(b.axis.x, b.axis.z), az(-b.axis.z, b.axis.x);
                const glm::vec2 outside =
                    glm::max(glm::abs(glm::vec2(glm::dot(d, ax), glm::dot(d, az))) - b.halfSize, 0.0f);
                if (glm::length(outside) < r - kOverlapToleranceM)
                    ++inObstacle;
            });
            // A pedestrian (a hero too: it goes where its keyframes say) steps onto the road on
            // red: its centre is on a controlled crosswalk's road part (LaneNetwork::onRoadPart:
            // inside the strip and on a lane's carriageway) at the end of this step and was not
            // at the end of the last. Over no lanes the whole strip is road.
            std::uint8_t on = 0;
            int light = -1;
            if (kind == AgentKind::Pedestrian)
                for (std::size_t k = 0; k < set.crosswalks.size(); ++k) {
                    const CrosswalkBox& c = set.crosswalks[k];
                    const glm::vec2 ab = c.b - c.a;
                    const float len = glm::length(ab);
                    const float along = glm::dot(p - c.a, ab) / len;
                    const float across = std::fabs(cross(ab, p - c.a)) / len;
                    const bool inStrip = along > 0.0f && along < len && across < c.halfWidth;
                    if (inStrip && (!v.traffic.system || v.traffic.system->lanes().onRoadPart(int(k), p))) {
                        on = 1;
                        light = c.light;
                    }
                }
            if (on && !onCrosswalk[i] && light >= 0 && v.lightState(std::size_t(light)) == 2)
                ++red;
            onCrosswalk[i] = on;
        }
        inObstacleAll.fetch_add(inObstacle, std::memory_order_relaxed);
        redAll.fetch_add(red, std::memory_order_relaxed);
    });
    m_counters.obstaclePenetrations += inObstacleAll.load();
    m_counters.redLightViolations += redAll.load();
}

void CountPhase::samplePeakDensity(const StepView& v)
{
    // The highest density at any pedestrian's centre (in the scene: not out through an
    // exit), in this step's positions; a chunk's peak, and the peak of those, is the same
    // for any cut of the work.
    const AgentColumns& a = v.agents;
    std::mutex lock;
    float peak = 0.0f;
    v.team.forChunks(a.size(), 1024, [&](std::size_t begin, std::size_t end, int) {
        float local = 0.0f;
        for (std::size_t i = begin; i < end; ++i) {
            if (a.out[i] || v.type(i).kind != AgentKind::Pedestrian)
                continue;
            const glm::vec2 p = xz(a.pos[i]);
            // Summed in fixed point, which is exact: the same total in whatever order the
            // grid offers the neighbours (its cells change size with the crowd).
            std::int64_t density = 0;
            v.grid.forEachNear(p, kDensityReachM, [&](std::uint32_t j, const glm::vec3& q) {
                if (v.type(j).kind != AgentKind::Pedestrian)
                    return;
                const glm::vec2 d = xz(q) - p;
                density += std::int64_t(densityWeight(glm::dot(d, d)) * kDensityFixedPoint);
            });
            local = std::max(local, float(double(density) / double(kDensityFixedPoint)));
        }
        const std::lock_guard<std::mutex> guard(lock);
        peak = std::max(peak, local);
    });
    if (peak > m_counters.peakDensity) {
        m_counters.peakDensity = peak;
        m_counters.peakDensityTimeS = v.clock.timeS();
    }
}

bool CountPhase::overlapping(const StepView& v, std::size_t i, glm::vec3 p, std::uint32_t j, glm::vec3 q,
                             OverlapDepths& depths)
{
    if (v.types.makingWay && !collide(v.collision(i), v.collision(j)))
        return false;  // layers that do not collide may overlap
    if (v.traffic.anyOffStage && (v.traffic.offStage[i] | v.traffic.offStage[j]))
        return false;  // off stage: waiting at its lane's end with others that left it
    const float touch = v.agents.radius[i] + v.agents.radius[j], contact = touch - kOverlapToleranceM;
    const glm::vec3 d = p - q;
    const float d2 = glm::dot(d, d);
    if (!(d2 < contact * contact))
        return false;
    depths.add((touch - std::sqrt(d2)) / touch);
    return true;
}

std::uint64_t CountPhase::overlapsAfter(const StepView& v, std::size_t i, OverlapDepths& depths)
{
    std::uint64_t count = 0;
    const glm::vec3 p = v.agents.pos[i];
    auto overlap = [&](std::uint32_t j, const glm::vec3& q) { count += j > i && overlapping(v, i, p, j, q, depths); };
    const float reach = v.agents.radius[i] + v.maxRadius;
    if (v.hasFliers)
        v.grid.forEachNear3D(p, reach, overlap);
    else
        v.grid.forEachNear(xz(p), reach, overlap);
    return count;
}

std::uint64_t CountPhase::laterOverlaps(const StepView& v, std::size_t begin, std::size_t end, OverlapDepths& depths)
{
    const std::span<const std::uint32_t> order = v.grid.order();
    std::uint64_t count = 0;
    auto reach = [&](std::size_t k) { return v.agents.radius[order[k]] + v.maxRadius; };
    auto overlap = [&](std::size_t k, std::uint32_t j, const glm::vec3& q) {
        count += overlapping(v, order[k], v.grid.orderedPosition(k), j, q, depths);
    };
    if (v.grid.forEachLaterNearRun(begin, end, 2.0f * v.maxRadius, reach, overlap))
        return count;
    for (std::size_t k = begin; k < end; ++k)
        v.grid.forEachLaterNear(k, reach(k), [&](std::uint32_t j, const glm::vec3& q) { overlap(k, j, q); });
    return count;
}

}  // namespace throng::sim
