#pragma once
// The headway rule (the collision-free speed model: Tordeux, Chraibi and Seyfried 2016): a
// walker goes no faster than lets it stop in time behind the body in its way, its speed at
// most the free gap ahead over a time gap T. In single file it gives the linear relation
// Seyfried et al. (2005) measured between speed and spacing, d = l + T v (l the bodies'
// length, 0.36 m; T 1.06 s). Pure: no state.

#include "simcore/steering/Neighbour.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <span>

namespace throng::sim {

// How far a body of radius `radius` at `p` can go along the unit direction `way` before it
// touches one of `near` (their centres on the ground, x and z); `reachM` when none is in
// the way within it. A neighbour is in the way when its disc meets the strip the body
// sweeps; the gap is to the point of contact, so one straight ahead leaves the centres'
// distance less both radii.
inline float freeGapAhead(glm::vec2 p, float radius, glm::vec2 way, std::span<const Neighbour> near, float reachM)
{
    float gap = reachM;
    for (const Neighbour& n : near) {
        const glm::vec2 d = glm::vec2(n.position.x, n.position.z) - p;
        const float along = glm::dot(d, way);
        if (along <= 0.0f)
            continue;  // beside or behind
        const float across = way.x * d.y - way.y * d.x;
        const float reach = radius + n.radius;
        if (std::abs(across) >= reach)
            continue;  // the body passes it by
        gap = std::min(gap, along - std::sqrt(reach * reach - across * across));
    }
    return std::max(gap, 0.0f);
}

// The fastest a walker with `timeGapS` (> 0) may go with `gapM` free ahead, capped at its
// top speed.
inline float headwaySpeed(float gapM, float timeGapS, float maxSpeed)
{
    return std::min(maxSpeed, gapM / timeGapS);
}

}  // namespace throng::sim
