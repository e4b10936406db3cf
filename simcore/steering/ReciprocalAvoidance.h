#pragma once
// Reciprocal velocity obstacles on the ground plane (ORCA: van den Berg, Guy, Lin and
// Manocha, "Reciprocal n-Body Collision Avoidance", 2011). Each neighbour closes a
// half-plane of velocities that would touch it within the time horizon; the agent takes
// its share of the avoidance (half for a neighbour that avoids too, all of it for one
// that stands still) and picks the allowed velocity nearest the one it prefers, by a
// small linear program. Where no velocity is allowed, the one that least violates the
// worst half-plane. Pure, deterministic for a given neighbour order; no allocation.

#include "simcore/steering/BehaviourKey.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <span>
#include <string_view>

namespace throng::sim {

struct ReciprocalAvoidanceParams {
    float timeHorizonS = 1.0f;  // s, > 0: collisions further ahead than this are ignored
    float keepRightRad = 0.5f;  // rad, >= 0: turn right of the preferred way when walkers come the other way
};

struct PlanarNeighbour {
    glm::vec2 position{0.0f};
    glm::vec2 velocity{0.0f};
    float radius = 0.0f;
    float share = 0.5f;  // of the avoidance this agent takes: 0.5 reciprocal, 1 for a standing body
};

struct PlanarBody {
    glm::vec2 position{0.0f};
    glm::vec2 velocity{0.0f};
    float radius = 0.0f;
    float maxSpeed = 0.0f;
};

// The new velocity: within maxSpeed, outside every neighbour's half-plane when that is
// possible, nearest to `preferred`. dt is the step, used for bodies already overlapping
// (they part within one step). At most 16 neighbours are considered (the nearest first).
glm::vec2 avoidReciprocally(const PlanarBody& self, glm::vec2 preferred, std::span<const PlanarNeighbour> neighbours,
                            float dt, const ReciprocalAvoidanceParams& params = {});

// Whether a neighbour counts among the oncoming walkers of reciprocalForce's turn to the
// right: it walks (has not stopped), faces more than 120 degrees away from this walker's
// heading `forward` (on the ground plane), and stands ahead of it.
inline bool comesTheOtherWay(glm::vec2 position, glm::vec2 forward, glm::vec2 otherPosition, glm::vec2 otherForward,
                             bool otherStopped)
{
    return !otherStopped && glm::dot(otherForward, forward) < -0.5f &&
           glm::dot(otherPosition - position, forward) > 0.0f;
}

// The force that makes a walker's velocity the one avoidReciprocally chooses by the time
// of its next decision, decideDt from now (> 0; mass > 0): the velocity its steering
// `force` would reach, capped at body.maxSpeed, is the one it prefers, turned right of the
// way (turns[min(oncoming, 3) - 1]: cosine and sine) while `oncoming` walkers come the
// other way and params.keepRightRad > 0. The general path (Steer.h) and the walker
// kernel (WalkKernel.h) both call it.
inline glm::vec3 reciprocalForce(const PlanarBody& body, float mass, glm::vec3 force,
                                 std::span<const PlanarNeighbour> neighbours, std::size_t oncoming,
                                 const std::array<glm::vec2, 3>& turns, float decideDt,
                                 const ReciprocalAvoidanceParams& params)
{
    glm::vec2 preferred = body.velocity + glm::vec2(force.x, force.z) * (decideDt / mass);
    const float speed = glm::length(preferred);
    if (speed > body.maxSpeed && speed > 0.0f)
        preferred *= body.maxSpeed / speed;
    // Keep to the right of oncoming walkers (the pedestrians' convention), more the more
    // of them come: opposing streams then pass side by side instead of meeting head-on.
    if (oncoming > 0 && params.keepRightRad > 0.0f) {
        const glm::vec2 turn = turns[std::min<std::size_t>(oncoming, 3) - 1];
        const glm::vec2 right(-preferred.y, preferred.x);
        preferred = preferred * turn.x + right * turn.y;
    }
    const glm::vec2 change = (avoidReciprocally(body, preferred, neighbours, decideDt, params) - body.velocity) *
                             (mass / decideDt);
    return glm::vec3(change.x, 0.0f, change.y);
}

// Reciprocal avoidance's entry in the behaviour list (BehaviourTable.h). It asks for no
// force: it filters what the others ask for (Steer.h, avoidReciprocally).
struct ReciprocalAvoidanceBehaviour {
    static constexpr std::string_view kName = "reciprocal_avoidance";
    struct Slot {
        ReciprocalAvoidanceParams reciprocal;
    };
    static constexpr auto kParams = &Slot::reciprocal;
    using P = ReciprocalAvoidanceParams;
    static constexpr std::array kKeys{
        ParamKey<P>{.key = "time_horizon", .meaning = "s, > 0: collisions further ahead are ignored", .lo = 1e-3f,
                    .number = &P::timeHorizonS},
        ParamKey<P>{.key = "keep_right",
                    .meaning = "degrees, 0..90: turn right of the way while walkers come the other way",
                    .kind = ParamKind::AngleDeg, .hi = 90, .number = &P::keepRightRad},
    };
    template <class Step, class Emit>
    static void request(const Step&, const ReciprocalAvoidanceParams&, Emit&&)
    {
    }
};

}  // namespace throng::sim
