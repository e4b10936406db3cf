#pragma once
// Unaligned collision avoidance (Reynolds 1999): predict each neighbour's time of nearest
// approach assuming straight motion, and steer laterally away from the soonest one that will
// come too close, braking when it comes head-on. Pure; zero without a threat; no allocation.

#include "simcore/steering/BehaviourKey.h"
#include "simcore/steering/Neighbour.h"
#include "simcore/steering/SteeringAgent.h"

#include <glm/vec3.hpp>

#include <span>
#include <array>
#include <string_view>

namespace throng::sim {

struct UnalignedAvoidanceParams {
    float horizonS = 3.0f;          // s, > 0: approaches further in the future are ignored
    float marginM = 0.1f;           // m, >= 0: clearance wanted beyond the two radii
    float headOnCosine = -0.7f;     // [-1, 1]: heading dot product below which a threat is head-on
    float brakeFraction = 0.5f;     // [0, 1]: share of the force spent braking against a head-on threat
};

// The threat is the neighbour whose nearest approach comes soonest (ties: lower id) among those
// predicted to pass nearer than the two radii plus the margin. The lateral force points away
// from the threat's predicted position; a threat dead ahead is passed on the agent's right,
// so two agents meeting exactly head-on both go right and part. Strength: maxForce *
// (1 - time / horizon), the lateral and braking parts together at most maxForce.
glm::vec3 avoidUnalignedCollisions(const SteeringAgent& agent, std::span<const Neighbour> neighbours,
                                   const UnalignedAvoidanceParams& params = {});

// Unaligned collision avoidance's entry in the behaviour list (BehaviourTable.h), against
// the neighbours the agent avoids (not those making way for it).
struct UnalignedCollisionAvoidanceBehaviour {
    static constexpr std::string_view kName = "unaligned_collision_avoidance";
    struct Slot {
        UnalignedAvoidanceParams unaligned;
    };
    static constexpr auto kParams = &Slot::unaligned;
    using P = UnalignedAvoidanceParams;
    static constexpr std::array kKeys{
        ParamKey<P>{.key = "horizon", .meaning = "s, > 0: approaches later than this are ignored", .lo = 1e-3f,
                    .number = &P::horizonS},
        ParamKey<P>{.key = "margin", .meaning = "m, >= 0: clearance beyond the two bodies", .number = &P::marginM},
        ParamKey<P>{.key = "brake_fraction", .meaning = "0..1: share of force spent braking head-on", .hi = 1,
                    .number = &P::brakeFraction},
    };
    template <class Step, class Emit>
    static void request(const Step& step, const UnalignedAvoidanceParams& p, Emit&& emit)
    {
        emit(avoidUnalignedCollisions(step.self, step.avoided, p));
    }
};

}  // namespace throng::sim
