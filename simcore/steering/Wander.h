#pragma once
// Wander (Reynolds 1999): a target on a circle (sphere for fliers) ahead of the agent drifts by
// small random steps and the agent steers toward it. Pure: the caller passes the previous state
// and counter-RNG numbers and keeps the returned state; it never draws random numbers itself.

#include "simcore/steering/BehaviourKey.h"
#include "simcore/steering/SteeringAgent.h"

#include <glm/vec3.hpp>

#include <array>
#include <string_view>

namespace throng::sim {

struct WanderParams {
    float distanceM = 2.0f;       // m, >= 0: distance of the circle's centre ahead of the agent
    float radiusM = 0.5f;         // m, >= 0: circle radius, the wander strength
    float jitterM = 0.1f;         // m per call, >= 0: most the target moves in one step, the rate
    bool flying = false;          // false: the target stays in the agent's horizontal plane
    float responseTimeS = 0.5f;   // s, > 0: time to reach the desired velocity
};

struct WanderState {
    glm::vec3 target{0.0f, 0.0f, 1.0f};  // unit: on the circle, in the agent's frame (x right, y up, z forward)
};

struct WanderResult {
    glm::vec3 force{0.0f};  // N, at most maxForce
    WanderState state;      // pass it back next step
};

// random: three numbers in [-1, 1] (y ignored unless flying). The same inputs give the same result.
// The desired direction never leaves the cone of half-angle asin(radius / distance) around forward
// (when radius < distance), so the agent keeps moving ahead while it turns.
WanderResult wander(const SteeringAgent& agent, const WanderState& previous, glm::vec3 random,
                    const WanderParams& params = {});

// Wander's entry in the behaviour list (BehaviourTable.h): the step's seeded random draws
// move the agent's wander target, and the new target goes out with the step.
struct WanderBehaviour {
    static constexpr std::string_view kName = "wander";
    struct Slot {
        WanderParams wander;
    };
    static constexpr auto kParams = &Slot::wander;
    static constexpr std::array kKeys{
        ParamKey<WanderParams>{.key = "distance", .meaning = "m, >= 0: circle centre ahead of the agent",
                               .number = &WanderParams::distanceM},
        ParamKey<WanderParams>{.key = "strength", .meaning = "m, >= 0: circle radius",
                               .number = &WanderParams::radiusM},
        ParamKey<WanderParams>{.key = "rate", .meaning = "m per step, >= 0: how far the target may jitter",
                               .number = &WanderParams::jitterM},
    };
    // A wanderer goes somewhere: it does not come to rest without a goal (Steer.cpp).
    template <class Step>
    static bool leadsSomewhere(const Step&)
    {
        return true;
    }
    template <class Step, class Emit>
    static void request(const Step& step, const WanderParams& p, Emit&& emit)
    {
        const WanderResult w = wander(step.self, step.wanderState(), step.wanderRandom(), p);
        step.setWanderState(w.state);
        emit(w.force);
    }
};

}  // namespace throng::sim
