#pragma once
// Small pure helpers the World uses to follow a plan: a per-agent waypoint radius (so a
// group does not turn on one line), waypoint advance, and a stall watch that says when to
// re-plan or side-step (no progress toward the goal for a while). Never plans, never allocates.

#include <glm/vec2.hpp>

#include <cstddef>
#include <limits>
#include <span>

namespace throng::sim {

// baseM * (1 + spread * (2 * u01 - 1)): u01 in [0, 1] from the agent's rng, spread in [0, 1].
float waypointRadiusM(float baseM, float u01, float spread = 0.5f);

// The waypoint index to steer to: index advanced past every waypoint (except the last)
// that position is within radiusM of. index >= waypoints.size() stays as it is.
std::size_t advanceWaypoint(std::span<const glm::vec2> waypoints, std::size_t index, glm::vec2 position, float radiusM);

struct StallParams {
    float minProgressM = 0.5f;  // m, > 0: getting this much closer to the goal counts as progress
    float patienceS = 3.0f;     // s, > 0: time without progress before the agent is stalled
};

struct StallWatch {
    float bestDistanceM = std::numeric_limits<float>::infinity();  // closest to the goal so far
    float sinceProgressS = 0.0f;
};

// Feeds one step: distanceToGoalM now, dtS the step. Returns true once (then restarts the
// watch) when the agent has been patienceS without getting minProgressM closer: re-plan
// from the agent's current cell, or side-step.
bool updateStall(StallWatch& watch, float distanceToGoalM, float dtS, const StallParams& params = {});

}  // namespace throng::sim
