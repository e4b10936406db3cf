#pragma once
// The steer phase of the general path: what an agent's type's behaviours ask of it, from
// what it senses, combined by blending or prioritised allocation, then reciprocal
// avoidance on the ground. Functions over the StepView that read only the previous state
// and write nothing (Steer.cpp); the move phase (MovePhase.cpp) integrates what they return, and the
// walker kernel and describeAgent call them too.

#include "simcore/steering/Neighbour.h"
#include "simcore/steering/SteeringAgent.h"
#include "simcore/steering/SteeringRequestList.h"
#include "simcore/steering/Wander.h"
#include "simcore/world/TypeSteering.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <span>

namespace throng::sim {

class BrainPhase;
class DebugSink;
struct StepView;

// Every behaviour agent i's type runs, in priority order, combined; the new wander state
// goes out. `sink`, when given, hears each behaviour's force (describeAgent); null in
// the step.
glm::vec3 steer(const StepView& v, const BrainPhase& brains, std::size_t i, const SteeringAgent& self,
                std::span<const Neighbour> near, WanderState& wanderOut, DebugSink* sink = nullptr);
// Wall following's and obstacle avoidance's requests, in steer's order (after
// containment); the walker kernel adds the same. Nothing without walls or obstacles.
void steerAroundStatics(const StepView& v, const BrainPhase& brains, std::size_t i, const SteeringAgent& self,
                        glm::vec3 goal, SteeringRequestList& requests, DebugSink* sink = nullptr);
// The neighbours agent i avoids: all but those of lower priority, which make way for it
// (`buffer` holds them when some are left out).
std::span<const Neighbour> neighboursToAvoid(const StepView& v, std::size_t i, std::span<const Neighbour> near,
                                             Neighbour* buffer);
// Reciprocal avoidance (ORCA) on the ground: the force that turns the blend's wish into
// the nearest velocity that touches no neighbour within the horizon.
glm::vec3 avoidReciprocally(const StepView& v, std::size_t i, const SteeringAgent& self, glm::vec3 force,
                            std::span<const Neighbour> near, const TypeSteering& s);

}  // namespace throng::sim
