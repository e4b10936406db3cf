#pragma once
// The World's agents as structure of arrays: one column per attribute, by dense agent
// index. The step's phases read the current columns and write the next ones (m_next* in
// the step being computed); World::step swaps them in at its end. WorldState saves and
// restores these columns (detail/WorldStateColumns.h lists them).

#include "simcore/steering/Wander.h"
#include "simcore/world/FrameCache.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace throng::sim {

// Most neighbours one agent perceives (the nearest ones in its perception cone);
// DetourCrowd uses 6.
inline constexpr std::size_t kMaxNeighbours = 8;

struct AgentColumns {
    std::vector<AgentInfo> info;
    // The state; next*: the step being computed.
    std::vector<glm::vec3> pos, vel, fwd, side, up;
    std::vector<glm::vec3> nextPos, nextVel, nextFwd, nextSide, nextUp;
    std::vector<WanderState> wander, nextWander;
    // The steering force a walker decided on at the last decision (StepRate.h), applied
    // at every step until the next.
    std::vector<glm::vec3> heldForce;
    std::vector<float> radius, maxSpeed, phase, stride, arrivalTime;
    std::vector<std::int32_t> goal, path, leader;
    std::vector<glm::vec2> goalSpot;  // each agent's own point inside its goal's disk
    // Path followers: how far along their path's spine they have come, m (never back; see
    // advancePathProgress), so a hairpin's walked leg never draws them back. 0 without a path.
    std::vector<float> pathAlong;
    // Started inside a wall or obstacle and not yet out: walks straight to escapeTo
    // (clear of every shape) at its own pace, through what holds it (Constraints.h).
    std::vector<std::uint8_t> escaping;
    std::vector<glm::vec2> escapeTo;
    // arrived: entered its goal's area or reached its path's end (the stats' figure);
    // stopped: frozen for good (see World::commit); stoppedBefore: stopped as the commit
    // phase began.
    std::vector<std::uint8_t> arrived, stopped, stoppedBefore, onCrosswalk;
    std::vector<std::uint32_t> nearIndex;  // kMaxNeighbours per agent: whom it sensed this step
    std::vector<std::uint8_t> nearCount;
    std::vector<glm::vec3> resolvedPos;     // the collide pass's result
    std::vector<std::uint8_t> contactMoved;  // per step: moved by the contact rounds
    std::vector<std::uint8_t> out;           // left through an exit: never simulated or perceived again
    // A source's agent whose time has not come (or whose place is taken): out and stopped
    // as well until the source phase lets it in (Sources.h); not present in frames.
    std::vector<std::uint8_t> offstage;
    // A walker still standing out its reaction time: stopped as well until the start phase
    // lets it go (StartPhase.h); not the pile of an arrived crowd.
    std::vector<std::uint8_t> unstarted;
    // Action points (ActionPoints.h): the point it plays at now (-1 = none) and for how
    // many seconds more; the last point it entered, until it leaves that point's disk.
    std::vector<std::int32_t> pointAt, pointLast;
    std::vector<float> pointLeftS;

    std::size_t size() const { return pos.size(); }
};

}  // namespace throng::sim
