#pragma once
// Wall avoidance and wall following (Reynolds 1999) for vertical wall segments: feelers brake
// the approach to walls ahead, a standoff term holds the agent off near walls even against
// other forces. Pure; zero with no wall near or approached; never moves the agent or allocates.

#include "simcore/steering/SteeringAgent.h"
#include "simcore/steering/SteeringGeometry.h"

#include <glm/vec3.hpp>

#include <span>

namespace throng::sim {

struct WallAvoidanceParams {
    float feelerMinM = 0.5f;          // m, >= 0: feeler length when standing still
    float feelerLookaheadS = 1.0f;    // s, >= 0: extra feeler length per m/s of speed
    float sideFeelerAngleRad = 0.6f;  // rad, [0, pi/2]: angle of the two half-length side feelers
    float standoffM = 0.5f;           // m, > 0: S, body-to-wall gap below which the wall pushes back
    float standoffGain = 2.0f;        // >= 0: standoff force at contact, in units of maxForce
    float dampingTimeS = 0.25f;       // s, > 0: time constant that damps motion along the normal at contact
};

// Both terms push along the wall's normal at the agent's closest point, toward the agent:
//   feeler term   for each wall a feeler meets (one along the heading at full length, two to the
//                 sides at half length) and that the agent approaches at normal speed v, the force
//                 that stops the approach just before the body touches: mass * v^2 / (2 d), with d
//                 the body-to-wall gap (floored at 1 cm) - the sooner the contact, the steeper;
//   standoff term standoffGain * maxForce * (S - d) / S for each wall with gap d < S, minus a
//                 damping mass * (normal velocity) / dampingTimeS faded in over the same zone. With
//                 the default gain 2, another behaviour pushing with the whole budget maxForce is
//                 held at d = S / 2 and settles there.
// At a door post (a wall's end that no other wall in the list shares) the standoff term never
// pushes back along the agent's way: the way to `target` where one is given, else its heading.
// An agent exactly on a wall is pushed back against its heading. Not truncated.
glm::vec3 avoidWalls(const SteeringAgent& agent, std::span<const WallSegment> walls,
                     const WallAvoidanceParams& params = {}, const glm::vec3* target = nullptr);

}  // namespace throng::sim
