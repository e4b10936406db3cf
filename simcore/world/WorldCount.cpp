// World::countStep: the step's quality figures (StepCounters.h) on the positions it
// ended at: overlapping pairs and their depths, bodies in obstacles, walkers stepping onto
// the road on red, and the peak local density. Each chunk of agents counts its own; the
// totals are the same for any thread count.
#include "simcore/world/World.h"

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

void World::countStep(std::uint64_t nonFinite)
{
    const std::size_t n = m_pos.size();
    std::uint64_t overlaps = 0;
    m_grid.rebuild(m_pos, m_hasFliers, m_out, &m_team);
    m_gridCurrent = true;
    // Overlapping pairs in the grid's order when it holds every agent: each close pair is
    // met once, from the earlier of the two (NeighbourGrid::forEachLaterNear), and the
    // positions are read in the grid's copy, near each other in memory. A position that
    // is not a number breaks the order by height, so then they are counted by index.
    // Each chunk tallies its pairs' depths; the few chunks that found any add them in
    // (integer counts and a maximum: the same total in any order).
    const bool inGridOrder = m_grid.order().size() == n;
    std::mutex depthsLock;
    auto tally = [&](const OverlapDepths& local, std::uint64_t count) {
        if (count > 0) {
            const std::lock_guard<std::mutex> lock(depthsLock);
            m_counters.overlapDepths.add(local);
        }
        return count;
    };
    if (inGridOrder && nonFinite == 0) {
        const std::size_t run = std::max<std::size_t>(1024, n / (std::size_t(m_team.size()) * 16));
        overlaps = m_team.sumChunks(n, run, [&](std::size_t begin, std::size_t end, int) {
            OverlapDepths local;
            return tally(local, laterOverlaps(begin, end, local));
        });
    } else {
        overlaps = m_team.sumChunks(n, 1024, [&](std::size_t begin, std::size_t end, int) {
            OverlapDepths local;
            std::uint64_t count = 0;
            for (std::size_t i = begin; i < end; ++i)
                count += m_out[i] ? 0 : overlapsAfter(i, local);  // out: left through an exit
            return tally(local, count);
        });
    }
    if (m_allFliers) {
        m_counters.overlappingPairs += overlaps;
        m_counters.nonFiniteValues += nonFinite;
        m_counters.agentSteps += n;
        return;
    }
    if (densitySampleDue(m_step, double(m_dt)))
        samplePeakDensity();
    std::atomic<std::uint64_t> inObstacleAll{0}, redAll{0};
    m_team.forChunks(n, 1024, [&](std::size_t begin, std::size_t end, int) {
        std::uint64_t inObstacle = 0, red = 0;
        for (std::size_t i = begin; i < end; ++i) {
            if (m_out[i])
                continue;  // left through an exit: no longer in the scene
            const glm::vec2 p = xz(m_pos[i]);
            const float r = m_radius[i];
            if (m_types[m_info[i].typeIndex].kind == AgentKind::Flier)
                continue;
            // In an obstacle: the body reaches more than the tolerance into a circle or a box
            // (boxes are walls too, but an agent inside one crosses none of them).
            m_obstacleGrid.forEachNear(p, r, [&](std::uint32_t k) {
                if (k < m_circles.size()) {
                    if (glm::distance(p, xz(m_circles[k].centre)) < m_circles[k].radius + r - kOverlapToleranceM)
                        ++inObstacle;
                    return;
                }
                const BoxObstacle& b = m_boxes[k - m_circles.size()];
                const glm::vec2 d = p - xz(b.centre), ax(b.axis.x, b.axis.z), az(-b.axis.z, b.axis.x);
                const glm::vec2 outside = glm::max(glm::abs(glm::vec2(glm::dot(d, ax), glm::dot(d, az))) - b.halfSize, 0.0f);
                if (glm::length(outside) < r - kOverlapToleranceM)
                    ++inObstacle;
            });
            // A pedestrian (a hero too: it goes where its keyframes say) steps onto the road on
            // red: its centre is on a controlled crosswalk's road part (LaneNetwork::onRoadPart:
            // inside the strip and on a lane's carriageway) at the end of this step and was not
            // at the end of the last. Over no lanes the whole strip is road.
            std::uint8_t on = 0;
            int light = -1;
            if (m_types[m_info[i].typeIndex].kind == AgentKind::Pedestrian)
                for (std::size_t k = 0; k < m_crosswalks.size(); ++k) {
                    const CrosswalkBox& c = m_crosswalks[k];
                    const glm::vec2 ab = c.b - c.a;
                    const float len = glm::length(ab);
                    const float along = glm::dot(p - c.a, ab) / len;
                    const float across = std::fabs(cross(ab, p - c.a)) / len;
                    const bool inStrip = along > 0.0f && along < len && across < c.halfWidth;
                    if (inStrip && (!m_traffic.system || m_traffic.system->lanes().onRoadPart(int(k), p))) {
                        on = 1;
                        light = c.light;
                    }
                }
            if (on && !m_onCrosswalk[i] && light >= 0 && lightState(std::size_t(light)) == 2)
                ++red;
            m_onCrosswalk[i] = on;
        }
        inObstacleAll.fetch_add(inObstacle, std::memory_order_relaxed);
        redAll.fetch_add(red, std::memory_order_relaxed);
    });
    m_counters.overlappingPairs += overlaps;
    m_counters.nonFiniteValues += nonFinite;
    m_counters.obstaclePenetrations += inObstacleAll.load();
    m_counters.redLightViolations += redAll.load();
    m_counters.agentSteps += n;
}

void World::samplePeakDensity()
{
    // The highest density at any pedestrian's centre (in the scene: not out through an
    // exit), in this step's positions; a chunk's peak, and the peak of those, is the same
    // for any cut of the work.
    const std::size_t n = m_pos.size();
    std::mutex lock;
    float peak = 0.0f;
    m_team.forChunks(n, 1024, [&](std::size_t begin, std::size_t end, int) {
        float local = 0.0f;
        for (std::size_t i = begin; i < end; ++i) {
            if (m_out[i] || m_types[m_info[i].typeIndex].kind != AgentKind::Pedestrian)
                continue;
            const glm::vec2 p = xz(m_pos[i]);
            float density = 0.0f;
            m_grid.forEachNear(p, kDensityReachM, [&](std::uint32_t j, const glm::vec3& q) {
                if (m_types[m_info[j].typeIndex].kind != AgentKind::Pedestrian)
                    return;
                const glm::vec2 d = xz(q) - p;
                density += densityWeight(glm::dot(d, d));
            });
            local = std::max(local, density);
        }
        const std::lock_guard<std::mutex> guard(lock);
        peak = std::max(peak, local);
    });
    if (peak > m_counters.peakDensity) {
        m_counters.peakDensity = peak;
        m_counters.peakDensityTimeS = timeS();
    }
}

bool World::overlapping(std::size_t i, glm::vec3 p, std::uint32_t j, glm::vec3 q, OverlapDepths& depths) const
{
    if (m_makingWay && !collide(collision(i), collision(j)))
        return false;  // layers that do not collide may overlap
    if (m_traffic.anyOffStage && (m_traffic.offStage[i] | m_traffic.offStage[j]))
        return false;  // off stage: waiting at its lane's end with others that left it
    const float touch = m_radius[i] + m_radius[j], contact = touch - kOverlapToleranceM;
    const glm::vec3 d = p - q;
    const float d2 = glm::dot(d, d);
    if (!(d2 < contact * contact))
        return false;
    depths.add((touch - std::sqrt(d2)) / touch);
    return true;
}

std::uint64_t World::overlapsAfter(std::size_t i, OverlapDepths& depths) const
{
    std::uint64_t count = 0;
    const glm::vec3 p = m_pos[i];
    auto overlap = [&](std::uint32_t j, const glm::vec3& q) { count += j > i && overlapping(i, p, j, q, depths); };
    const float reach = m_radius[i] + m_maxRadius;
    if (m_hasFliers)
        m_grid.forEachNear3D(p, reach, overlap);
    else
        m_grid.forEachNear(xz(p), reach, overlap);
    return count;
}

std::uint64_t World::laterOverlaps(std::size_t begin, std::size_t end, OverlapDepths& depths) const
{
    const std::span<const std::uint32_t> order = m_grid.order();
    std::uint64_t count = 0;
    auto reach = [&](std::size_t k) { return m_radius[order[k]] + m_maxRadius; };
    auto overlap = [&](std::size_t k, std::uint32_t j, const glm::vec3& q) {
        count += overlapping(order[k], m_grid.orderedPosition(k), j, q, depths);
    };
    if (m_grid.forEachLaterNearRun(begin, end, 2.0f * m_maxRadius, reach, overlap))
        return count;
    for (std::size_t k = begin; k < end; ++k)
        m_grid.forEachLaterNear(k, reach(k), [&](std::uint32_t j, const glm::vec3& q) { overlap(k, j, q); });
    return count;
}

}  // namespace throng::sim
