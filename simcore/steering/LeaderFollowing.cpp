// Leader following (Reynolds 1999, "Leader Following").
#include "simcore/steering/LeaderFollowing.h"

#include "simcore/steering/PursuitBehaviours.h"
#include "simcore/steering/detail/BehaviourMath.h"
#include "simcore/steering/detail/SteeringMath.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace throng::sim {

using namespace detail;

namespace {

struct LeaderFrame {
    glm::vec3 forward, right;
    float along, lateral;  // m: the follower's offset in the leader's frame
};

LeaderFrame leaderFrame(const SteeringAgent& follower, const Neighbour& leader)
{
    LeaderFrame f;
    f.forward = normalizeOr(leader.forward, normalizeOr(leader.velocity, glm::vec3(0.0f, 0.0f, 1.0f)));
    f.right = rightOfForward(f.forward);
    const glm::vec3 rel = finiteOrZero(follower.position - leader.position);
    f.along = glm::dot(rel, f.forward);
    f.lateral = glm::dot(rel, f.right);
    return f;
}

}  // namespace

bool inLeaderCorridor(const SteeringAgent& follower, const Neighbour& leader, const LeaderFollowParams& params)
{
    const LeaderFrame f = leaderFrame(follower, leader);
    return f.along >= 0.0f && f.along <= nonNegative(params.corridorLengthM) &&
           std::abs(f.lateral) < nonNegative(params.corridorHalfWidthM) + nonNegative(follower.radius);
}

glm::vec3 followLeader(const SteeringAgent& follower, const Neighbour& leader, const LeaderFollowParams& params)
{
    if (inLeaderCorridor(follower, leader, params)) {
        const LeaderFrame f = leaderFrame(follower, leader);
        float side = f.lateral > 0.0f ? 1.0f : -1.0f;
        if (f.lateral == 0.0f)
            side = (follower.id & 1u) ? 1.0f : -1.0f;
        return steerTowards(follower, f.right * (side * nonNegative(follower.maxSpeed)), params.responseTimeS);
    }
    OffsetPursuitParams pursuit;
    pursuit.offsetM = {0.0f, 0.0f, -nonNegative(params.behindM)};
    pursuit.slowingDistanceM = params.slowingDistanceM;
    pursuit.responseTimeS = params.responseTimeS;
    return pursueOffset(follower, leader, pursuit);
}

}  // namespace throng::sim
