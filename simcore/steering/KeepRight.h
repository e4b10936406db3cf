#pragma once
// Keeping right of oncoming walkers, for pedestrians that keep their distance (separation)
// and do not avoid reciprocally (ORCA keeps right its own way, ReciprocalAvoidance.h). A
// walker with an oncoming walker in its way, less than kKeepRightAheadM ahead and nearer its
// line than the two bodies plus kKeepRightClearM, steps to its right with a share of its max
// force (World: separation's keep_right, a quarter of it for a type that also runs
// unaligned collision avoidance, which dodges sideways itself). Crowds that meet head-on
// then form lanes; without it, walkers pressed face to face until one squeezed through the
// other, and with bodies that no longer squeeze through each other (issue 23) a 3 m
// sidewalk with 20 walkers each way stood still, and 120 walkers of the default behaviours
// crossing a 25 m ring to the far side jammed in its middle (14 arrived in 120 s). Pure,
// shared by World's general path and its walker kernel.

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>

namespace throng::sim {

inline constexpr float kKeepRightAheadM = 2.0f;
inline constexpr float kKeepRightClearM = 0.1f;
inline constexpr float kKeepRightOncomingMps = 0.2f;

// Whether a walker at q facing fwdJ and moving at velJ (radius rJ) comes the other way, at
// more than kKeepRightOncomingMps, in the way of one at p facing fwd (radius r). Facings are
// on the ground (y = 0) and of unit length. (One that stands facing this way, turned by the
// press of a crowd at a door, is not oncoming: counted, it set a whole jam stepping aside.)
inline bool oncomingInTheWay(glm::vec3 p, glm::vec3 fwd, float r, glm::vec3 q, glm::vec3 fwdJ, glm::vec3 velJ, float rJ)
{
    const glm::vec3 d = q - p;
    const float ahead = glm::dot(d, fwd);
    const float across = d.z * fwd.x - d.x * fwd.z;  // along the walker's right, (-fwd.z, 0, fwd.x)
    return ahead > 0.0f && ahead < kKeepRightAheadM && std::fabs(across) < r + rJ + kKeepRightClearM &&
           glm::dot(fwdJ, fwd) < -0.5f && glm::dot(velJ, fwd) < -kKeepRightOncomingMps;
}

// The step to the right: `share` (0..1) of the max force, across the facing.
inline glm::vec3 keepRightForce(glm::vec3 fwd, float maxForce, float share)
{
    return glm::vec3(-fwd.z, 0.0f, fwd.x) * (maxForce * share);
}

}  // namespace throng::sim
