#pragma once
// Where a World is in time: the steps taken, their length, the sub-steps per frame below
// 24 fps, and whether this step decides (steers and avoids) or applies the forces decided
// (StepRate.h). Plain data, set by World::build and advanced by World::stepOnce.

#include <cstdint>

namespace throng::sim {

struct StepClock {
    std::uint64_t step = 0;         // steps taken, subSteps per frame
    float frameDt = 1.0f / 24.0f;   // a frame's length, s (1 / fps)
    int subSteps = 1;               // steps per frame (1 from 24 fps up)
    float dt = 1.0f / 24.0f;        // one step's length, s (a frame's below 24 fps: StepRate.h)
    bool decide = true;             // this step decides; else it applies the held forces
    float decideDt = 1.0f / 24.0f;  // s until the next decision (decisionAt, StepRate.h)

    std::uint64_t frame() const { return step / std::uint64_t(subSteps); }
    double timeS() const { return double(step) * double(dt); }
};

}  // namespace throng::sim
