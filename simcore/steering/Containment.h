#pragma once
// Containment (Reynolds 1999): probe points ahead of and beside the agent are tested
// against a walkable region; when one is outside, steer along the surface normal back in.
// Pure; zero while every probe is inside; never moves the agent or allocates.

#include "simcore/steering/SteeringAgent.h"
#include "simcore/steering/SteeringGeometry.h"

#include <glm/vec3.hpp>

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

}  // namespace throng::sim
