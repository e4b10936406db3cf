#include "simcore/nav/NavFollow.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace throng::sim {

float waypointRadiusM(float baseM, float u01, float spread)
{
    const float s = std::clamp(spread, 0.0f, 1.0f), u = std::clamp(u01, 0.0f, 1.0f);
    return std::max(0.0f, baseM * (1.0f + s * (2.0f * u - 1.0f)));
}

std::size_t advanceWaypoint(std::span<const glm::vec2> waypoints, std::size_t index, glm::vec2 position, float radiusM)
{
    while (index + 1 < waypoints.size() && glm::distance(position, waypoints[index]) <= radiusM)
        ++index;
    return index;
}

bool updateStall(StallWatch& watch, float distanceToGoalM, float dtS, const StallParams& params)
{
    if (distanceToGoalM <= watch.bestDistanceM - params.minProgressM) {
        watch.bestDistanceM = distanceToGoalM;
        watch.sinceProgressS = 0.0f;
        return false;
    }
    watch.sinceProgressS += dtS;
    if (watch.sinceProgressS < params.patienceS)
        return false;
    watch = StallWatch{distanceToGoalM, 0.0f};
    return true;
}

}  // namespace throng::sim
