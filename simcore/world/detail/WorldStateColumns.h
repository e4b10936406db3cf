#pragma once
// The one list of the World's per-agent state arrays that a WorldState holds (used by
// WorldState.cpp and WorldStateRemap.cpp): a renamed or new array is added here.

// Per-agent arrays of the World (m_NAME) and of the WorldState (NAME), copied whole.
#define THRONG_AGENT_COLUMNS(X)                                                                          \
    X(pos) X(vel) X(fwd) X(side) X(up) X(nextPos) X(nextVel) X(nextFwd) X(nextSide) X(nextUp)             \
    X(resolvedPos) X(wander) X(nextWander) X(radius) X(maxSpeed) X(phase) X(stride) X(arrivalTime) X(goal) \
    X(path) X(leader) X(goalSpot) X(arrived) X(stopped) X(stoppedBefore) X(onCrosswalk) X(nearCount)     \
    X(out) X(nearIndex)

// Per-agent navigation arrays (m_nav.NAME in the World).
#define THRONG_NAV_COLUMNS(X)                                                                             \
    X(plan, plan) X(planGoal, planGoal) X(waypoint, waypoint) X(waypointRadiusM, waypointRadiusM)          \
    X(sideStepS, sideStepS) X(stall, stall) X(replan, replan) X(hasTarget, hasTarget) X(waiting, waiting) \
    X(waitingNext, waitingNext) X(lostSteps, lostSteps) X(sideDir, sideDir) X(target, target) X(mode, navMode)

