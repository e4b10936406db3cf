// Humanoid actions (sim::Clip's wait, look_around, wave, talk, phone, cheer, sit,
// shift_weight, point): each a loop over the idle pose's legs, with the arms, chest, neck
// and head posed by hand. Standing, the feet stay where the idle pose puts them (a weight
// shift turns the legs about the planted feet), so an action over a standing agent slides
// no foot; sitting lowers the hips onto a seat behind the agent, shins upright. Fall and
// get_up play once, through key poses, the ankles put until the legs stretch out.
#include "export/character/BuiltinCharacters.h"
#include "export/character/PoseMaths.h"

#include "simcore/scene/Clip.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>

namespace throng::exporting {

namespace {

constexpr int kSamplesPerAction = 16;

// The joints an action plays over walking: the chest and everything above it.
std::vector<std::uint8_t> upperBody()
{
    std::vector<std::uint8_t> mask(kHumanoidJointCount, 0);
    for (int j : {kChest, kNeck, kHead, kUpperArmL, kLowerArmL, kHandL, kUpperArmR, kLowerArmR, kHandR})
        mask[std::size_t(j)] = 1;
    return mask;
}

// Poses over one cycle: the idle pose, changed by `pose(phase in radians, pose)`.
ActionClip makeAction(const Character& c, sim::Clip clip, const std::function<void(float, Pose&)>& pose,
                      float blendS = 0.3f, bool overWalking = true)
{
    ActionClip a;
    a.clip.name = sim::toString(clip);
    a.clip.strideM = 1.0f;  // unused: an action's phase runs by time
    a.layered = overWalking ? upperBody() : std::vector<std::uint8_t>(kHumanoidJointCount, 0);
    a.blendS = blendS;
    for (int k = 0; k < kSamplesPerAction; ++k) {
        Pose p = c.idle.samples.front();
        pose(2.0f * kPi * static_cast<float>(k) / static_cast<float>(kSamplesPerAction), p);
        a.clip.samples.push_back(std::move(p));
    }
    return a;
}

// A one-shot over progress u in [0, 1]: sample k at u = k / (n - 1), the last the pose it
// holds; in full over locomotion too (ActionClip::oneShot).
ActionClip makeOneShot(const Character& c, sim::Clip clip, const std::function<void(float, Pose&)>& pose,
                       float blendS)
{
    ActionClip a;
    a.clip.name = sim::toString(clip);
    a.clip.strideM = 1.0f;
    a.layered.assign(kHumanoidJointCount, 1);
    a.blendS = blendS;
    a.oneShot = true;
    for (int k = 0; k < kSamplesPerAction; ++k) {
        Pose p = c.idle.samples.front();
        pose(static_cast<float>(k) / static_cast<float>(kSamplesPerAction - 1), p);
        a.clip.samples.push_back(std::move(p));
    }
    return a;
}

// One moment of falling to the ground (or getting up): the trunk's lean back from upright
// and each leg's hip and knee bends, all about Z (+ = the thigh forward, the trunk back),
// with the ankles at `ankleForward` m ahead of where standing put them.
struct FallKey {
    float trunk, hip, knee;   // rad
    float spine, neck;        // rad, about Z
    float armForward, armOut; // upper arms: about Z (forward), about X (out to the side)
    float elbow;              // lower arms, about Z
    float ankleForward;       // m at scale 1
};

// Standing, crouched with the knees giving way, sitting on the ground leaning back on the
// hands, lying on the back.
constexpr FallKey kStand{0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f};
constexpr FallKey kCrouch{-0.15f, 1.4f, -1.9f, -0.1f, 0.1f, 0.8f, 0.15f, 0.6f, 0.0f};
constexpr FallKey kSitDown{0.3f, 1.9f, -1.6f, 0.0f, -0.1f, -0.6f, 0.25f, 0.2f, 0.0f};
constexpr FallKey kLying{1.45f, 0.05f, -0.1f, 0.0f, -0.3f, 0.05f, 0.3f, 0.1f, 0.25f};

// Four keys at progress 0, `at[0]`, `at[1]` and 1, eased in and out between neighbours.
struct FallPath {
    std::array<FallKey, 4> keys;
    std::array<float, 2> at;
};
constexpr FallPath kFalling{{kStand, kCrouch, kSitDown, kLying}, {0.3f, 0.6f}};
constexpr FallPath kGettingUp{{kLying, kSitDown, kCrouch, kStand}, {0.35f, 0.7f}};

FallKey fallKeyAt(float u, const FallPath& path)
{
    const float times[4] = {0.0f, path.at[0], path.at[1], 1.0f};
    const int k = u < times[1] ? 0 : (u < times[2] ? 1 : 2);
    const FallKey& a = path.keys[std::size_t(k)];
    const FallKey& b = path.keys[std::size_t(k + 1)];
    float t = std::clamp((u - times[k]) / (times[k + 1] - times[k]), 0.0f, 1.0f);
    t = t * t * (3.0f - 2.0f * t);
    const auto mix = [t](float x, float y) { return x + (y - x) * t; };
    return {mix(a.trunk, b.trunk),
            mix(a.hip, b.hip),
            mix(a.knee, b.knee),
            mix(a.spine, b.spine),
            mix(a.neck, b.neck),
            mix(a.armForward, b.armForward),
            mix(a.armOut, b.armOut),
            mix(a.elbow, b.elbow),
            mix(a.ankleForward, b.ankleForward)};
}

}  // namespace

void addHumanoidActions(Character& c, float scale)
{
    // Arms hang along -Y: about Z swings a hand forward (+X), about X (negative on the
    // right, +Z side) raises it out to the side. Joint rotations are absolute (the rest
    // rotations are all identity).
    const Pose& idle = c.idle.samples.front();
    // Hip joint to ankle in the idle pose: the leg that turns about the planted foot.
    const std::vector<glm::mat4> at = jointGlobalTransforms(c, idle);
    const float legM = at[kUpperLegL][3].y - at[kFootL][3].y;
    // The hips `sway` m sideways (+Z) over planted feet: each whole leg turns about X at
    // the hip, the hips drop as the legs lean, and each foot turns back so the sole stays
    // level (its new local rotation undoes the turn in the leg's frame).
    auto swayOverFeet = [&](float sway, Pose& p) {
        const float lean = std::asin(sway / legM);
        p.rootTranslation.z += sway;
        p.rootTranslation.y -= legM * (1.0f - std::cos(lean));
        for (int side = 0; side < 2; ++side) {
            const int upper = side == 0 ? kUpperLegL : kUpperLegR;
            const glm::quat leg = idle.rotations[upper] * idle.rotations[upper + 1];
            p.rotations[upper] = aboutX(lean) * idle.rotations[upper];
            p.rotations[upper + 2] = glm::inverse(leg) * aboutX(-lean) * leg * idle.rotations[upper + 2];
        }
    };
    c.actions.push_back(makeAction(c, sim::Clip::Wait, [&](float t, Pose& p) {
        // Weight from foot to foot: the hips sway 3 cm while the feet stay put, the hands
        // rest together in front, the head turns a little now and then.
        swayOverFeet(0.03f * scale * std::sin(t), p);
        p.rotations[kUpperArmL] = aboutZ(0.25f) * aboutX(-0.15f);
        p.rotations[kUpperArmR] = aboutZ(0.25f) * aboutX(0.15f);
        p.rotations[kLowerArmL] = aboutZ(1.1f) * aboutY(-0.5f);
        p.rotations[kLowerArmR] = aboutZ(1.1f) * aboutY(0.5f);
        p.rotations[kNeck] = aboutY(0.25f * std::sin(2.0f * t) * std::max(0.0f, std::sin(t)));
    }));
    c.actions.push_back(makeAction(c, sim::Clip::LookAround, [&](float t, Pose& p) {
        // Left, right and back: the head leads, the chest follows a little.
        p.rotations[kNeck] = aboutY(0.7f * std::sin(t));
        p.rotations[kHead] = aboutZ(0.08f * std::sin(2.0f * t));
        p.rotations[kChest] = aboutY(0.2f * std::sin(t));
    }));
    c.actions.push_back(makeAction(c, sim::Clip::Wave, [&](float t, Pose& p) {
        // The right arm up and out, the forearm upright and swinging side to side.
        p.rotations[kUpperArmR] = aboutX(-2.2f) * aboutZ(0.2f);
        p.rotations[kLowerArmR] = aboutX(-(0.9f + 0.45f * std::sin(t)));
        p.rotations[kHandR] = aboutX(-0.2f * std::sin(t));
        p.rotations[kNeck] = aboutY(0.15f);
    }));
    c.actions.push_back(makeAction(c, sim::Clip::Talk, [&](float t, Pose& p) {
        // Both forearms forward, gesturing out of step; a nod on each gesture.
        p.rotations[kUpperArmL] = aboutZ(0.35f + 0.1f * std::sin(t));
        p.rotations[kUpperArmR] = aboutZ(0.35f + 0.1f * std::sin(t + 2.0f));
        p.rotations[kLowerArmL] = aboutZ(1.2f + 0.35f * std::sin(t)) * aboutY(-0.3f);
        p.rotations[kLowerArmR] = aboutZ(1.2f + 0.35f * std::sin(t + 2.0f)) * aboutY(0.3f);
        p.rotations[kHandL] = aboutX(0.3f * std::sin(t));
        p.rotations[kHandR] = aboutX(-0.3f * std::sin(t + 2.0f));
        p.rotations[kHead] = aboutZ(0.06f * std::sin(2.0f * t));
    }));
    c.actions.push_back(makeAction(c, sim::Clip::Phone, [&](float t, Pose& p) {
        // The right hand at the ear, the head tilted toward it, nodding now and then.
        p.rotations[kUpperArmR] = aboutZ(0.4f) * aboutX(-0.3f);
        p.rotations[kLowerArmR] = aboutZ(2.55f) * aboutY(0.5f);
        p.rotations[kNeck] = aboutX(-0.12f);
        p.rotations[kHead] = aboutZ(0.05f * std::sin(2.0f * t));
    }));
    c.actions.push_back(makeAction(c, sim::Clip::Cheer, [&](float t, Pose& p) {
        // Both arms overhead, pumping.
        const float pump = 0.5f + 0.5f * std::sin(t);
        p.rotations[kUpperArmL] = aboutX(2.7f - 0.25f * pump);
        p.rotations[kUpperArmR] = aboutX(-(2.7f - 0.25f * pump));
        p.rotations[kLowerArmL] = aboutZ(0.2f + 0.5f * pump);
        p.rotations[kLowerArmR] = aboutZ(0.2f + 0.5f * pump);
        p.rotations[kHead] = aboutZ(-0.1f * pump);
    }));
    // Seated on a seat 42 cm high behind the agent: the thighs level, the shins upright
    // with the ankles where standing put them, the hands on the thighs; a slow breath and
    // a glance aside. Slow to sit down and get up (0.8 s), and not over walking.
    const float hipJointM = at[kUpperLegL][3].y - at[kHips][3].y;  // hip joints under the hips joint
    const float ankleM = at[kFootL][3].y, ankleX = at[kFootL][3].x;
    c.actions.push_back(makeAction(
        c, sim::Clip::Sit,
        [&](float t, Pose& p) {
            const float thigh = HumanoidLegs::kThighM * scale, shin = HumanoidLegs::kShinM * scale;
            p.rootTranslation = glm::vec3(ankleX - thigh, ankleM + shin - hipJointM, 0.0f);
            for (int side = 0; side < 2; ++side) {
                const int upper = side == 0 ? kUpperLegL : kUpperLegR;
                // The knees a little apart: the level thigh turns about Y, the toes with it.
                p.rotations[upper] = aboutY(side == 0 ? 0.1f : -0.1f) * aboutZ(1.5708f);
                p.rotations[upper + 1] = aboutZ(-1.5708f);
                p.rotations[upper + 2] = glm::quat(1.0f, 0.0f, 0.0f, 0.0f);
            }
            const float breath = 0.5f + 0.5f * std::sin(t);
            p.rotations[kSpine] = aboutZ(-0.05f);
            p.rotations[kChest] = aboutZ(-0.03f - 0.02f * breath);
            p.rotations[kUpperArmL] = aboutZ(0.55f) * aboutX(-0.12f);
            p.rotations[kUpperArmR] = aboutZ(0.55f) * aboutX(0.12f);
            p.rotations[kLowerArmL] = aboutZ(0.75f);
            p.rotations[kLowerArmR] = aboutZ(0.75f);
            p.rotations[kNeck] = aboutY(0.35f * std::sin(t) * std::max(0.0f, std::sin(2.0f * t)));
        },
        0.8f, false));
    c.actions.push_back(makeAction(
        c, sim::Clip::ShiftWeight,
        [&](float t, Pose& p) {
            // Onto the left leg, held, then onto the right: the hips 5 cm out over the
            // loaded leg, the shoulders leaning back a little the other way.
            const float side = std::tanh(3.0f * std::sin(t));
            swayOverFeet(-0.05f * scale * side, p);
            p.rotations[kChest] = aboutX(0.06f * side);
            p.rotations[kNeck] = aboutX(-0.03f * side);
            p.rotations[kUpperArmL] = aboutX(-0.06f) * aboutZ(0.05f * side);
            p.rotations[kUpperArmR] = aboutX(0.06f) * aboutZ(-0.05f * side);
        },
        0.5f, false));
    c.actions.push_back(makeAction(c, sim::Clip::Point, [&](float t, Pose& p) {
        // The right arm straight out ahead and a little up, the hand bobbing; the head
        // looks where it points.
        p.rotations[kUpperArmR] = aboutZ(1.75f + 0.05f * std::sin(t)) * aboutX(0.1f);
        p.rotations[kLowerArmR] = aboutZ(0.05f);
        p.rotations[kHandR] = aboutZ(0.15f * std::sin(t));
        p.rotations[kChest] = aboutY(-0.1f);
        p.rotations[kNeck] = aboutY(-0.1f) * aboutZ(0.05f);
    }));
    // Falling and getting up: the legs' angles and the trunk's lean come from the keys,
    // and the hips go where the ankles stay put (ahead by ankleForward), so the feet do
    // not slide until the legs stretch out along the ground.
    const glm::vec3 hipOffset = glm::vec3(at[kUpperLegL][3]) - glm::vec3(at[kHips][3]);
    const float thigh = HumanoidLegs::kThighM * scale, shin = HumanoidLegs::kShinM * scale;
    auto posed = [&, thigh, shin](const FallKey& k, Pose& p) {
        const auto along = [](float angle, float length) {  // a limb hanging along -Y turned by angle
            return glm::vec3(length * std::sin(angle), -length * std::cos(angle), 0.0f);
        };
        const glm::vec3 ankle(ankleX + k.ankleForward * scale, ankleM, 0.0f);
        const glm::vec3 hipJoint = ankle - along(k.trunk + k.hip, thigh) - along(k.trunk + k.hip + k.knee, shin);
        const glm::vec3 turned = aboutZ(k.trunk) * glm::vec3(hipOffset.x, hipOffset.y, 0.0f);
        p.rootTranslation = glm::vec3(hipJoint.x - turned.x, hipJoint.y - turned.y, 0.0f);
        p.rotations[kHips] = aboutZ(k.trunk);
        for (int upper : {int(kUpperLegL), int(kUpperLegR)}) {
            p.rotations[std::size_t(upper)] = aboutZ(k.hip);
            p.rotations[std::size_t(upper + 1)] = aboutZ(k.knee);
            // The sole level while the foot is down; lying, the toes up as the leg lies.
            const float level = 1.0f - k.ankleForward / kLying.ankleForward;
            p.rotations[std::size_t(upper + 2)] = aboutZ(-(k.trunk + k.hip + k.knee) * level);
        }
        p.rotations[kSpine] = aboutZ(k.spine);
        p.rotations[kNeck] = aboutZ(k.neck);
        p.rotations[kUpperArmL] = aboutZ(k.armForward) * aboutX(-k.armOut);
        p.rotations[kUpperArmR] = aboutZ(k.armForward) * aboutX(k.armOut);
        p.rotations[kLowerArmL] = aboutZ(k.elbow);
        p.rotations[kLowerArmR] = aboutZ(k.elbow);
    };
    for (const auto& [clip, path] : {std::pair{sim::Clip::Fall, kFalling}, std::pair{sim::Clip::GetUp, kGettingUp}})
        c.actions.push_back(makeOneShot(c, clip, [&](float u, Pose& p) { posed(fallKeyAt(u, path), p); }, 0.15f));
}

}  // namespace throng::exporting
