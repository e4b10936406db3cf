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

// Walkers decide (steer and avoid) at most kDecisionsPerS times a second, at the first
// step at or after each 1/kDecisionsPerS of simulated time, and between decisions apply
// the force they decided on. Deciding at every step of 1/240 s, ORCA's velocity for the
// next step was hardly a change of the current one, and a crowd stood where at 24 fps it
// walked on: 120 walkers left a room in 101 s at 240 fps against 76 s at 24 fps.
inline constexpr double kDecisionsPerS = 24.0;

// Whether step `step` (0 = the first, each of stepS seconds) begins with a decision.
inline bool decisionAt(unsigned long long step, double stepS)
{
    if (step == 0 || !(stepS * kDecisionsPerS < 1.0 - 1e-9))
        return true;
    auto interval = [&](unsigned long long s) { return std::floor(double(s) * stepS * kDecisionsPerS + 1e-6); };
    return interval(step) > interval(step - 1);
}

// The time from decision step `step` to the next decision, s.
inline double decisionIntervalS(unsigned long long step, double stepS)
{
    unsigned long long next = step + 1;
    while (!decisionAt(next, stepS) && next < step + 1000000ull)
        ++next;
    return double(next - step) * stepS;
}

// The length of one step, s.
inline float physicsStepS(float fps)
{
    return 1.0f / (fps * float(subStepsPerFrame(fps)));
}

}  // namespace throng::sim
