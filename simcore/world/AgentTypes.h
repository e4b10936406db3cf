#pragma once
// A World's agent types as the step reads them, one entry per Scene::agentTypes entry:
// body and vehicle figures, compiled steering, collision layers and the keep-right share.
// Built once with the World (World.cpp); read-only during a step.

#include "simcore/scene/Scene.h"
#include "simcore/world/TypeSteering.h"
#include "simcore/world/WorldPriority.h"

#include <vector>

namespace throng::sim {

struct TypeParams {
    float radius, maxSpeed, maxForce, mass, perception;
    float cosHalfView;  // view cone: cos(view angle / 2); -1 = all round
    AgentKind kind;
};

struct AgentTypes {
    std::vector<TypeParams> params;
    std::vector<TypeSteering> steering;
    std::vector<TypeCollision> collision;  // layers and priority
    // The share of max force a pedestrian that keeps its distance (separation) but looks
    // no further ahead (neither unaligned nor reciprocal avoidance) steps right with, an
    // oncoming walker in its way (KeepRight.h); 0 for every other type.
    std::vector<float> keepRight;
    std::vector<glm::vec2> ageYears;  // the variation's age range ([0, 0] = no age; WalkingAge.h)
    std::vector<float> timeGapS;      // walkers' headway rule (steering/Headway.h); 0 = none
    bool makingWay = false;  // some types differ in layers or priority (else all collide as equals)
};

}  // namespace throng::sim
