#pragma once
// The exact bake of one agent's joints: its own gait, feet planted, at every joint frame, each
// joint's rotations (and the skeleton root's translation) reduced and written as its own
// channel. Baking is pure and may run on any thread; writing appends to the model.
#ifndef THRONG_EXPORT_BUILD
#error "a detail/ header, private to throng::export: include the module's public headers instead"
#endif

#include "export/character/FootPlanter.h"
#include "export/character/Gait.h"
#include "export/detail/AgentRig.h"
#include "export/detail/AnimationChannels.h"

namespace throng::exporting::detail {

struct JointClock {
    Clock clock;                        // times of the joint frames
    std::vector<std::uint32_t> frames;  // which recorded frames they are: every step-th and the last
};

// One agent's joint keys on the joint clock and the keys each channel keeps.
struct BakedJoints {
    std::vector<glm::vec3> rootTranslation;          // per joint frame
    std::vector<glm::quat> rotations;                // joint-major: joint j's keys at j * frames
    std::vector<std::uint32_t> rootKept;
    std::vector<std::vector<std::uint32_t>> kept;    // per joint
};

// The poses are the gait's with the feet planted on the terrain (FootPlanter), every
// recorded frame walked through so a foot's lock carries between joint frames.
BakedJoints bakeJoints(const JointClock& jointClock, const Character& character, const std::vector<GaitFrame>& gait,
                       const RootMotion& motion, const sim::Terrain& terrain, float toleranceM, float toleranceRad);
void writeJoints(AnimationChannels& channels, const JointClock& jointClock, const BakedJoints& baked, const AgentRig& rig);

}  // namespace throng::exporting::detail
