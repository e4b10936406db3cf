#pragma once
// The one list of the World's per-agent state arrays that a WorldState holds (used by
// WorldState.cpp and WorldStateRemap.cpp): a renamed or new array is added here.
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

// Per-agent arrays of the World (m_agents.NAME, AgentColumns.h) and of the WorldState
// (NAME), copied whole.
#define THRONG_AGENT_COLUMNS(X)                                                                                        \
    X(pos)                                                                                                             \
    X(vel) X(fwd) X(side) X(up) X(nextPos) X(nextVel) X(nextFwd) X(nextSide) X(nextUp) X(resolvedPos) X(wander)        \
        X(nextWander) X(radius) X(maxSpeed) X(phase) X(stride) X(arrivalTime) X(goal) X(path) X(leader) X(goalSpot)    \
            X(pathAlong) X(escaping) X(escapeTo) X(arrived) X(stopped) X(stoppedBefore) X(onCrosswalk) X(nearCount)    \
                X(out) X(offstage) X(unstarted) X(nearIndex) X(heldForce) X(pointAt) X(pointLast) X(pointLeftS)

// Per-agent navigation arrays (m_nav.NAME in the World).
#define THRONG_NAV_COLUMNS(X)                                                                                          \
    X(plan, plan)                                                                                                      \
    X(planGoal, planGoal) X(waypoint, waypoint) X(waypointRadiusM, waypointRadiusM) X(sideStepS, sideStepS)            \
        X(stall, stall) X(replan, replan) X(hasTarget, hasTarget) X(waiting, waiting) X(waitingNext, waitingNext)      \
            X(lostSteps, lostSteps) X(sideDir, sideDir) X(target, target) X(mode, navMode) X(noWay, noWay)

// Whole members of the World (its member expression) and of the WorldState (NAME),
// copied as they are by saveState. restoreDynamicState puts back those marked Plain as
// they are; the others (Kept) it puts back by the rule written there (a traffic system
// only into a World that has one, the plan grid and cache only onto the same cells).
#define THRONG_WHOLE_MEMBERS(X)                                                                     \
    X(m_clock.step, step, Plain) X(m_count.counters(), counters, Plain) X(m_traffic.system, trafficSystem, Kept)  \
    X(m_traffic.signal, signal, Plain) X(m_traffic.before, pedestriansBefore, Plain)                \
    X(m_traffic.after, pedestriansAfter, Plain) X(m_nav.counters, navCounters, Plain)               \
    X(m_nav.grid, navGrid, Kept) X(m_nav.cache, planCache, Kept) X(m_grid, grid, Kept)              \
    X(m_gridCurrent, gridCurrent, Kept)

// Brain members of the World's WorldBrains (wb.NAME) and of the WorldState (STATE), saved
// as they are; restoreDynamicState takes them agent by agent (memory, actions) or by tag.
#define THRONG_BRAIN_MEMBERS(X)                                                                      \
    X(batch, brainBatch) X(local, brainLocal) X(action, brainAction) X(tags, tags) X(tagValues, tagValues) \
    X(vehicleSpeed, vehicleSpeed)
