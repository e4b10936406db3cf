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

const char* toString(MaterialSlot slot)
{
    switch (slot) {
    case MaterialSlot::Body: return "body";
    case MaterialSlot::Skin: return "skin";
    case MaterialSlot::Top: return "top";
    case MaterialSlot::Bottom: return "bottom";
    case MaterialSlot::Hair: return "hair";
    case MaterialSlot::GreyHair: return "grey_hair";
    case MaterialSlot::Shoes: return "shoes";
    case MaterialSlot::Hat: return "hat";
    case MaterialSlot::Bag: return "bag";
    }
    return "body";
}

const char* toString(Lod lod)
{
    switch (lod) {
    case Lod::Near: return "near";
    case Lod::Mid: return "mid";
    case Lod::Far: return "far";
    }
    return "near";
}

bool lodFromName(std::string_view name, Lod& lod)
{
    for (Lod l : {Lod::Near, Lod::Mid, Lod::Far})
        if (name == toString(l)) {
            lod = l;
            return true;
        }
    return false;
}

std::vector<MeshPart> partsOf(const CharacterMesh& mesh)
{
    if (!mesh.parts.empty())
        return mesh.parts;
    return {MeshPart{MaterialSlot::Body, 0, static_cast<std::uint32_t>(mesh.indices.size()), 1.0f}};
}

void normaliseInfluences(std::array<std::uint16_t, 4>& j, glm::vec4& w)
{
    int order[4] = {0, 1, 2, 3};
    std::sort(order, order + 4, [&](int a, int b) { return w[a] > w[b]; });
    std::array<std::uint16_t, 4> js{};
    glm::vec4 ws(0.0f);
    for (int k = 0; k < 4; ++k) {
        ws[k] = std::max(0.0f, w[order[k]]);
        js[k] = ws[k] > 0.0f ? j[order[k]] : 0;
    }
    const float sum = ws.x + ws.y + ws.z + ws.w;
    ws = sum > 0.0f ? ws / sum : glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
    for (int tries = 0; tries < 16; ++tries) {
        const float s = ws.x + ws.y + ws.z + ws.w;
        if (s == 1.0f)
            break;
        ws.x = std::nextafter(ws.x, s < 1.0f ? 2.0f : 0.0f);
    }
    j = js;
    w = ws;
}

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

namespace {

// Each joint's transform in the character's space into `out`, for the joints `wanted` marks
// (nullptr: all of them); parents come before their children.
void fillGlobals(const Character& character, const Pose& pose, const std::vector<std::uint8_t>* wanted,
                 std::vector<glm::mat4>& out)
{
    out.resize(character.joints.size());
    for (std::size_t j = 0; j < character.joints.size(); ++j) {
        if (wanted && (j >= wanted->size() || !(*wanted)[j]))
            continue;
        const Joint& joint = character.joints[j];
        const glm::vec3 t = j == 0 ? pose.rootTranslation : joint.restTranslation;
        const glm::mat4 local = localTransform(joint, t, pose.rotations[j]);
        out[j] = joint.parent < 0 ? local : out[static_cast<std::size_t>(joint.parent)] * local;
    }
}

}  // namespace

std::vector<glm::mat4> jointGlobalTransforms(const Character& character, const Pose& pose)
{
    std::vector<glm::mat4> global;
    fillGlobals(character, pose, nullptr, global);
    return global;
}

void jointGlobalTransforms(const Character& character, const Pose& pose, const std::vector<std::uint8_t>& wanted,
                           std::vector<glm::mat4>& out)
{
    fillGlobals(character, pose, &wanted, out);
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
    std::uint32_t next = 0;
    for (const MeshPart& part : m.parts) {
        if (part.firstIndex != next || part.indexCount == 0 || part.indexCount % 3 != 0 ||
            !(part.wornShare > 0.0f && part.wornShare <= 1.0f))
            return where + "mesh part '" + toString(part.slot) + "' does not follow the one before or is empty";
        next += part.indexCount;
    }
    if (!m.parts.empty() && next != m.indices.size())
        return where + "the mesh's parts do not cover its triangles";
    if (c.ladder.size() != c.ladderSpeeds.size() || c.ladder.size() == 1)
        return where + "the gait ladder needs a speed per gait and at least two gaits";
    for (std::size_t k = 1; k < c.ladderSpeeds.size(); ++k)
        if (!(c.ladderSpeeds[k] > c.ladderSpeeds[k - 1]))
            return where + "the gait ladder's speeds do not rise";
    std::vector<const CycleClip*> clips{&c.idle, &c.walk, &c.run};
    for (const CycleClip& rung : c.ladder)
        clips.push_back(&rung);
    for (const CycleClip* clip : clips) {
        if (clip->samples.empty() || !(clip->strideM > 0.0f))
            return where + "clip '" + clip->name + "' has no samples or no stride";
        for (const Pose& p : clip->samples)
            if (p.rotations.size() != c.joints.size())
                return where + "clip '" + clip->name + "' poses a different number of joints";
    }
    for (const Leg& leg : c.legs) {
        const auto joints = static_cast<int>(c.joints.size());
        if (leg.upper < 1 || leg.foot >= joints || leg.lower >= joints || c.joints[leg.upper].parent < 0 ||
            c.joints[leg.lower].parent != leg.upper || c.joints[leg.foot].parent != leg.lower)
            return where + "a leg's joints are not a chain of hip, knee and ankle";
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
