#pragma once
// Shares plans between agents: one plan per (start cell, goal cell), made on first request
// and dropped wholesale when the grid's generation changes (the scene changed: re-plan).
// Not thread-safe: the World asks for plans in a serial phase, in agent order.

#include "simcore/nav/AStar.h"

#include <cstddef>
#include <map>
#include <memory>
#include <utility>

namespace throng::sim {

class PlanCache {
public:
    // The shared plan for start -> goal on grid, planned with astar on a miss. The pointer
    // stays valid (and unchanged) for as long as the caller holds it, even after a clear.
    std::shared_ptr<const NavPlan> plan(const NavGrid& grid, NavCell start, NavCell goal, AStar& astar);

    void clear();
    std::size_t size() const { return m_plans.size(); }
    std::size_t hits() const { return m_hits; }
    std::size_t misses() const { return m_misses; }
    std::size_t invalidations() const { return m_invalidations; }
    // True when plan was made on an older grid than the current one (the holder should re-plan).
    static bool stale(const NavPlan& plan, const NavGrid& grid) { return plan.generation != grid.generation(); }

private:
    std::map<std::pair<int, int>, std::shared_ptr<const NavPlan>> m_plans;
    std::uint64_t m_generation = 0;
    std::size_t m_hits = 0, m_misses = 0, m_invalidations = 0;
};

// What the World calls for an agent at `from` heading for `to`: both points snap to their
// cell, or to the nearest walkable cell when that is blocked (an agent brushing a wall
// stands in its inflated margin), then the cache answers. Null when the grid has no
// walkable cell at all.
std::shared_ptr<const NavPlan> planBetween(PlanCache& cache, const NavGrid& grid, glm::vec2 from, glm::vec2 to,
                                           AStar& astar);

}  // namespace throng::sim
