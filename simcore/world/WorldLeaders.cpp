// Leader overtakes: the figure a user checks after a chase (cavalry): no follower ever
// gets ahead of the leader it chases. Reads the committed state only.
#include "simcore/world/World.h"

#include "simcore/world/detail/StepGeometry.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace throng::sim {

using namespace detail;

// Arc length (m) from the start of path `path` to its point nearest p.
float World::routeProgress(std::size_t path, glm::vec2 p) const
{
    const std::vector<glm::vec2>& points = m_paths[path].points;
    float best = INFINITY, bestAt = 0.0f, walked = 0.0f;
    for (std::size_t k = 0; k + 1 < points.size(); ++k) {
        const glm::vec2 c = closestOnSegment(p, points[k], points[k + 1]);
        const float d = glm::distance(p, c);
        if (d < best) {
            best = d;
            bestAt = walked + glm::distance(points[k], c);
        }
        walked += glm::distance(points[k], points[k + 1]);
    }
    return bestAt;
}

// A follower (a ground agent, not driven, whose type pursues or follows its leader)
// overtakes in a step when its leader is still on its way (not stopped for good), the
// follower's centre lies in front of the leader's centre (more than the two bodies'
// radii ahead along the leader's heading, and further ahead than to the side: within
// 45 degrees of the heading, so a flanker level with a turning leader does not count),
// and, when the leader follows an open path, the follower's progress along that path
// (the arc length to its nearest point) exceeds the leader's.
void World::countLeaderOvertakes()
{
    if (m_allFliers)
        return;  // a flier is never counted (below): no pass over a flock for nothing
    const std::size_t n = m_pos.size();
    auto isAhead = [&](std::size_t i) -> bool {
        if (m_leader[i] < 0 || m_traffic.isDriven(i))
            return false;
        const TypeSteering& s = m_steering[m_info[i].typeIndex];
        if (s.vehicle.flying ||
            !(s.on(Behaviour::Pursuit) || s.on(Behaviour::OffsetPursuit) || s.on(Behaviour::LeaderFollowing)))
            return false;
        const auto l = std::size_t(m_leader[i]);
        if (m_stopped[l])
            return false;
        const glm::vec2 fwd = xz(m_fwd[l]), rel = xz(m_pos[i]) - xz(m_pos[l]);
        if (glm::dot(fwd, fwd) < 1e-12f)
            return false;
        const glm::vec2 heading = glm::normalize(fwd);
        const float along = glm::dot(rel, heading), aside = std::fabs(cross(heading, rel));
        if (along <= m_radius[i] + m_radius[l] || along <= aside)
            return false;
        if (m_path[l] >= 0 && !m_paths[std::size_t(m_path[l])].closed) {
            const auto path = std::size_t(m_path[l]);
            if (routeProgress(path, xz(m_pos[i])) <= routeProgress(path, xz(m_pos[l])))
                return false;
        }
        return true;
    };
    const std::uint64_t ahead = m_team.sumChunks(n, 256, [&](std::size_t begin, std::size_t end, int) {
        std::uint64_t count = 0;
        for (std::size_t i = begin; i < end; ++i)
            count += isAhead(i);
        return count;
    });
    m_counters.leaderOvertaken += ahead;
}

}  // namespace throng::sim
