#pragma once
// Flow-field following (Reynolds 1999): the caller samples the field at the agent's
// predicted position and passes the direction; the agent steers to travel along it at top
// speed. Pure; never samples a field itself, never allocates.

#include "simcore/steering/BehaviourKey.h"
#include "simcore/steering/SteeringAgent.h"

#include <glm/vec3.hpp>

#include <array>
#include <string_view>

namespace throng::sim {

struct FlowFollowParams {
    float predictionS = 0.5f;     // s, >= 0: the field is sampled at position + velocity * this
    float responseTimeS = 0.25f;  // s, > 0: time to reach the desired velocity
};

// Where the caller should sample the field.
glm::vec3 flowSamplePoint(const SteeringAgent& agent, const FlowFollowParams& params = {});

// fieldDirection: the field's desired direction at the sample point (any length; zero = no flow
// there, and then the force is exactly zero).
glm::vec3 followFlow(const SteeringAgent& agent, glm::vec3 fieldDirection, const FlowFollowParams& params = {});

// Flow field following's entry in the behaviour list (BehaviourTable.h): asks wherever
// the scene has a sketched flow.
struct FlowFieldFollowingBehaviour {
    static constexpr std::string_view kName = "flow_field_following";
    struct Slot {
        FlowFollowParams flow;
    };
    static constexpr auto kParams = &Slot::flow;
    static constexpr std::array kKeys{
        ParamKey<FlowFollowParams>{.key = "prediction", .meaning = "s, >= 0: where the field is sampled",
                                   .number = &FlowFollowParams::predictionS},
        ParamKey<FlowFollowParams>{.key = "response_time", .meaning = "s, > 0", .lo = 1e-3f,
                                   .number = &FlowFollowParams::responseTimeS},
    };
    // A flow follower goes somewhere wherever a flow is sketched (Steer.cpp).
    template <class Step>
    static bool leadsSomewhere(const Step& step)
    {
        return step.hasFlow();
    }
    template <class Step, class Emit>
    static void request(const Step& step, const FlowFollowParams& p, Emit&& emit)
    {
        if (step.hasFlow())
            emit(followFlow(step.self, step.flowAt(flowSamplePoint(step.self, p)), p));
    }
};

}  // namespace throng::sim
