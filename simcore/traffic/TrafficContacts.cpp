// Contact counts (vehicle-vehicle, vehicle-pedestrian) over a hashed uniform grid of the
// active vehicles, rebuilt by counting sort after each step: O(vehicles + pedestrians),
// whatever the extent of the lanes.
#include "simcore/traffic/TrafficSystem.h"

#include "simcore/base/Rng.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>
#include <cmath>

namespace throng::sim {

namespace {
std::uint64_t cellKey(int cx, int cy) { return (std::uint64_t(std::uint32_t(cx)) << 32) | std::uint32_t(cy); }
}  // namespace

void TrafficSystem::buildVehicleGrid()
{
    m_cellM = 2.0f * m_maxRadius;
    const std::size_t buckets = std::bit_ceil(std::max<std::size_t>(64, 2 * m_s.size()));
    m_cellStart.assign(buckets + 1, 0u);
    m_cellKey.resize(m_s.size());
    m_cellOf.resize(m_s.size());
    for (std::size_t i = 0; i < m_s.size(); ++i) {
        if (!m_active[i])
            continue;
        m_cellKey[i] = cellKey(int(std::floor(m_pos[i].x / m_cellM)), int(std::floor(m_pos[i].y / m_cellM)));
        m_cellOf[i] = std::uint32_t(mix64(m_cellKey[i]) & (buckets - 1));
        ++m_cellStart[m_cellOf[i] + 1];
    }
    for (std::size_t c = 1; c < m_cellStart.size(); ++c)
        m_cellStart[c] += m_cellStart[c - 1];
    m_cellItems.resize(m_cellStart.back());
    m_cellCursor.assign(m_cellStart.begin(), m_cellStart.end() - 1);
    for (std::uint32_t i = 0; i < m_s.size(); ++i)
        if (m_active[i])
            m_cellItems[m_cellCursor[m_cellOf[i]]++] = i;
}

template <class Fn>
void TrafficSystem::forEachVehicleNear(glm::vec2 p, float radiusM, Fn&& fn) const
{
    const std::size_t mask = m_cellStart.size() - 2;
    const int x0 = int(std::floor((p.x - radiusM) / m_cellM)), x1 = int(std::floor((p.x + radiusM) / m_cellM));
    const int y0 = int(std::floor((p.y - radiusM) / m_cellM)), y1 = int(std::floor((p.y + radiusM) / m_cellM));
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const std::uint64_t key = cellKey(x, y);
            const std::size_t b = std::size_t(mix64(key)) & mask;
            // Other cells may share the bucket: visit only this cell's vehicles.
            for (std::uint32_t k = m_cellStart[b]; k < m_cellStart[b + 1]; ++k)
                if (m_cellKey[m_cellItems[k]] == key)
                    fn(m_cellItems[k]);
        }
}

void TrafficSystem::countVehicleContacts()
{
    for (std::uint32_t i = 0; i < m_s.size(); ++i) {
        if (!m_active[i])
            continue;
        forEachVehicleNear(m_pos[i], m_radius[i] + m_maxRadius, [&](std::uint32_t j) {
            const float r = m_radius[i] + m_radius[j];
            if (j > i && glm::dot(m_pos[i] - m_pos[j], m_pos[i] - m_pos[j]) < r * r)
                ++m_counters.vehicleCollisions;
        });
    }
}

void TrafficSystem::countPedestrianContacts(std::span<const PedestrianView> peds)
{
    if (m_s.empty())
        return;
    for (const PedestrianView& p : peds)
        forEachVehicleNear(p.position, p.radiusM + m_maxRadius, [&](std::uint32_t j) {
            const float r = m_radius[j] + p.radiusM;
            const glm::vec2 d = p.position - m_pos[j];
            if (glm::dot(d, d) < r * r)
                ++m_counters.carPedestrianCollisions;
        });
}

}  // namespace throng::sim
