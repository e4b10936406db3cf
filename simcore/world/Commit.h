#pragma once
// The commit phase: each agent's gait advances by the distance it walked (so its feet do
// not slide), a walker that crosses a wall is counted, its arrival and its stop are noted
// (at the end of an open path, on its spot in its goal, through an exit, or against the
// pile of those who stopped before it), and the next state becomes the state. No copying:
// every path of the step (stopped, boids, walkers, the general one, traffic and heroes
// over those) writes all six next columns of every agent, so the old state the swap
// leaves in the next* columns is never read before it is overwritten (Commit.cpp).

#include "simcore/world/AgentColumns.h"

#include <cstdint>

namespace throng::sim {

struct StepView;

struct CommitCounts {
    std::uint64_t wallCrossings = 0;  // walkers' moves this step that crossed a wall
    std::uint64_t nonFinite = 0;      // agents whose new position or velocity is not a number
};

// Writes the agents' phase, escaping, pathAlong, arrived, arrivalTime, stopped,
// stoppedBefore and out, a stopping agent's next velocity, and swaps the next state in.
CommitCounts commit(const StepView& v, AgentColumns& agents);

}  // namespace throng::sim
