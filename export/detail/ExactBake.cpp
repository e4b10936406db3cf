#include "export/detail/ExactBake.h"

namespace throng::exporting::detail {

void bakeJointsExact(AnimationChannels& channels, const JointClock& jc, const Character& c,
                     const std::vector<GaitFrame>& gait, const AgentRig& rig, float toleranceM, float toleranceRad)
{
    const std::size_t keys = jc.frames.size(), joints = c.joints.size();
    std::vector<glm::vec3> rootTranslation(keys);
    std::vector<glm::quat> rotations(joints * keys);  // joint-major
    for (std::size_t k = 0; k < keys; ++k) {
        const Pose pose = gaitPose(c, gait[jc.frames[k]]);
        rootTranslation[k] = pose.rootTranslation;
        for (std::size_t j = 0; j < joints; ++j) {
            glm::quat q = pose.rotations[j];
            // q and -q are one rotation; neighbours in one hemisphere interpolate the short way.
            if (k > 0 && glm::dot(q, rotations[j * keys + k - 1]) < 0.0f)
                q = -q;
            rotations[j * keys + k] = q;
        }
    }
    channels.vec3Channel(rig.firstJoint, "translation", jc.clock, rootTranslation, toleranceM);
    for (std::size_t j = 0; j < joints; ++j)
        channels.rotationChannel(rig.firstJoint + static_cast<int>(j),
                                 std::span<const glm::quat>(rotations.data() + j * keys, keys), jc.clock, toleranceRad);
}

}  // namespace throng::exporting::detail
