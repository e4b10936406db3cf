#include "export/detail/ExactBake.h"

#include "export/detail/KeyReduction.h"

namespace throng::exporting::detail {

BakedJoints bakeJoints(const JointClock& jc, const Character& c, const std::vector<GaitFrame>& gait,
                       const RootMotion& motion, const sim::Terrain& terrain, float toleranceM, float toleranceRad)
{
    FootPlanter planter(c, gait, motion, terrain);
    const std::size_t keys = jc.frames.size(), joints = c.joints.size();
    BakedJoints b;
    b.rootTranslation.resize(keys);
    b.rotations.resize(joints * keys);
    for (std::size_t k = 0; k < keys; ++k) {
        Pose pose = planter.next();
        while (planter.frame() <= jc.frames[k])
            pose = planter.next();
        b.rootTranslation[k] = pose.rootTranslation;
        for (std::size_t j = 0; j < joints; ++j) {
            glm::quat q = pose.rotations[j];
            // q and -q are one rotation; neighbours in one hemisphere interpolate the short way.
            if (k > 0 && glm::dot(q, b.rotations[j * keys + k - 1]) < 0.0f)
                q = -q;
            b.rotations[j * keys + k] = q;
        }
    }
    b.rootKept = keepVec3Keys(jc.clock.times, b.rootTranslation, toleranceM);
    b.kept.resize(joints);
    for (std::size_t j = 0; j < joints; ++j)
        b.kept[j] = keepRotationKeys(jc.clock.times, std::span<const glm::quat>(b.rotations.data() + j * keys, keys),
                                     toleranceRad * c.keyToleranceScale);
    return b;
}

void writeJoints(AnimationChannels& channels, const JointClock& jc, const BakedJoints& b, const AgentRig& rig)
{
    const std::size_t keys = jc.frames.size();
    channels.vec3Channel(rig.firstJoint, "translation", jc.clock, b.rootTranslation, b.rootKept);
    for (std::size_t j = 0; j < b.kept.size(); ++j)
        channels.rotationChannel(rig.firstJoint + static_cast<int>(j),
                                 std::span<const glm::quat>(b.rotations.data() + j * keys, keys), jc.clock, b.kept[j]);
}

}  // namespace throng::exporting::detail
