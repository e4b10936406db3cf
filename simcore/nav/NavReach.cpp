#include "simcore/nav/NavReach.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::sim {

float NavReach::cellFor(glm::vec2 boundsMin, glm::vec2 boundsMax, float finestM)
{
    const glm::vec2 size = glm::max(boundsMax - boundsMin, glm::vec2(1.0f));
    return std::max(finestM, std::sqrt(size.x * size.y / 4.0e6f));
}

void NavReach::build(const NavShapes& shapes, glm::vec2 boundsMin, glm::vec2 boundsMax, float bodyRadiusM,
                     float cellM)
{
    m_bodyRadiusM = bodyRadiusM;
    // The grid blocks every cell a shape's inflation touches: inflated by the full radius,
    // a door a few centimetres wider than the body would close.
    m_grid.build(shapes, boundsMin, boundsMax, NavGridParams{cellM, std::max(0.0f, bodyRadiusM - 0.75f * cellM)});
    const int cells = m_grid.cellCount();
    m_region.assign(std::size_t(cells), -1);
    std::vector<int> stack;
    std::int32_t next = 0;
    for (int start = 0; start < cells; ++start) {
        if (!m_grid.walkableIndex(start) || m_region[std::size_t(start)] >= 0)
            continue;
        m_region[std::size_t(start)] = next;
        stack.assign(1, start);
        while (!stack.empty()) {
            const NavCell c = m_grid.cellAt(stack.back());
            stack.pop_back();
            for (int dz = -1; dz <= 1; ++dz)
                for (int dx = -1; dx <= 1; ++dx) {
                    const NavCell d{c.x + dx, c.z + dz};
                    // Diagonal steps only between two open sides, as a body passes a corner.
                    if ((dx == 0 && dz == 0) || !m_grid.walkable(d) ||
                        (dx != 0 && dz != 0 &&
                         (!m_grid.walkable({c.x + dx, c.z}) || !m_grid.walkable({c.x, c.z + dz}))))
                        continue;
                    std::int32_t& r = m_region[std::size_t(m_grid.index(d))];
                    if (r < 0) {
                        r = next;
                        stack.push_back(m_grid.index(d));
                    }
                }
        }
        ++next;
    }
}

std::int32_t NavReach::regionAt(glm::vec2 p) const
{
    if (!built())
        return -1;
    const NavCell free = m_grid.nearestWalkable(m_grid.cellOf(p));
    if (!m_grid.walkable(free) || glm::distance(m_grid.centre(free), p) > m_bodyRadiusM + 1.5f * m_grid.cellM())
        return -1;
    return m_region[std::size_t(m_grid.index(free))];
}

bool NavReach::enterable(glm::vec2 centre, float radiusM) const
{
    return reaches(glm::vec2(NAN), centre, radiusM);
}

bool NavReach::reaches(glm::vec2 from, glm::vec2 centre, float radiusM) const
{
    if (!built())
        return true;  // no grid, no judgement
    const bool any = std::isnan(from.x);
    const std::int32_t mine = any ? -1 : regionAt(from);
    if (!any && mine < 0)
        return false;
    // A cell whose centre lies within the disk, or the one the centre falls in.
    const float r = std::max(radiusM, 0.0f);
    const NavCell lo = m_grid.cellOf(centre - glm::vec2(r)), hi = m_grid.cellOf(centre + glm::vec2(r));
    for (int z = std::max(lo.z, 0); z <= std::min(hi.z, m_grid.rows() - 1); ++z)
        for (int x = std::max(lo.x, 0); x <= std::min(hi.x, m_grid.cols() - 1); ++x) {
            const NavCell c{x, z};
            if (!m_grid.walkable(c) || (glm::distance(m_grid.centre(c), centre) >= r && !(c == m_grid.cellOf(centre))))
                continue;
            if (any || m_region[std::size_t(m_grid.index(c))] == mine)
                return true;
        }
    return false;
}

}  // namespace throng::sim
