#pragma once
// Separation, alignment and cohesion (Reynolds 1987 boids, 1999 steering): the three group
// behaviours over the neighbours the caller gathered. Pure; zero without neighbours in
// range; never allocates, never reads the world, never draws random numbers.

#include "simcore/steering/BehaviourKey.h"
#include "simcore/steering/Neighbour.h"
#include "simcore/steering/SteeringAgent.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <array>
#include <string_view>

namespace throng::sim {

struct SeparationParams {
    float rangeM = 0.5f;         // m, >= 0: body-to-body gap below which a neighbour pushes
    float dampingTimeS = 0.5f;   // s, > 0: time constant damping how fast a neighbour in range
                                 // closes or opens the gap
    float keepRight = 1.0f;      // 0..1: share of max force a pedestrian that runs neither
                                 // unaligned nor reciprocal avoidance steps right with, an
                                 // oncoming walker in its way (KeepRight.h, World)
};

struct AlignmentParams {
    bool matchSpeed = false;      // false: turn to the neighbours' mean heading at the current speed;
                                  // true: match their mean velocity
    float responseTimeS = 0.5f;   // s, > 0: time to reach the desired velocity
};

struct CohesionParams {
    float slowingDistanceM = 2.0f;  // m, > 0: the approach to the centre slows inside it
    float responseTimeS = 0.5f;     // s, > 0
};

// The separation weight never exceeds this, however close two agents are.
inline constexpr float kMaxSeparationWeight = 10.0f;

// The unit direction in which agent `self` leaves a neighbour `other` at the same point:
// horizontal, fixed by the unordered pair of ids, opposite for the two.
glm::vec3 separationAxis(std::uint32_t self, std::uint32_t other);

// Sum over neighbours nearer than the two radii plus rangeM of
//   fade * (maxForce * w - mass / dampingTimeS * opening speed) * away,
// with the inverse-distance weight w = (r_i + r_j) / d (1 at contact, capped at 10 when nearly
// coincident) and fade = min(1, (r_i + r_j + rangeM - d) / rangeM), 1 up to contact and 0 at the
// edge of the range, so a neighbour entering the range adds no jump. Coincident agents part along a direction hashed
// from their two ids, in opposite senses. Not truncated: a crowded agent may get more than maxForce.
glm::vec3 separate(const SteeringAgent& agent, std::span<const Neighbour> neighbours,
                   const SeparationParams& params = {});

// Steers toward the neighbours' mean heading (or mean velocity). Zero without neighbours or when
// their headings cancel.
glm::vec3 align(const SteeringAgent& agent, std::span<const Neighbour> neighbours, const AlignmentParams& params = {});

// Arrives at the neighbours' centre. Zero without neighbours.
glm::vec3 cohere(const SteeringAgent& agent, std::span<const Neighbour> neighbours, const CohesionParams& params = {});

// Separation's, alignment's and cohesion's entries in the behaviour list (BehaviourTable.h).
// Separation keeps off the neighbours the agent avoids (not those making way for it);
// alignment and cohesion follow every neighbour it sees.
struct SeparationBehaviour {
    static constexpr std::string_view kName = "separation";
    struct Slot {
        SeparationParams separation;
    };
    static constexpr auto kParams = &Slot::separation;
    static constexpr std::array kKeys{
        ParamKey<SeparationParams>{.key = "range", .meaning = "m, >= 0: body gap below which neighbours push",
                                   .number = &SeparationParams::rangeM},
        ParamKey<SeparationParams>{
            .key = "keep_right",
            .meaning = "0..1: share of max force a walker steps right with, an oncoming walker in its way",
            .hi = 1,
            .number = &SeparationParams::keepRight},
    };
    template <class Step, class Emit>
    static void request(const Step& step, const SeparationParams& p, Emit&& emit)
    {
        emit(separate(step.self, step.avoided, p));
    }
};

struct AlignmentBehaviour {
    static constexpr std::string_view kName = "alignment";
    struct Slot {
        AlignmentParams alignment;
    };
    static constexpr auto kParams = &Slot::alignment;
    static constexpr std::array kKeys{
        ParamKey<AlignmentParams>{.key = "match_speed", .meaning = "true: match speed too, not only heading",
                                  .kind = ParamKind::Flag, .hi = 1, .flag = &AlignmentParams::matchSpeed},
        ParamKey<AlignmentParams>{.key = "response_time", .meaning = "s, > 0", .lo = 1e-3f,
                                  .number = &AlignmentParams::responseTimeS},
    };
    template <class Step, class Emit>
    static void request(const Step& step, const AlignmentParams& p, Emit&& emit)
    {
        emit(align(step.self, step.near, p));
    }
};

struct CohesionBehaviour {
    static constexpr std::string_view kName = "cohesion";
    struct Slot {
        CohesionParams cohesion;
    };
    static constexpr auto kParams = &Slot::cohesion;
    static constexpr std::array kKeys{
        ParamKey<CohesionParams>{.key = "slowing_distance", .meaning = "m, > 0", .lo = 1e-3f,
                                 .number = &CohesionParams::slowingDistanceM},
    };
    template <class Step, class Emit>
    static void request(const Step& step, const CohesionParams& p, Emit&& emit)
    {
        emit(cohere(step.self, step.near, p));
    }
};

}  // namespace throng::sim
