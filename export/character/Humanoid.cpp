#include "export/character/BuiltinCharacters.h"
#include "export/character/MeshBuilder.h"

namespace throng::exporting {

namespace {

struct JointSpec {
    const char* name;
    int parent;
    glm::vec3 offset;  // from the parent, m at scale 1
};

}  // namespace

Character makeHumanoid(const std::string& name, const HumanoidBody& body)
{
    using L = HumanoidLegs;
    const float s = body.scale;
    const float legRootY = L::kAnkleM + 0.985f * (L::kThighM + L::kShinM);  // hip joints over a near-straight leg
    const float sw = body.shoulderHalfWidth, hw = body.hipHalfWidth;
    const JointSpec specs[kHumanoidJointCount] = {
        {"hips", -1, {0.0f, legRootY + 0.05f, 0.0f}},
        {"spine", kHips, {0.0f, 0.12f, 0.0f}},
        {"chest", kSpine, {0.0f, 0.2f, 0.0f}},
        {"neck", kChest, {0.0f, 0.2f, 0.0f}},
        {"head", kNeck, {0.0f, 0.08f, 0.0f}},
        {"upper_arm_l", kChest, {0.0f, 0.18f, -sw}},
        {"lower_arm_l", kUpperArmL, {0.0f, -0.29f, 0.0f}},
        {"hand_l", kLowerArmL, {0.0f, -0.25f, 0.0f}},
        {"upper_arm_r", kChest, {0.0f, 0.18f, sw}},
        {"lower_arm_r", kUpperArmR, {0.0f, -0.29f, 0.0f}},
        {"hand_r", kLowerArmR, {0.0f, -0.25f, 0.0f}},
        {"upper_leg_l", kHips, {0.0f, -0.05f, -hw}},
        {"lower_leg_l", kUpperLegL, {0.0f, -L::kThighM, 0.0f}},
        {"foot_l", kLowerLegL, {0.0f, -L::kShinM, 0.0f}},
        {"upper_leg_r", kHips, {0.0f, -0.05f, hw}},
        {"lower_leg_r", kUpperLegR, {0.0f, -L::kThighM, 0.0f}},
        {"foot_r", kLowerLegR, {0.0f, -L::kShinM, 0.0f}},
    };
    Character c;
    c.name = name;
    std::vector<glm::vec3> at(kHumanoidJointCount);  // joint positions in bind space
    for (int j = 0; j < kHumanoidJointCount; ++j) {
        Joint joint;
        joint.name = specs[j].name;
        joint.parent = specs[j].parent;
        joint.restTranslation = specs[j].offset * s;
        at[j] = joint.restTranslation + (joint.parent < 0 ? glm::vec3(0.0f) : at[joint.parent]);
        c.joints.push_back(joint);
    }

    MeshBuilder mb(c.mesh);
    auto seg = [&](int joint, glm::vec3 lo, glm::vec3 hi, glm::vec2 taper = glm::vec2(1.0f)) {
        mb.box(joint, at[joint] + lo * s, at[joint] + hi * s, taper);
    };
    // Torso: pelvis, belly, chest; the chest narrows to the shoulders.
    seg(kHips, {-0.11f, -0.1f, -hw - 0.07f}, {0.11f, 0.12f, hw + 0.07f});
    seg(kSpine, {-0.1f, 0.0f, -0.15f}, {0.1f, 0.2f, 0.15f});
    seg(kChest, {-0.12f, 0.0f, -sw + 0.02f}, {0.12f, 0.22f, sw - 0.02f}, {0.9f, 1.0f});
    seg(kNeck, {-0.04f, 0.0f, -0.04f}, {0.04f, 0.08f, 0.04f});
    const float hs = body.headScale;
    seg(kHead, glm::vec3(-0.1f, 0.0f, -0.085f) * hs, glm::vec3(0.11f, 0.19f, 0.085f) * hs, {0.9f, 0.9f});
    mb.box(kHead, at[kHead] + glm::vec3(0.11f, 0.08f, -0.02f) * hs * s, at[kHead] + glm::vec3(0.14f, 0.13f, 0.02f) * hs * s);
    if (body.longHair)
        seg(kHead, glm::vec3(-0.13f, -0.1f, -0.095f) * hs, glm::vec3(-0.04f, 0.2f, 0.095f) * hs);
    if (body.hat) {
        mb.prism(kHead, at[kHead] + glm::vec3(0.0f, 0.2f, 0.0f) * hs * s, 1, 0.2f * hs * s, 0.012f * s, 10);
        mb.prism(kHead, at[kHead] + glm::vec3(0.0f, 0.27f, 0.0f) * hs * s, 1, 0.11f * hs * s, 0.06f * s, 10);
    }
    if (body.skirt)
        seg(kHips, {-0.16f, -0.38f, -hw - 0.1f}, {0.16f, -0.05f, hw + 0.1f}, {0.7f, 0.8f});
    for (int side = 0; side < 2; ++side) {
        const int upperArm = side == 0 ? kUpperArmL : kUpperArmR;
        seg(upperArm, {-0.045f, -0.29f, -0.045f}, {0.045f, 0.02f, 0.045f});
        seg(upperArm + 1, {-0.04f, -0.25f, -0.04f}, {0.04f, 0.0f, 0.04f});
        seg(upperArm + 2, {-0.035f, -0.1f, -0.025f}, {0.05f, 0.0f, 0.025f});
        const int upperLeg = side == 0 ? kUpperLegL : kUpperLegR;
        seg(upperLeg, {-0.07f, -L::kThighM, -0.065f}, {0.07f, 0.02f, 0.065f}, {1.1f, 1.1f});
        seg(upperLeg + 1, {-0.055f, -L::kShinM, -0.05f}, {0.055f, 0.0f, 0.05f}, {1.1f, 1.1f});
        seg(upperLeg + 2, {-0.06f, -L::kAnkleM, -0.05f}, {0.19f, 0.02f, 0.05f});
    }
    c.mesh.inverseBindMatrices = restInverseBindMatrices(c.joints);
    addHumanoidClips(c, s);
    addHumanoidActions(c, s);
    return c;
}

std::optional<Character> makeBuiltinCharacter(const std::string& name)
{
    if (name == "man")
        return makeHumanoid(name, HumanoidBody{});
    if (name == "woman")
        return makeHumanoid(name, HumanoidBody{0.95f, 0.17f, 0.11f, 1.0f, true, true, false});
    if (name == "tall_man")
        return makeHumanoid(name, HumanoidBody{1.1f, 0.21f, 0.1f, 1.0f, false, false, false});
    if (name == "child")
        return makeHumanoid(name, HumanoidBody{0.62f, 0.18f, 0.1f, 1.35f, false, false, true});
    if (name == "car")
        return makeCar();
    if (name == "bird")
        return makeBird();
    return std::nullopt;
}

}  // namespace throng::exporting
