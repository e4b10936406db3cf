#pragma once
// Hard constraints (Constraints.cpp): no body ends a step inside a wall or obstacle. Pure
// functions of the set (and, for constrain, of the agent's own columns), for every phase
// that moves a body: steering, the collide pass and its contact rounds, the walker
// kernel, traffic.

#include "simcore/world/AgentColumns.h"
#include "simcore/world/StaticSet.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>

namespace throng::sim {

// Holds a body of radius r that moves from `from` to `to` out of the set: a move that
// would cross a wall stops where it started (no tunnelling at any speed), then the body is
// pushed out of the walls and circles it overlaps (two passes settle corners). Changes
// only to.x and to.z.
void holdOut(const StaticSet& set, glm::vec3 from, glm::vec3& to, float r);
// Agent i's move from `from` to `to`, held out of the set; or, for an agent that started
// inside a wall or obstacle and is still walking out (agents.escaping), its move toward
// agents.escapeTo at its own pace (at least 0.5 m/s) over dt seconds, through what holds it.
void constrain(const AgentColumns& agents, const StaticSet& set, float dt, std::size_t i, glm::vec3 from,
               glm::vec3& to);
// Where a body of radius r at p gets out of the walls and obstacles it overlaps: the
// shortest way out of the deepest overlap, repeated while that leads into another (at
// most 8 rounds), 2 cm clear. True when that way is longer than r: p lies inside one.
bool escapeTarget(const StaticSet& set, glm::vec2 p, float r, glm::vec2& out);
// Whether wall segment s is a side of a box obstacle whose inside holds p (the commit
// does not count an escaping agent's move out through it as a wall crossing).
bool sideOfBoxAround(const StaticSet& set, const Segment& s, glm::vec2 p);

}  // namespace throng::sim
