#pragma once
// How a frame of 1 / fps seconds is stepped. Below kMinPhysicsFps a frame is cut into
// equal sub-steps, so no step is longer than 1 / kMinPhysicsFps: a walker then moves at
// most a tenth of a body length (1.4 m/s at 24 fps is 6 cm against a 0.6 m body) before
// its neighbours and walls are looked at again. At 1 fps a walker took 1.4 m at a time,
// through anyone in its way, and one walker of a 40-walker room never left; at 12 fps a
// crowd left a room 7 % sooner than at 24 fps (issue 23). The World and the
// TrafficSystem step at the same rate.

#include <algorithm>
#include <cmath>

namespace throng::sim {

inline constexpr float kMinPhysicsFps = 24.0f;

// Steps per frame: 1 at 24 fps and above, 2 at 12 to 23.99 fps, 24 at 1 fps.
inline int subStepsPerFrame(float fps)
{
    if (!(fps > 0.0f) || !std::isfinite(fps))
        return 1;
    return std::max(1, int(std::ceil(kMinPhysicsFps / fps - 1e-4f)));
}

// The length of one step, s.
inline float physicsStepS(float fps)
{
    return 1.0f / (fps * float(subStepsPerFrame(fps)));
}

}  // namespace throng::sim
