#pragma once
// Leader following (Reynolds 1999): arrive at a point behind the leader, and step aside
// when standing in the corridor ahead of it. Separation from other followers is the
// caller's to add. Pure; never allocates, never reads anything but its arguments.

#include "simcore/steering/BehaviourKey.h"
#include "simcore/steering/Neighbour.h"
#include "simcore/steering/SteeringAgent.h"

#include <glm/vec3.hpp>

#include <array>
#include <string_view>

namespace throng::sim {

struct LeaderFollowParams {
    float behindM = 1.5f;             // m, >= 0: the follow point's distance behind the leader's centre
    float corridorLengthM = 3.0f;     // m, >= 0: length of the region ahead of the leader kept clear
    float corridorHalfWidthM = 0.8f;  // m, >= 0: its half width, to which the follower's radius is added
    float slowingDistanceM = 2.0f;    // m, > 0: arrival ramp toward the follow point
    float responseTimeS = 0.25f;      // s, > 0
};

// True when the follower's centre lies in the corridor: ahead of the leader's centre by at most
// corridorLengthM and nearer its heading line than corridorHalfWidthM + the follower's radius.
bool inLeaderCorridor(const SteeringAgent& follower, const Neighbour& leader, const LeaderFollowParams& params = {});

// In the corridor: steer straight out of it sideways at top speed (away from the leader's line;
// a follower exactly on the line goes right when its id is odd, left when even). Elsewhere:
// offset pursuit of the point behindM behind the leader.
glm::vec3 followLeader(const SteeringAgent& follower, const Neighbour& leader, const LeaderFollowParams& params = {});

// Leader following's entry in the behaviour list (BehaviourTable.h): asks only of an
// agent with a leader.
struct LeaderFollowingBehaviour {
    static constexpr std::string_view kName = "leader_following";
    struct Slot {
        LeaderFollowParams leader;
    };
    static constexpr auto kParams = &Slot::leader;
    using P = LeaderFollowParams;
    static constexpr std::array kKeys{
        ParamKey<P>{.key = "behind", .meaning = "m, >= 0: follow point behind the leader", .number = &P::behindM},
        ParamKey<P>{.key = "corridor_length", .meaning = "m, >= 0: kept clear ahead of the leader",
                    .number = &P::corridorLengthM},
        ParamKey<P>{.key = "corridor_half_width", .meaning = "m, >= 0", .number = &P::corridorHalfWidthM},
    };
    template <class Step, class Emit>
    static void request(const Step& step, const LeaderFollowParams& p, Emit&& emit)
    {
        if (step.leader)
            emit(followLeader(step.self, *step.leader, p));
    }
};

}  // namespace throng::sim
