#include "export/character/BuiltinCharacters.h"
#include "export/character/PoseMaths.h"
#include "export/character/SurfaceBuilder.h"

#include <glm/mat4x4.hpp>

#include <vector>

namespace throng::exporting {

Character makeHumanoid(const std::string& name, const HumanoidBody& body, Lod lod)
{
    using L = HumanoidLegs;
    const float s = body.scale;
    const float legRootY = L::kAnkleM + 0.985f * (L::kThighM + L::kShinM);  // hip joints over a near-straight leg
    const float sw = body.shoulderHalfWidth, hw = body.hipHalfWidth;
    const JointSpec specs[kHumanoidJointCount] = {
        {"hips", -1, {0.0f, legRootY + 0.05f, 0.0f}},
        {"spine", kHips, {0.0f, 0.12f, 0.0f}},
        {"chest", kSpine, {0.0f, 0.2f, 0.0f}},
        {"neck", kChest, {body.stoopM, 0.2f, 0.0f}},
        {"head", kNeck, {0.0f, 0.08f, 0.0f}},
        {"upper_arm_l", kChest, {0.8f * body.stoopM, 0.18f, -sw}},
        {"lower_arm_l", kUpperArmL, {0.0f, -0.29f, 0.0f}},
        {"hand_l", kLowerArmL, {0.0f, -0.25f, 0.0f}},
        {"upper_arm_r", kChest, {0.8f * body.stoopM, 0.18f, sw}},
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

    SurfaceBuilder sb(c.mesh, lod);
    const float g = body.girth, hs = body.headScale;
    const MaterialSlot legs = body.skirt ? MaterialSlot::Skin : MaterialSlot::Bottom;
    const MaterialSlot hair = body.greyHair ? MaterialSlot::GreyHair : MaterialSlot::Hair;
    // A point `d` (m at scale 1) from joint j, and a section there.
    auto p = [&](int j, glm::vec3 d) { return at[j] + d * s; };
    auto section = [&](int j, glm::vec3 d, float depth, float width, MaterialSlot slot) {
        return TubeSection{p(j, d), depth * s, width * s, slot};
    };
    auto scaled = [&](float m) { return m * s; };

    // Torso, crotch to shoulders: trousers to the waist, the top above; a stoop leans the
    // chest towards the neck.
    {
        Tube t;
        const float lean = body.stoopM;
        auto leanAt = [&](float dy) { return dy > 0.2f ? lean * (dy - 0.2f) / 0.3f : 0.0f; };
        const struct { float dy, depth, width; MaterialSlot slot; } rings[] = {
            {-0.14f, 0.06f, 0.08f, MaterialSlot::Bottom},
            {-0.06f, 0.105f, hw + 0.07f, MaterialSlot::Bottom},
            {0.02f, 0.105f, hw + 0.065f, MaterialSlot::Bottom},
            {0.10f, 0.098f, 0.135f, MaterialSlot::Top},
            {0.22f, 0.11f, sw - 0.035f, MaterialSlot::Top},
            {0.36f, 0.12f, sw - 0.012f, MaterialSlot::Top},
            {0.46f, 0.10f, sw - 0.015f, MaterialSlot::Top},
            {0.52f, 0.075f, sw - 0.07f, MaterialSlot::Top},
        };
        for (const auto& r : rings)
            t.sections.push_back(section(kHips, {leanAt(r.dy), r.dy, 0.0f}, r.depth * g, r.width * g, r.slot));
        t.bones = {{kHips, 0.0f}, {kSpine, 3.17f}, {kChest, 4.71f}};
        t.blendM = scaled(0.06f);
        t.endCapM = scaled(0.03f);
        sb.tube(t);
    }
    if (body.skirt) {
        Tube t;
        t.sections = {section(kHips, {0.0f, 0.10f, 0.0f}, 0.1f * g, 0.14f * g, MaterialSlot::Bottom),
                      section(kHips, {0.0f, 0.0f, 0.0f}, 0.12f * g, (hw + 0.09f) * g, MaterialSlot::Bottom),
                      section(kHips, {0.0f, -0.2f, 0.0f}, 0.15f * g, (hw + 0.13f) * g, MaterialSlot::Bottom),
                      section(kHips, {0.0f, -0.42f, 0.0f}, 0.17f * g, (hw + 0.16f) * g, MaterialSlot::Bottom)};
        t.bones = {{kHips, 0.0f}};
        t.startCapM = scaled(0.03f);
        t.endCapM = 0.0f;
        sb.tube(t);
    }
    // Neck and head, with the face's nose and ears and the hair over the skull.
    {
        Tube neck;
        neck.sections = {section(kChest, {0.6f * body.stoopM, 0.14f, 0.0f}, 0.05f, 0.052f, MaterialSlot::Skin),
                         section(kNeck, {0.0f, 0.0f, 0.0f}, 0.046f, 0.047f, MaterialSlot::Skin),
                         section(kNeck, {0.0f, 0.12f, 0.0f}, 0.045f, 0.046f, MaterialSlot::Skin)};
        neck.bones = {{kChest, 0.0f}, {kNeck, 1.0f}, {kHead, 1.67f}};
        neck.blendM = scaled(0.03f);
        neck.endCapM = scaled(0.02f);
        sb.tube(neck);
    }
    auto headSection = [&](glm::vec3 d, float depth, float width, MaterialSlot slot) {
        return TubeSection{at[kHead] + d * hs * s, depth * hs * s, width * hs * s, slot};
    };
    auto headTube = [&](std::vector<TubeSection> sections, float startCap, float endCap, glm::vec3 forward,
                        bool small) {
        Tube t;
        t.sections = std::move(sections);
        t.bones = {{kHead, 0.0f}};
        t.startCapM = startCap * hs * s;
        t.endCapM = endCap * hs * s;
        t.forward = forward;
        t.small = small;
        sb.tube(t);
    };
    const glm::vec3 up(0.0f, 1.0f, 0.0f), ahead(1.0f, 0.0f, 0.0f);
    headTube({headSection({0.025f, -0.03f, 0.0f}, 0.055f, 0.05f, MaterialSlot::Skin),
              headSection({0.02f, 0.02f, 0.0f}, 0.085f, 0.07f, MaterialSlot::Skin),
              headSection({0.005f, 0.09f, 0.0f}, 0.1f, 0.083f, MaterialSlot::Skin),
              headSection({-0.005f, 0.15f, 0.0f}, 0.098f, 0.084f, MaterialSlot::Skin),
              headSection({-0.01f, 0.19f, 0.0f}, 0.07f, 0.062f, MaterialSlot::Skin)},
             0.02f, 0.03f, ahead, false);
    headTube({headSection({0.09f, 0.075f, 0.0f}, 0.016f, 0.012f, MaterialSlot::Skin),
              headSection({0.112f, 0.062f, 0.0f}, 0.01f, 0.01f, MaterialSlot::Skin)},
             -1.0f, 0.008f, up, true);
    for (float side : {-1.0f, 1.0f})
        headTube({headSection({-0.005f, 0.09f, side * 0.075f}, 0.022f, 0.028f, MaterialSlot::Skin),
                  headSection({-0.01f, 0.09f, side * 0.092f}, 0.02f, 0.025f, MaterialSlot::Skin)},
                 -1.0f, 0.006f, ahead, true);
    {
        std::vector<TubeSection> h;
        if (body.longHair) {
            h.push_back(headSection({-0.07f, -0.12f, 0.0f}, 0.045f, 0.08f, hair));
            h.push_back(headSection({-0.04f, 0.0f, 0.0f}, 0.085f, 0.09f, hair));
        }
        h.push_back(headSection({-0.02f, 0.07f, 0.0f}, 0.094f, 0.088f, hair));
        h.push_back(headSection({-0.012f, 0.15f, 0.0f}, 0.104f, 0.09f, hair));
        h.push_back(headSection({-0.015f, 0.2f, 0.0f}, 0.075f, 0.066f, hair));
        headTube(std::move(h), body.longHair ? 0.02f : 0.03f, 0.03f, ahead, false);
    }
    // Arms, shoulder to fingertips: sleeves, then skin from the cuff (or the biceps).
    for (int side = 0; side < 2; ++side) {
        const int upper = side == 0 ? kUpperArmL : kUpperArmR;
        const MaterialSlot sleeve = MaterialSlot::Top, bare = MaterialSlot::Skin;
        const MaterialSlot lowerSleeve = body.shortSleeves ? bare : sleeve;
        const struct { float dy, depth, width; MaterialSlot slot; } rings[] = {
            {0.0f, 0.05f * g, 0.05f * g, sleeve},        {-0.06f, 0.052f * g, 0.05f * g, sleeve},
            {-0.16f, 0.046f * g, 0.044f * g, lowerSleeve}, {-0.29f, 0.037f * g, 0.036f * g, lowerSleeve},
            {-0.36f, 0.04f * g, 0.039f * g, lowerSleeve},  {-0.51f, 0.03f, 0.026f, bare},
            {-0.56f, 0.028f, 0.022f, bare},                {-0.61f, 0.043f, 0.021f, bare},
            {-0.67f, 0.04f, 0.019f, bare},                {-0.73f, 0.03f, 0.013f, bare},
        };
        Tube t;
        for (const auto& r : rings)
            t.sections.push_back(section(upper, {0.0f, r.dy, 0.0f}, r.depth, r.width, r.slot));
        t.bones = {{upper, 0.0f}, {upper + 1, 3.0f}, {upper + 2, 5.6f}};
        t.blendM = scaled(0.04f);
        t.startCapM = scaled(0.035f);
        t.endCapM = scaled(0.015f);
        sb.tube(t);
    }
    // Legs, hip to ankle, and shoes from heel to toe.
    for (int side = 0; side < 2; ++side) {
        const int upper = side == 0 ? kUpperLegL : kUpperLegR;
        const struct { float dy, depth, width; } rings[] = {
            {0.04f, 0.085f, 0.085f}, {-0.08f, 0.082f, 0.078f}, {-0.24f, 0.068f, 0.064f}, {-0.42f, 0.052f, 0.05f},
            {-0.47f, 0.05f, 0.048f}, {-0.58f, 0.056f, 0.052f}, {-0.76f, 0.038f, 0.036f}, {-0.84f, 0.034f, 0.032f},
        };
        Tube leg;
        for (const auto& r : rings)
            leg.sections.push_back(section(upper, {0.0f, r.dy, 0.0f}, r.depth * g, r.width * g, legs));
        leg.bones = {{upper, 0.0f}, {upper + 1, 3.4f}};
        leg.blendM = scaled(0.05f);
        leg.startCapM = scaled(0.04f);
        leg.endCapM = scaled(0.03f);
        sb.tube(leg);
        Tube shoe;
        const int foot = upper + 2;
        shoe.sections = {section(foot, {-0.07f, -0.035f, 0.0f}, 0.035f, 0.038f, MaterialSlot::Shoes),
                         section(foot, {-0.01f, -0.035f, 0.0f}, 0.048f, 0.044f, MaterialSlot::Shoes),
                         section(foot, {0.07f, -0.035f, 0.0f}, 0.034f, 0.047f, MaterialSlot::Shoes),
                         section(foot, {0.15f, -0.035f, 0.0f}, 0.022f, 0.04f, MaterialSlot::Shoes)};
        shoe.forward = up;
        shoe.bones = {{foot, 0.0f}};
        shoe.startCapM = scaled(0.03f);
        shoe.endCapM = scaled(0.035f);
        sb.tube(shoe);
    }
    // Accessories: a hat with a brim, and a backpack with straps over the shoulders.
    if (body.hatShare > 0.0f) {
        headTube({headSection({-0.01f, 0.15f, 0.0f}, 0.17f, 0.16f, MaterialSlot::Hat),
                  headSection({-0.01f, 0.165f, 0.0f}, 0.17f, 0.16f, MaterialSlot::Hat)},
                 0.0f, 0.0f, ahead, false);
        headTube({headSection({-0.01f, 0.16f, 0.0f}, 0.108f, 0.1f, MaterialSlot::Hat),
                  headSection({-0.012f, 0.27f, 0.0f}, 0.1f, 0.092f, MaterialSlot::Hat)},
                 0.0f, 0.02f, ahead, false);
        sb.setWornShare(MaterialSlot::Hat, body.hatShare);
    }
    if (body.bagShare > 0.0f) {
        const float back = -(0.12f * g + 0.05f) + 0.3f * body.stoopM;
        Tube pack;
        pack.sections = {section(kChest, {back, -0.06f, 0.0f}, 0.05f, 0.13f, MaterialSlot::Bag),
                         section(kChest, {back, 0.1f, 0.0f}, 0.055f, 0.135f, MaterialSlot::Bag),
                         section(kChest, {back + 0.01f, 0.24f, 0.0f}, 0.045f, 0.12f, MaterialSlot::Bag)};
        pack.bones = {{kChest, 0.0f}};
        pack.startCapM = scaled(0.02f);
        pack.endCapM = scaled(0.03f);
        sb.tube(pack);
        for (float side : {-1.0f, 1.0f}) {
            const float z = side * 0.1f * g, top = -0.02f + 0.5f * body.stoopM, front = 0.115f * g + body.stoopM;
            Tube strap;
            strap.sections = {section(kChest, {back + 0.05f, 0.2f, z}, 0.02f, 0.007f, MaterialSlot::Bag),
                              section(kChest, {top, 0.24f, z}, 0.02f, 0.007f, MaterialSlot::Bag),
                              section(kChest, {front, 0.15f, z}, 0.02f, 0.007f, MaterialSlot::Bag),
                              section(kChest, {0.125f * g, -0.02f, z}, 0.02f, 0.007f, MaterialSlot::Bag)};
            strap.forward = glm::vec3(0.0f, 0.0f, 1.0f);
            strap.bones = {{kChest, 0.0f}};
            sb.tube(strap);
        }
        sb.setWornShare(MaterialSlot::Bag, body.bagShare);
    }
    sb.finish();
    c.mesh.inverseBindMatrices = restInverseBindMatrices(c.joints);
    addHumanoidClips(c, s);
    const std::vector<glm::mat4> idle = jointGlobalTransforms(c, sampleClip(c.idle, 0.0));
    for (int upper : {int(kUpperLegL), int(kUpperLegR)})
        c.legs.push_back({upper, upper + 1, upper + 2, glm::vec3(idle[std::size_t(upper + 2)][3])});
    addHumanoidActions(c, s);
    return c;
}

std::optional<HumanoidBody> humanoidBuild(const std::string& name)
{
    if (name == "man")
        return HumanoidBody{.hatShare = 0.15f, .bagShare = 0.25f};
    if (name == "woman")
        return HumanoidBody{.scale = 0.95f, .shoulderHalfWidth = 0.17f, .hipHalfWidth = 0.11f, .girth = 0.9f,
                            .skirt = true, .longHair = true, .shortSleeves = true, .hatShare = 0.1f, .bagShare = 0.3f};
    if (name == "tall_man")
        return HumanoidBody{.scale = 1.1f, .shoulderHalfWidth = 0.21f, .girth = 1.05f, .hatShare = 0.15f,
                            .bagShare = 0.2f};
    if (name == "child")
        return HumanoidBody{.scale = 0.62f, .shoulderHalfWidth = 0.18f, .headScale = 1.35f, .girth = 1.05f,
                            .shortSleeves = true, .hatShare = 1.0f, .bagShare = 0.5f};
    if (name == "elderly")
        return HumanoidBody{.scale = 0.96f, .shoulderHalfWidth = 0.19f, .hipHalfWidth = 0.11f, .girth = 1.08f,
                            .stoopM = 0.06f, .greyHair = true, .hatShare = 0.6f};
    return std::nullopt;
}

std::optional<Character> makeBuiltinCharacter(const std::string& name, Lod lod)
{
    if (const std::optional<HumanoidBody> build = humanoidBuild(name))
        return makeHumanoid(name, *build, lod);
    if (name == "car")
        return makeCar();
    if (name == "bird")
        return makeBird(lod);
    if (name == "horse")
        return makeHorse(lod);
    return std::nullopt;
}

}  // namespace throng::exporting
