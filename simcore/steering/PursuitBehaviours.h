#pragma once
// Pursuit, evasion and offset pursuit (Reynolds 1999): steering relative to a moving agent
// by predicting where it will be. Pure functions returning a force (N, at most maxForce);
// they never integrate, allocate or look at anything but their arguments.

#include "simcore/steering/BehaviourKey.h"
#include "simcore/steering/Neighbour.h"
#include "simcore/steering/SteeringAgent.h"

#include <glm/vec3.hpp>

#include <array>
#include <string_view>

namespace throng::sim {

struct PursuitParams {
    float maxPredictionS = 2.0f;  // s, >= 0: the prediction interval never exceeds this
    float responseTimeS = 0.25f;  // s, > 0: time to reach the desired velocity
};

struct EvasionParams {
    float maxPredictionS = 2.0f;  // s, >= 0
    float panicDistanceM = 0.0f;  // m, >= 0: evade only when nearer than this; 0 = at any distance
    float responseTimeS = 0.25f;  // s, > 0
};

struct OffsetPursuitParams {
    glm::vec3 offsetM{0.0f, 0.0f, -1.5f};  // m, in the quarry's frame: x right, y up, z forward
    float slowingDistanceM = 2.0f;         // m, > 0: arrival ramp toward the offset point
    float toleranceM = 0.02f;              // m, >= 0: no correction nearer than this
    float responseTimeS = 0.25f;           // s, > 0
};

// Seeks the quarry's position predicted T = distance / maxSpeed ahead (clamped to maxPredictionS).
glm::vec3 pursue(const SteeringAgent& agent, const Neighbour& quarry, const PursuitParams& params = {});

// Flees from the threat's position predicted T = distance / threat speed ahead (clamped).
glm::vec3 evade(const SteeringAgent& agent, const Neighbour& threat, const EvasionParams& params = {});

// Holds a point fixed in the quarry's frame: the quarry's velocity fed forward plus arrival at the
// offset point, so a steady offset is held without lag. Zero once the offset is held exactly.
glm::vec3 pursueOffset(const SteeringAgent& agent, const Neighbour& quarry, const OffsetPursuitParams& params = {});

// The world position of a point given in the quarry's frame (x right, y up, z forward).
glm::vec3 pointInFrameOf(const Neighbour& quarry, glm::vec3 localOffset);

// Evasion's, offset pursuit's and pursuit's entries in the behaviour list
// (BehaviourTable.h): each asks only of an agent with a leader, the one they act on.
struct EvasionBehaviour {
    static constexpr std::string_view kName = "evasion";
    struct Slot {
        EvasionParams evasion;
    };
    static constexpr auto kParams = &Slot::evasion;
    static constexpr std::array kKeys{
        ParamKey<EvasionParams>{.key = "max_prediction", .meaning = "s, >= 0",
                                .number = &EvasionParams::maxPredictionS},
        ParamKey<EvasionParams>{.key = "panic_distance", .meaning = "m, >= 0: evade only nearer than this; 0 = always",
                                .number = &EvasionParams::panicDistanceM},
        ParamKey<EvasionParams>{.key = "response_time", .meaning = "s, > 0", .lo = 1e-3f,
                                .number = &EvasionParams::responseTimeS},
    };
    template <class Step, class Emit>
    static void request(const Step& step, const EvasionParams& p, Emit&& emit)
    {
        if (step.leader)
            emit(evade(step.self, *step.leader, p));
    }
};

struct OffsetPursuitBehaviour {
    static constexpr std::string_view kName = "offset_pursuit";
    struct Slot {
        OffsetPursuitParams offsetPursuit;
    };
    static constexpr auto kParams = &Slot::offsetPursuit;
    using P = OffsetPursuitParams;
    static constexpr std::array kKeys{
        ParamKey<P>{.key = "offset", .meaning = "[x, y, z] m in the leader's frame: x right, y up, z forward",
                    .kind = ParamKind::Vector3, .lo = -kParamBig, .vector = &P::offsetM},
        ParamKey<P>{.key = "slowing_distance", .meaning = "m, > 0", .lo = 1e-3f, .number = &P::slowingDistanceM},
        ParamKey<P>{.key = "response_time", .meaning = "s, > 0", .lo = 1e-3f, .number = &P::responseTimeS},
    };
    template <class Step, class Emit>
    static void request(const Step& step, const OffsetPursuitParams& p, Emit&& emit)
    {
        if (step.leader)
            emit(pursueOffset(step.self, *step.leader, p));
    }
};

struct PursuitBehaviour {
    static constexpr std::string_view kName = "pursuit";
    struct Slot {
        PursuitParams pursuit;
    };
    static constexpr auto kParams = &Slot::pursuit;
    static constexpr std::array kKeys{
        ParamKey<PursuitParams>{.key = "max_prediction", .meaning = "s, >= 0: the prediction interval's cap",
                                .number = &PursuitParams::maxPredictionS},
        ParamKey<PursuitParams>{.key = "response_time", .meaning = "s, > 0", .lo = 1e-3f,
                                .number = &PursuitParams::responseTimeS},
    };
    template <class Step, class Emit>
    static void request(const Step& step, const PursuitParams& p, Emit&& emit)
    {
        if (step.leader)
            emit(pursue(step.self, *step.leader, p));
    }
};

}  // namespace throng::sim
