#include "export/character/Character.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>

namespace throng::exporting {

namespace {

glm::quat nlerpShort(const glm::quat& a, glm::quat b, float t)
{
    if (glm::dot(a, b) < 0.0f)
        b = -b;
    const glm::quat q(a.w + (b.w - a.w) * t, a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t, a.z + (b.z - a.z) * t);
    return glm::normalize(q);
}

glm::mat4 localTransform(const Joint& joint, const glm::vec3& translation, const glm::quat& rotation)
{
    return glm::translate(glm::mat4(1.0f), translation) * glm::mat4_cast(rotation) *
           glm::scale(glm::mat4(1.0f), joint.restScale);
}

}  // namespace

Pose sampleClip(const CycleClip& clip, double phase)
{
    const std::size_t n = clip.samples.size();
    if (n == 1)
        return clip.samples[0];
    const double wrapped = phase - std::floor(phase);
    const double at = wrapped * static_cast<double>(n);
    const std::size_t k = std::min(n - 1, static_cast<std::size_t>(at));
    const float t = static_cast<float>(at - static_cast<double>(k));
    return blendPoses(clip.samples[k], clip.samples[(k + 1) % n], t);
}

Pose blendPoses(const Pose& a, const Pose& b, float t)
{
    if (t <= 0.0f)
        return a;
    if (t >= 1.0f)
        return b;
    Pose out;
    out.rotations.resize(a.rotations.size());
    for (std::size_t j = 0; j < a.rotations.size(); ++j)
        out.rotations[j] = nlerpShort(a.rotations[j], b.rotations[j], t);
    out.rootTranslation = a.rootTranslation + (b.rootTranslation - a.rootTranslation) * t;
    return out;
}

Pose blendPosesLayered(const Pose& a, const Pose& b, const std::vector<std::uint8_t>& layered, float t, float rest)
{
    t = std::clamp(t, 0.0f, 1.0f);
    rest = std::clamp(rest, 0.0f, 1.0f);
    Pose out;
    out.rotations.resize(a.rotations.size());
    for (std::size_t j = 0; j < a.rotations.size(); ++j) {
        const float w = j < layered.size() && layered[j] ? t : rest;
        out.rotations[j] = w <= 0.0f   ? a.rotations[j]
                           : w >= 1.0f ? b.rotations[j]
                                       : nlerpShort(a.rotations[j], b.rotations[j], w);
    }
    out.rootTranslation = a.rootTranslation + (b.rootTranslation - a.rootTranslation) * rest;
    return out;
}

int Character::actionIndex(std::string_view name) const
{
    for (std::size_t a = 0; a < actions.size(); ++a)
        if (actions[a].clip.name == name)
            return static_cast<int>(a);
    return -1;
}

std::vector<glm::mat4> jointGlobalTransforms(const Character& character, const Pose& pose)
{
    std::vector<glm::mat4> global(character.joints.size());
    for (std::size_t j = 0; j < character.joints.size(); ++j) {
        const Joint& joint = character.joints[j];
        const glm::vec3 t = j == 0 ? pose.rootTranslation : joint.restTranslation;
        const glm::mat4 local = localTransform(joint, t, pose.rotations[j]);
        global[j] = joint.parent < 0 ? local : global[static_cast<std::size_t>(joint.parent)] * local;
    }
    return global;
}

Pose restPose(const Character& character)
{
    Pose pose;
    for (const Joint& joint : character.joints)
        pose.rotations.push_back(joint.restRotation);
    pose.rootTranslation = character.joints.empty() ? glm::vec3(0.0f) : character.joints[0].restTranslation;
    return pose;
}

std::vector<glm::mat4> restInverseBindMatrices(const std::vector<Joint>& joints)
{
    std::vector<glm::mat4> global(joints.size()), inverse(joints.size());
    for (std::size_t j = 0; j < joints.size(); ++j) {
        const glm::mat4 local = localTransform(joints[j], joints[j].restTranslation, joints[j].restRotation);
        global[j] = joints[j].parent < 0 ? local : global[static_cast<std::size_t>(joints[j].parent)] * local;
        inverse[j] = glm::inverse(global[j]);
    }
    return inverse;
}

std::string checkCharacter(const Character& c)
{
    const std::string where = "character '" + c.name + "': ";
    if (c.joints.empty())
        return where + "has no joints";
    for (std::size_t j = 0; j < c.joints.size(); ++j)
        if (c.joints[j].parent >= static_cast<int>(j) || (j > 0 && c.joints[j].parent < 0))
            return where + "joint '" + c.joints[j].name + "' does not follow its parent";
    const CharacterMesh& m = c.mesh;
    const std::size_t v = m.positions.size();
    if (v == 0 || m.normals.size() != v || m.joints.size() != v || m.weights.size() != v || m.indices.empty() ||
        m.indices.size() % 3 != 0 || m.inverseBindMatrices.size() != c.joints.size())
        return where + "mesh arrays disagree in size";
    for (std::size_t i = 0; i < v; ++i) {
        const glm::vec4 w = m.weights[i];
        if (w.x + w.y + w.z + w.w != 1.0f)
            return where + "weights of vertex " + std::to_string(i) + " do not sum to 1";
        for (int k = 0; k < 4; ++k)
            if (m.joints[i][k] >= c.joints.size() || (w[k] == 0.0f && m.joints[i][k] != 0))
                return where + "vertex " + std::to_string(i) + " has a bad joint slot";
    }
    for (std::uint32_t index : m.indices)
        if (index >= v)
            return where + "an index points past the vertices";
    for (const CycleClip* clip : {&c.idle, &c.walk, &c.run}) {
        if (clip->samples.empty() || !(clip->strideM > 0.0f))
            return where + "clip '" + clip->name + "' has no samples or no stride";
        for (const Pose& p : clip->samples)
            if (p.rotations.size() != c.joints.size())
                return where + "clip '" + clip->name + "' poses a different number of joints";
    }
    for (const ActionClip& a : c.actions) {
        if (a.clip.samples.empty() || a.layered.size() != c.joints.size() || !(a.blendS >= 0.0f))
            return where + "action '" + a.clip.name + "' has no samples, no mask per joint or a bad blend time";
        for (const Pose& p : a.clip.samples)
            if (p.rotations.size() != c.joints.size())
                return where + "action '" + a.clip.name + "' poses a different number of joints";
    }
    return {};
}

}  // namespace throng::exporting
