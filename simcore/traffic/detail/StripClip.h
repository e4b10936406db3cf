#pragma once
// Liang-Barsky clipping of a segment against an oriented strip (from `origin` along unit
// `dir` for `length` metres, `halfWidth` either side), shared by crosswalk stretches and
// kerb openings.
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>

namespace throng::sim::detail {

// The part of p0 -> p1 inside the strip as parameters [t0, t1] in [0, 1]; false when none.
inline bool clipToStrip(glm::vec2 p0, glm::vec2 p1, glm::vec2 origin, glm::vec2 dir, float length, float halfWidth,
                        float& t0, float& t1)
{
    const glm::vec2 side(dir.y, -dir.x), d = p1 - p0, rel = p0 - origin;
    const float pu = glm::dot(rel, dir), du = glm::dot(d, dir);
    const float pv = glm::dot(rel, side), dv = glm::dot(d, side);
    t0 = 0.0f;
    t1 = 1.0f;
    auto keep = [&](float q, float r) {  // keep where q * t <= r
        if (q == 0.0f)
            return r >= 0.0f;
        const float t = r / q;
        if (q < 0.0f)
            t0 = std::max(t0, t);
        else
            t1 = std::min(t1, t);
        return t0 <= t1;
    };
    return keep(-du, pu) && keep(du, length - pu) && keep(-dv, pv + halfWidth) && keep(dv, halfWidth - pv);
}

}  // namespace throng::sim::detail
