#pragma once
// Containment (Reynolds 1999): probe points ahead of and beside the agent are tested
// against a walkable region; when one is outside, steer along the surface normal back in.
// Pure; zero while every probe is inside; never moves the agent or allocates.

#include "simcore/steering/BehaviourKey.h"
#include "simcore/steering/SteeringAgent.h"
#include "simcore/steering/SteeringGeometry.h"

#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <string_view>

namespace throng::sim {

struct ContainmentParams {
    float probeMinM = 0.5f;          // m, >= 0: length of the ahead probe when standing still
    float probeLookaheadS = 1.0f;    // s, >= 0: extra probe length per m/s of speed
    float sideProbeAngleRad = 0.6f;  // rad, [0, pi/2]: side probes' angle from the heading
    float sideProbeFraction = 0.5f;  // [0, 1]: side probes' length relative to the ahead probe
};

// Probes: the agent's own position, one straight ahead and one to each side. For each probe
// outside, the direction from it to the nearest point of the region (the inward surface normal
// where it left) is summed; the force is maxForce along that sum.
glm::vec3 stayInside(const SteeringAgent& agent, const WalkableBox& region, const ContainmentParams& params = {});

// The same for a polygon in the ground plane (probes are tested by their (x, z)).
glm::vec3 stayInside(const SteeringAgent& agent, const WalkablePolygon& region, const ContainmentParams& params = {});

// Containment's entry in the behaviour list (BehaviourTable.h). Only agents whose probes
// can reach the bounds ask; the rest are far inside.
struct ContainmentBehaviour {
    static constexpr std::string_view kName = "containment";
    struct Slot {
        ContainmentParams containment;
    };
    static constexpr auto kParams = &Slot::containment;
    static constexpr std::array kKeys{
        ParamKey<ContainmentParams>{.key = "probe_length", .meaning = "m, >= 0: probe when standing",
                                    .number = &ContainmentParams::probeMinM},
        ParamKey<ContainmentParams>{.key = "lookahead", .meaning = "s, >= 0: extra probe per m/s",
                                    .number = &ContainmentParams::probeLookaheadS},
    };
    template <class Step, class Emit>
    static void request(const Step& step, const ContainmentParams& p, Emit&& emit)
    {
        const SteeringAgent& self = step.self;
        if (probesReach(self.position, self.speed(), self.radius, step.bounds(), p, step.flying))
            emit(stayInside(self, step.bounds(), p));
    }
    // Whether an agent at `position`, moving at `speed`, lies nearer a face of the bounds
    // than its probe and body reach (else it asks nothing: every probe is inside). The
    // walker kernel asks the same.
    static bool probesReach(glm::vec3 position, float speed, float radius, const WalkableBox& bounds,
                            const ContainmentParams& p, bool flying)
    {
        const float probe = p.probeMinM + p.probeLookaheadS * speed + radius;
        const glm::vec3 lo = position - bounds.min, hi = bounds.max - position;
        const float nearest = flying ? std::min({lo.x, lo.y, lo.z, hi.x, hi.y, hi.z})
                                     : std::min({lo.x, lo.z, hi.x, hi.z});  // walkers ignore height
        return nearest < probe;
    }
};

}  // namespace throng::sim
