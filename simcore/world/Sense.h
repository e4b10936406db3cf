#pragma once
// The sense phase's queries (Sense.cpp), for every path of the step: the general one, the
// boids and walker kernels, the brains' senses and describeAgent. They read only the
// previous state.

#include "simcore/steering/Neighbour.h"
#include "simcore/steering/SteeringAgent.h"
#include "simcore/world/AgentColumns.h"
#include "simcore/world/AgentTypes.h"
#include "simcore/world/StepView.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>

namespace throng::sim {

// Agent i as the steering functions see it.
SteeringAgent steeringAgent(const AgentColumns& agents, const AgentTypes& types, std::size_t i);
// The nearest kMaxNeighbours agents within agent i's perception radius and view cone
// (Reynolds 1987; a touching one is always felt), nearest first, ties by id (TieOrder.h),
// so the choice depends neither on the grid's order nor on the World's; those of higher
// priority first when types make way (WorldPriority.h). Writes their indices to indices,
// and them (their state) to out unless it is null; returns how many.
std::size_t gatherNeighbours(const StepView& v, std::size_t i, Neighbour* out, std::uint32_t* indices);
// The kernels' first search bound: agents move little in a step, so last step's k
// nearest of agent i, where they are now, bound its k-th nearest from above (squared;
// perception2 when it had fewer than k).
float lastNearestBound(const AgentColumns& agents, std::size_t i, glm::vec3 p, float perception2);
// The flow at p that flow-field following steers along: the sketched field's where it
// solved, else the direction of the nearest stroke segment whose band holds p (zero
// outside every band).
glm::vec3 flowDirection(const StepView& v, glm::vec3 p);
// Where agent i wants to go, as a direction on the ground (not normalised): 2 m ahead
// along its path from the nearest point of it (even while it stands or rounds a corner),
// else toward its goal's navigation target, else its velocity or, standing, its heading.
// Signals and the brains' stop-line sense read it.
glm::vec2 wantedHeading(const StepView& v, std::size_t i);

}  // namespace throng::sim
