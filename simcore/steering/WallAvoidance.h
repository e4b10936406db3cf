#pragma once
// Wall avoidance and wall following (Reynolds 1999) for vertical wall segments: feelers brake
// the approach to walls ahead, a standoff term holds the agent off near walls even against
// other forces. Pure; zero with no wall near or approached; never moves the agent or allocates.

#include "simcore/steering/BehaviourKey.h"
#include "simcore/steering/SteeringAgent.h"
#include "simcore/steering/SteeringGeometry.h"

#include <glm/vec3.hpp>

#include <span>
#include <array>
#include <string_view>

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

// Wall following (Reynolds 1999): an agent whose way leads into a nearby wall travels
// along it toward the end nearer its way, instead of pressing against its face (the local
// minimum a goal straight behind a wall makes). Zero when no wall is in the way.
glm::vec3 slideAlongWall(const SteeringAgent& agent, std::span<const WallSegment> walls, glm::vec3 target,
                         const WallAvoidanceParams& params);

// Wall following's entry in the behaviour list (BehaviourTable.h): two requests, the
// feelers' and the slide along the wall in the way, when walls are within the feelers.
struct WallFollowingBehaviour {
    static constexpr std::string_view kName = "wall_following";
    struct Slot {
        WallAvoidanceParams walls;
    };
    static constexpr auto kParams = &Slot::walls;
    using P = WallAvoidanceParams;
    static constexpr std::array kKeys{
        ParamKey<P>{.key = "feeler_length", .meaning = "m, >= 0: feeler when standing", .number = &P::feelerMinM},
        ParamKey<P>{.key = "lookahead", .meaning = "s, >= 0: extra feeler per m/s", .number = &P::feelerLookaheadS},
        ParamKey<P>{.key = "feeler_angle", .meaning = "degrees, 0..90: side feelers' angle",
                    .kind = ParamKind::AngleDeg, .hi = 90, .number = &P::sideFeelerAngleRad},
        ParamKey<P>{.key = "standoff", .meaning = "m, > 0: gap below which a wall pushes back", .lo = 1e-3f,
                    .number = &P::standoffM},
    };
    template <class Step, class Emit>
    static void request(const Step& step, const WallAvoidanceParams& p, Emit&& emit)
    {
        const float reach = p.feelerMinM + p.feelerLookaheadS * step.self.speed() + p.standoffM + step.self.radius;
        step.withWallsNear(reach, [&](std::span<const WallSegment> walls) {
            emit(avoidWalls(step.self, walls, p, &step.goal));
            emit(slideAlongWall(step.self, walls, step.goal, p));
        });
    }
};

}  // namespace throng::sim
