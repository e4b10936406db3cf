#pragma once
// The exact bake of one agent's joints: its own gait evaluated at every joint frame, each
// joint's rotations (and the skeleton root's translation) reduced and written as its own
// channel. Writes animation data only.

#include "export/character/Gait.h"
#include "export/detail/AgentRig.h"
#include "export/detail/AnimationChannels.h"

namespace throng::exporting::detail {

struct JointClock {
    Clock clock;                        // times of the joint frames
    std::vector<std::uint32_t> frames;  // which recorded frames they are: every step-th and the last
};

void bakeJointsExact(AnimationChannels& channels, const JointClock& jointClock, const Character& character,
                     const std::vector<GaitFrame>& gait, const AgentRig& rig, float toleranceM, float toleranceRad);

}  // namespace throng::exporting::detail
