// Leader overtakes: the figure a user checks after a chase (cavalry): no follower ever
// gets ahead of the leader it chases. Reads the committed state only.
#include "simcore/world/CountPhase.h"

#include "simcore/world/detail/StepGeometry.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace throng::sim {

using namespace detail;

namespace {

// Arc length (m) from the start of `path` to its point nearest p.
float routeProgress(const Path& path, glm::vec2 p)
{
    const std::vector<glm::vec2>& points = path.points;
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

}  // namespace

// A follower (a ground agent, not driven, whose type pursues or follows its leader)
// overtakes in a step when its leader is still on its way (not stopped for good), the
// follower's centre lies in front of the leader's centre (more than the two bodies'
// radii ahead along the leader's heading, and further ahead than to the side: within
// 45 degrees of the heading, so a flanker level with a turning leader does not count),
// and, when the leader follows an open path, the follower's progress along that path
// (the arc length to its nearest point) exceeds the leader's.
void CountPhase::countLeaderOvertakes(const StepView& v)
{
    const AgentColumns& a = v.agents;
    auto isAhead = [&](std::size_t i) -> bool {
        if (a.leader[i] < 0 || v.traffic.isDriven(i))
            return false;
        const TypeSteering& s = v.types.steering[a.info[i].typeIndex];
        if (s.vehicle.flying ||
            !(s.on(Behaviour::Pursuit) || s.on(Behaviour::OffsetPursuit) || s.on(Behaviour::LeaderFollowing)))
            return false;
        const auto l = std::size_t(a.leader[i]);
        if (a.stopped[l])
            return false;
        const glm::vec2 fwd = xz(a.fwd[l]), rel = xz(a.pos[i]) - xz(a.pos[l]);
        if (glm::dot(fwd, fwd) < 1e-12f)
            return false;
        const glm::vec2 heading = glm::normalize(fwd);
        const float along = glm::dot(rel, heading), aside = std::fabs(cross(heading, rel));
        if (along <= a.radius[i] + a.radius[l] || along <= aside)
            return false;
        if (a.path[l] >= 0 && !v.set.paths[std::size_t(a.path[l])].closed) {
            const Path& path = v.set.paths[std::size_t(a.path[l])];
            if (routeProgress(path, xz(a.pos[i])) <= routeProgress(path, xz(a.pos[l])))
                return false;
        }
        return true;
    };
    m_counters.leaderOvertaken += v.team.sumChunks(a.size(), 256, [&](std::size_t begin, std::size_t end, int) {
        std::uint64_t count = 0;
        for (std::size_t i = begin; i < end; ++i)
            count += isAhead(i);
        return count;
    });
}

}  // namespace throng::sim
