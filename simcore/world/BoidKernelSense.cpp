// The boids kernel's search (BoidKernel.cpp, searchBoid) for up to four consecutive boids of
// the grid's order at once. They lie in one cell at rising heights, so the same columns hold
// their neighbours: each column's window is read once for the four
// (NeighbourGrid::forEachNearestSweep4), and each candidate's squared distance to the four,
// and whether it lies in their view cones, are 4-wide sums and masks (base/Lanes.h),
// with searchBoid's operations. A candidate is then ranked only for the boids whose
// bound it lies within, exactly as searchBoid ranks it, so each boid's k nearest, and
// their order, are what searchBoid finds for it alone, and so is the result to the bit
// (TestNeighbourSweep and the flock's state hash show it).
#include "simcore/world/BoidKernel.h"

#include "simcore/world/Sense.h"

#include "simcore/base/Lanes.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>
#include <cmath>

namespace throng::sim {

using namespace simd;

void BoidPass::senseFourBoids(const std::uint32_t* boid, int count, NeighbourGrid::Sweep& sweep, BoidSense* out)
{
    constexpr int kLanes = 4;
    const float perception = m_types.params[m_agents.info[boid[0]].typeIndex].perception;
    const float perception2 = perception * perception;
    bool together = m_neighbourSweep && count > 1 && count <= kLanes;
    for (int l = 1; l < count; ++l)
        together = together && m_types.params[m_agents.info[boid[l]].typeIndex].perception == perception;
    if (!together) {
        for (int l = 0; l < count; ++l)
            senseBoid(boid[l], &sweep, out[l]);
        return;
    }
    glm::vec3 p[kLanes];
    float guess2[kLanes];
    F4 bound, fx, fy, fz, radius, cone;
    M4 self;
    BoidNearest best[kLanes];
    for (int l = 0; l < kLanes; ++l) {
        // Lanes past count copy lane 0's point, to aim the sweep, and take no candidate.
        const std::size_t i = boid[l < count ? l : 0];
        self[l] = std::int32_t(i);
        p[l] = m_agents.pos[i];
        fx[l] = m_agents.fwd[i].x;
        fy[l] = m_agents.fwd[i].y;
        fz[l] = m_agents.fwd[i].z;
        radius[l] = m_agents.radius[i];
        cone[l] = m_types.params[m_agents.info[i].typeIndex].cosHalfView;
        guess2[l] = lastNearestBound(m_agents, i, p[l], perception2);  // as senseBoid
        bound[l] = l < count ? guess2[l] : -1.0f;
    }
    const F4 px{p[0].x, p[1].x, p[2].x, p[3].x}, py{p[0].y, p[1].y, p[2].y, p[3].y},
        pz{p[0].z, p[1].z, p[2].z, p[3].z};
    // searchBoid's consider, for the lanes whose bound the candidate lies within (the same
    // test: not d2 > bound), with the view cone's test (outsideViewCone's operations) and
    // the contact distance's for all four at once; then ranked one lane at a time.
    const F4 cone2 = cone * cone;
    const bool watch = !m_ties.byIndex();  // for ties, as searchBoid
    const M4 allRound = cone <= -1.0f, coneAhead = cone >= 0.0f;
    auto consider = [&](std::uint32_t j, const glm::vec3& q) {
        const F4 dx = q.x - px, dy = q.y - py, dz = q.z - pz;
        const F4 d2 = dx * dx + dy * dy + dz * dz;  // glm::dot's order
        M4 take = ~(d2 > bound) & (self != std::int32_t(j));
        if (!any(take))
            return;
        const F4 along = dx * fx + dy * fy + dz * fz, along2 = along * along, c2d2 = cone2 * d2;
        const M4 outside =
            ~allRound & select(coneAhead, (along < 0.0f) | (along2 < c2d2), (along < 0.0f) & (along2 > c2d2));
        if (any(take & outside)) {
            const F4 contact = radius + m_agents.radius[j];
            take &= ~(outside & (d2 > contact * contact));
        }
        for (unsigned lanes = bitsOf(take); lanes != 0; lanes &= lanes - 1) {
            const int l = std::countr_zero(lanes);
            const std::uint64_t key = nearestKey(d2[l], j);
            if ((watch ? best[l].insertWatchingTies(key) : best[l].insert(key)) && best[l].full())
                bound[l] = best[l].worstDistance2();
        }
    };
    if (!m_grid.forEachNearestSweep4(p, perception, [&] { return bound; }, consider, sweep)) {
        for (int l = 0; l < count; ++l)
            senseBoid(boid[l], &sweep, out[l]);
        return;
    }
    for (int l = 0; l < count; ++l) {
        const std::size_t i = boid[l];
        // As senseBoid: fewer than k within the guess, so search the whole radius; and
        // again by rank after a tie (TieOrder.h).
        finishSearch(i, &sweep, guess2[l], perception2, best[l]);
        sumBoid(i, best[l], out[l]);
    }
}

}  // namespace throng::sim
