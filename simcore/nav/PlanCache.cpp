#include "simcore/nav/PlanCache.h"

namespace throng::sim {

std::shared_ptr<const NavPlan> PlanCache::plan(const NavGrid& grid, NavCell start, NavCell goal, AStar& astar)
{
    if (grid.generation() != m_generation) {
        if (!m_plans.empty())
            ++m_invalidations;
        m_plans.clear();
        m_generation = grid.generation();
    }
    // Cells outside the grid have no index of their own; they all plan to StartBlocked or
    // GoalBlocked, so they share the key -1.
    const auto key =
        std::make_pair(grid.inside(start) ? grid.index(start) : -1, grid.inside(goal) ? grid.index(goal) : -1);
    if (const auto it = m_plans.find(key); it != m_plans.end()) {
        ++m_hits;
        return it->second;
    }
    ++m_misses;
    auto made = std::make_shared<const NavPlan>(astar.plan(grid, start, goal));
    m_plans.emplace(key, made);
    return made;
}

void PlanCache::clear()
{
    m_plans.clear();
}

std::shared_ptr<const NavPlan> planBetween(PlanCache& cache, const NavGrid& grid, glm::vec2 from, glm::vec2 to,
                                           AStar& astar)
{
    const NavCell start = grid.nearestWalkable(grid.cellOf(from)), goal = grid.nearestWalkable(grid.cellOf(to));
    if (!grid.walkable(start) || !grid.walkable(goal))
        return nullptr;
    return cache.plan(grid, start, goal, astar);
}

}  // namespace throng::sim
