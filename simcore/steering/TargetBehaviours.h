#pragma once
// Seek, flee and arrival (Reynolds 1999): steering toward or away from one fixed point.
// Pure functions of their arguments; they return a force (N, at most maxForce) and never
// integrate, allocate or read anything but their parameters.

#include "simcore/steering/BehaviourKey.h"
#include "simcore/steering/SteeringAgent.h"

#include <glm/vec3.hpp>

#include <array>
#include <string_view>

namespace throng::sim {

struct SeekParams {
    float responseTimeS = 0.25f;  // s, > 0: time to reach the desired velocity (force = mass * dv / t)
};

struct FleeParams {
    float panicDistanceM = 0.0f;  // m, >= 0: flee only when nearer than this; 0 = at any distance
    float responseTimeS = 0.25f;  // s, > 0
};

struct ArrivalParams {
    float slowingDistanceM = 2.0f;  // m, > 0: the desired speed ramps down linearly inside it
    float toleranceM = 0.02f;       // m, >= 0: inside it the desired velocity is exactly zero
    float responseTimeS = 0.25f;    // s, > 0; below slowingDistanceM / (4 maxSpeed) the approach
                                    // is overdamped and never overshoots
};

// Desired velocity: toward target at maxSpeed (zero on the target, so it brakes there). Zero when
// standing still on the target.
glm::vec3 seek(const SteeringAgent& agent, glm::vec3 target, const SeekParams& params = {});

// Desired velocity: away from threat at maxSpeed. Zero outside the panic distance. An agent
// standing exactly on the threat flees along its forward.
glm::vec3 flee(const SteeringAgent& agent, glm::vec3 threat, const FleeParams& params = {});

// Seek that slows down inside the slowing distance and stops at the target. Zero once stopped
// inside the tolerance.
glm::vec3 arrive(const SteeringAgent& agent, glm::vec3 target, const ArrivalParams& params = {});

// The desired velocity of arrival alone, for behaviours that add a feed-forward velocity to it.
glm::vec3 arrivalVelocity(const SteeringAgent& agent, glm::vec3 target, float slowingDistanceM, float toleranceM);

// Flee's, arrival's and seek's entries in the behaviour list (BehaviourTable.h). Flee runs
// from the leader when there is one, else from the goal; arrival and seek head for the
// goal of an agent that follows no path.
struct FleeBehaviour {
    static constexpr std::string_view kName = "flee";
    struct Slot {
        FleeParams flee;
    };
    static constexpr auto kParams = &Slot::flee;
    static constexpr std::array kKeys{
        ParamKey<FleeParams>{.key = "panic_distance", .meaning = "m, >= 0: flee only nearer than this; 0 = always",
                             .number = &FleeParams::panicDistanceM},
        ParamKey<FleeParams>{.key = "response_time", .meaning = "s, > 0", .lo = 1e-3f,
                             .number = &FleeParams::responseTimeS},
    };
    template <class Step, class Emit>
    static void request(const Step& step, const FleeParams& p, Emit&& emit)
    {
        if (step.leader)
            emit(flee(step.self, step.leader->position, p));
        else if (step.hasGoal)
            emit(flee(step.self, step.goal, p));
    }
};

struct ArrivalBehaviour {
    static constexpr std::string_view kName = "arrival";
    struct Slot {
        ArrivalParams arrival;
    };
    static constexpr auto kParams = &Slot::arrival;
    static constexpr std::array kKeys{
        ParamKey<ArrivalParams>{.key = "slowing_distance", .meaning = "m, > 0: the speed ramps down inside it",
                                .lo = 1e-3f, .number = &ArrivalParams::slowingDistanceM},
        ParamKey<ArrivalParams>{.key = "tolerance", .meaning = "m, >= 0: stopped this near the target",
                                .number = &ArrivalParams::toleranceM},
        ParamKey<ArrivalParams>{.key = "response_time", .meaning = "s, > 0", .lo = 1e-3f,
                                .number = &ArrivalParams::responseTimeS},
    };
    template <class Step, class Emit>
    static void request(const Step& step, const ArrivalParams& p, Emit&& emit)
    {
        if (!step.hasGoal || step.onPath())
            return;
        // An exit is walked through, not stopped at: slowing down short of it, a walker
        // whose door posts pushed it back (wall following) stood in front of the door for
        // good (issue 23). Walkers with a navigation target keep their slowing: it sets a
        // flow-field walker's pace in a crowd (WorldNav.cpp, Weidmann).
        if (!step.walksThroughGoal()) {
            emit(arrive(step.self, step.goal, p));
            return;
        }
        ArrivalParams through = p;
        through.slowingDistanceM = kThroughSlowingM;
        emit(arrive(step.self, step.goal, through));
    }
    // The slowing distance through an exit: none to speak of (the walker kernel takes it too).
    static constexpr float kThroughSlowingM = 1e-6f;
};

struct SeekBehaviour {
    static constexpr std::string_view kName = "seek";
    struct Slot {
        SeekParams seek;
    };
    static constexpr auto kParams = &Slot::seek;
    static constexpr std::array kKeys{
        ParamKey<SeekParams>{.key = "response_time", .meaning = "s, > 0: time to reach the desired velocity",
                             .lo = 1e-3f, .number = &SeekParams::responseTimeS},
    };
    template <class Step, class Emit>
    static void request(const Step& step, const SeekParams& p, Emit&& emit)
    {
        if (step.hasGoal && !step.onPath())
            emit(seek(step.self, step.goal, p));
    }
};

}  // namespace throng::sim
