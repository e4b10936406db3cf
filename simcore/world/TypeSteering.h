#pragma once
// An agent type's steering, compiled from the scene: which behaviours run, their
// weights (or priority order) and parameters, and the vehicle model's settings. Built
// once per World; read-only during a step.

#include "simcore/scene/BehaviourTable.h"
#include "simcore/scene/Scene.h"
#include "simcore/steering/Steering.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace throng::sim {

// The behaviours' parameters come from the behaviour list (BehaviourTable.h): one member
// per behaviour, named by its descriptor's Slot (`seek`, `walls`, `obstacles`, ...).
struct TypeSteering : BehaviourParamsOf<BehaviourList> {
    std::array<float, kBehaviourCount> weight{};  // >= 0; 0 = the behaviour does not run
    bool priority = false;                        // prioritised allocation instead of blending
    VehicleParams vehicle;
    // cos and sin of the keep-right turn for 1, 2 and 3 or more oncoming walkers
    // (computed once here, not per agent per step).
    std::array<glm::vec2, 3> keepRightTurn{};

    float w(Behaviour b) const { return weight[std::size_t(b)]; }
    bool on(Behaviour b) const { return weight[std::size_t(b)] > 0.0f; }
    float weightIfOn(Behaviour b) const { return on(b) ? w(b) : 0.0f; }
};

// Builds a type's steering from its scene description. A type that names no behaviours
// gets the defaults for its kind: pedestrians arrival, path following, separation,
// unaligned collision avoidance, obstacle and wall avoidance, containment, reciprocal
// avoidance; vehicles the force behaviours without unaligned avoidance; fliers boids
// (separation, alignment, cohesion) with containment, a light pull to their goal or path,
// and a little wander.
TypeSteering compileTypeSteering(const AgentType& type);

// Parameters a behaviour accepts in the scene file, for the reader's checks and the docs.
struct BehaviourParamInfo {
    const char* behaviour;
    const char* key;
    const char* meaning;  // with unit and range
};
const std::vector<BehaviourParamInfo>& behaviourParams();
// Checks one behaviour parameter; returns an error message, empty when fine.
std::string checkBehaviourParam(const std::string& behaviour, const BrainParam& param);

}  // namespace throng::sim
