#pragma once
// Small geometry shared by the step's phases (MovePhase.cpp, Steer.cpp, ...), with the
// planar segment tests of base/detail/PlanarSegments.h, the vector helpers of
// steering/detail/SteeringMath.h and the step's constants (StepConstants.h). Internal to simcore/world; inline, no state.
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include "simcore/base/Atan2.h"
#include "simcore/base/detail/PlanarSegments.h"
#include "simcore/steering/detail/SteeringMath.h"
#include "simcore/world/detail/StepConstants.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace throng::sim::detail {

// An agent's own spot in its goal's disk (centre, radius) from two uniform draws u, v in
// [0, 1): uniform over 80 % of the disk, so a crowd sharing a goal spreads over it instead
// of converging on one point. For an exit, over 80 % of the disk less the body's radius:
// a disk placed across a door as wide as itself has its rim on the door posts, and a walker
// aiming at a spot near the rim pressed into the wall beside the door, just outside the
// disk, for good (issue 23).
inline glm::vec2 goalSpot(glm::vec2 centre, float radiusM, bool exit, float bodyRadiusM, float u, float v)
{
    const float reach = exit ? std::max(0.0f, radiusM - bodyRadiusM) : radiusM;
    const float r = 0.8f * reach * std::sqrt(u);
    const float a = 6.28318531f * v;
    return centre + r * glm::vec2(std::cos(a), std::sin(a));
}

// The bearings of offsets (dx, dy) on the ground from the unit heading f, in degrees, + =
// to the left: dot(d, left) and dot(d, f) with left = (f.y, -f.x), in glm::dot's order, and
// the angle by Throng's own atan2 (base/Atan2.h), lane by lane. bearingDeg for one offset
// gives what its lane does.
template <class F>
[[gnu::always_inline]] inline F bearingsDeg(glm::vec2 f, F dx, F dy)
{
    const F side = dx * f.y + dy * -f.x, ahead = dx * f.x + dy * f.y;
    return simd::atan2Of(side, ahead) * 57.295779513082320876798154814105f;  // glm::degrees
}
inline float bearingDeg(glm::vec2 f, glm::vec2 d)
{
    return bearingsDeg(f, d.x, d.y);
}

}  // namespace throng::sim::detail
