// The built-in horse with its rider: one skeleton and one smooth skinned surface (the
// horse's coat, mane, tail and hooves, a saddle cloth, and a seated rider in a helmet,
// hands on the reins), and four gaits on a ladder (walk, trot, canter, gallop). Each
// gait is its own footfall pattern, the hooves placed by two-bone IK on a path that
// holds a hoof still on the ground while the body covers one stride per cycle, so every
// hoof that touches down stays where it landed until it lifts. The body rises and falls
// and pitches over the hooves that carry it; the head nods; the rider sits the motion.
#include "export/character/BuiltinCharacters.h"
#include "export/character/PoseMaths.h"
#include "export/character/StrideMaths.h"
#include "export/character/SurfaceBuilder.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace throng::exporting {

namespace {

constexpr int kHorseSamplesPerCycle = 128;

// Leg order in the tables below: left fore, right fore, left hind, right hind.
constexpr int kLegs = 4;
constexpr std::array<int, kLegs> kUpper{kHorseForeUpperL, kHorseForeUpperR, kHorseHindUpperL, kHorseHindUpperR};
constexpr float kHoofM = 0.08f;             // hoof joint above the ground, standing
// The legs hang from high in the body (the shoulder blade's and the hip's pivots), so a
// gallop's stance sweeps them through little more than 20 degrees.
constexpr float kForeUpperM = 0.66f, kForeLowerM = 0.68f, kHindUpperM = 0.68f, kHindLowerM = 0.68f;
// Hooves land and lift moving back under the body at 65 % of its speed: little slide on the
// ground, and little reach past where they land.
constexpr float kLanding = 0.65f;

const JointSpec kSpecs[kHorseJointCount] = {
    {"body", -1, {0.0f, 1.22f, 0.0f}},
    {"neck", kHorseBody, {0.72f, 0.18f, 0.0f}},
    {"head", kHorseNeck, {0.42f, 0.48f, 0.0f}},
    {"tail", kHorseBody, {-0.88f, 0.16f, 0.0f}},
    {"fore_upper_l", kHorseBody, {0.58f, 0.2f, -0.17f}},
    {"fore_lower_l", kHorseForeUpperL, {0.0f, -kForeUpperM, 0.0f}},
    {"fore_hoof_l", kHorseForeLowerL, {0.0f, -kForeLowerM, 0.0f}},
    {"fore_upper_r", kHorseBody, {0.58f, 0.2f, 0.17f}},
    {"fore_lower_r", kHorseForeUpperR, {0.0f, -kForeUpperM, 0.0f}},
    {"fore_hoof_r", kHorseForeLowerR, {0.0f, -kForeLowerM, 0.0f}},
    {"hind_upper_l", kHorseBody, {-0.62f, 0.22f, -0.17f}},
    {"hind_lower_l", kHorseHindUpperL, {0.0f, -kHindUpperM, 0.0f}},
    {"hind_hoof_l", kHorseHindLowerL, {0.0f, -kHindLowerM, 0.0f}},
    {"hind_upper_r", kHorseBody, {-0.62f, 0.22f, 0.17f}},
    {"hind_lower_r", kHorseHindUpperR, {0.0f, -kHindUpperM, 0.0f}},
    {"hind_hoof_r", kHorseHindLowerR, {0.0f, -kHindLowerM, 0.0f}},
    {"rider_hips", kHorseBody, {0.12f, 0.4f, 0.0f}},
    {"rider_chest", kHorseRiderHips, {0.0f, 0.3f, 0.0f}},
    {"rider_head", kHorseRiderChest, {0.02f, 0.3f, 0.0f}},
    // The rider's arms reach forward and down to the reins: shoulder, elbow, hand.
    {"rider_upper_arm_l", kHorseRiderChest, {0.02f, 0.15f, -0.19f}},
    {"rider_lower_arm_l", kHorseRiderUpperArmL, {0.05f, -0.26f, -0.02f}},
    {"rider_hand_l", kHorseRiderLowerArmL, {0.37f, -0.09f, 0.11f}},
    {"rider_upper_arm_r", kHorseRiderChest, {0.02f, 0.15f, 0.19f}},
    {"rider_lower_arm_r", kHorseRiderUpperArmR, {0.05f, -0.26f, 0.02f}},
    {"rider_hand_r", kHorseRiderLowerArmR, {0.37f, -0.09f, -0.11f}},
};

// One gait: the hooves' path, when each touches down (the cycle phase; leg order above),
// and how the head and the rider move with it.
struct HorseGait {
    const char* name;
    FootPath path;
    std::array<float, kLegs> touchDown;
    float nod;        // rad, the neck's swing
    int nodsPerCycle;
    float riderLean;  // rad forward
};

// Walk: four beats (left hind, left fore, right hind, right fore), three hooves down at a
// time. Trot: diagonal pairs together. Canter (right lead): left hind, then right hind with
// left fore, then right fore; a moment of suspension. Gallop (right lead): four beats, each
// hoof down a fifth of the cycle, a long suspension. Strides in m per cycle.
const HorseGait kWalk{"walk", {1.6f, 0.62f, 0.12f, kLanding}, {0.25f, 0.75f, 0.0f, 0.5f}, 0.07f, 2, 0.05f};
const HorseGait kTrot{"trot", {2.5f, 0.42f, 0.2f, kLanding}, {0.0f, 0.5f, 0.5f, 0.0f}, 0.02f, 2, 0.1f};
const HorseGait kCanter{"canter", {3.4f, 0.3f, 0.24f, kLanding}, {0.3f, 0.55f, 0.0f, 0.3f}, 0.12f, 1, 0.22f};
const HorseGait kGallop{"gallop", {5.0f, 0.21f, 0.3f, kLanding}, {0.45f, 0.57f, 0.0f, 0.12f}, 0.16f, 1, 0.35f};
// The speeds (m/s) at which each is the whole gait; between two, the one blends into the next.
constexpr std::array<float, 4> kLadderSpeeds{1.0f, 3.0f, 5.5f, 9.0f};

bool isFore(int leg) { return leg < 2; }
float upperM(int leg) { return isFore(leg) ? kForeUpperM : kHindUpperM; }
float lowerM(int leg) { return isFore(leg) ? kForeLowerM : kHindLowerM; }
float reachM(int leg) { return 0.995f * (upperM(leg) + lowerM(leg)); }

// The pose at cycle phase p: each hoof on its path, the body at the height (and pitch)
// that the hooves on the ground allow, the neck nodding, the rider sitting it.
Pose posedAt(const Character& c, const HorseGait& g, float p)
{
    Pose pose;
    pose.rotations.assign(c.joints.size(), glm::quat(1.0f, 0.0f, 0.0f, 0.0f));
    // Each leg's hoof target (x from its upper joint's rest place, y above the ground) and
    // the highest its upper joint may stand for the hoof to reach it. Each end of the body
    // stands at the lower of its two legs' heights: every hoof reaches its target, down or
    // swinging, and the height changes smoothly as hooves land and lift.
    std::array<glm::vec2, kLegs> hoof{};
    std::array<float, 2> carried{1e9f, 1e9f};  // fore, hind: upper joints' height over the standing hoof joints
    for (int leg = 0; leg < kLegs; ++leg) {
        const float s = std::fmod(p - g.touchDown[std::size_t(leg)] + 2.0f, 1.0f);
        hoof[std::size_t(leg)] = footTarget(g.path, s, kHoofM);
        const float x = hoof[std::size_t(leg)].x, r = reachM(leg);
        const float h = std::sqrt(std::max(0.0f, r * r - x * x)) + hoof[std::size_t(leg)].y - kHoofM;
        float& end = carried[isFore(leg) ? 0 : 1];
        end = std::min(end, h);
    }
    const glm::vec3 foreAt = c.joints[kHorseForeUpperL].restTranslation;
    const glm::vec3 hindAt = c.joints[kHorseHindUpperL].restTranslation;
    const float foreBody = kHoofM + carried[0] - foreAt.y, hindBody = kHoofM + carried[1] - hindAt.y;
    const float pitch = std::atan2(foreBody - hindBody, foreAt.x - hindAt.x);
    // The body's height where the two ends meet their heights, on the line between them.
    const float t = -hindAt.x / (foreAt.x - hindAt.x);
    pose.rootTranslation = glm::vec3(0.0f, hindBody + t * (foreBody - hindBody), 0.0f);
    const glm::quat body = aboutZ(pitch);
    pose.rotations[kHorseBody] = body;
    // The ends' heights ignore how the pitch moves the upper joints: lower the body by
    // what any leg then still lacks to reach its hoof's target.
    float lacking = 0.0f;
    for (int leg = 0; leg < kLegs; ++leg) {
        const int upper = kUpper[std::size_t(leg)];
        const glm::vec3 joint = pose.rootTranslation + body * c.joints[std::size_t(upper)].restTranslation;
        const glm::vec2 target(c.joints[std::size_t(upper)].restTranslation.x + hoof[std::size_t(leg)].x,
                               hoof[std::size_t(leg)].y);
        const float dx = target.x - joint.x, r = reachM(leg);
        const float highest = target.y + std::sqrt(std::max(0.0f, r * r - dx * dx));
        lacking = std::max(lacking, joint.y - highest);
    }
    pose.rootTranslation.y -= lacking;
    for (int leg = 0; leg < kLegs; ++leg) {
        const int upper = kUpper[std::size_t(leg)];
        const glm::vec3 joint = pose.rootTranslation + body * c.joints[std::size_t(upper)].restTranslation;
        const glm::vec2 target(c.joints[std::size_t(upper)].restTranslation.x + hoof[std::size_t(leg)].x,
                               hoof[std::size_t(leg)].y);
        const auto [swing, bend] =
            legAngles(target - glm::vec2(joint.x, joint.y), upperM(leg), lowerM(leg), !isFore(leg));
        pose.rotations[std::size_t(upper)] = aboutZ(swing - pitch);
        pose.rotations[std::size_t(upper + 1)] = aboutZ(bend);
        pose.rotations[std::size_t(upper + 2)] = aboutZ(-(swing + bend));  // the hoof's sole level
    }
    const float nod = g.nod * std::sin(2.0f * kPi * float(g.nodsPerCycle) * p);
    pose.rotations[kHorseNeck] = aboutZ(-pitch * 0.5f + nod);
    pose.rotations[kHorseHead] = aboutZ(-0.5f * nod);
    pose.rotations[kHorseTail] = aboutZ(-0.25f - 0.5f * g.riderLean) * aboutY(0.08f * std::sin(2.0f * kPi * p));
    // The rider keeps upright against the horse's pitch and leans into the faster gaits.
    pose.rotations[kHorseRiderHips] = aboutZ(-0.8f * pitch);
    pose.rotations[kHorseRiderChest] = aboutZ(-g.riderLean);
    pose.rotations[kHorseRiderHead] = aboutZ(0.7f * g.riderLean);
    return pose;
}

CycleClip makeCycle(const Character& c, const HorseGait& g, int samples)
{
    CycleClip clip;
    clip.name = g.name;
    clip.strideM = g.path.strideM;
    for (int k = 0; k < samples; ++k)
        clip.samples.push_back(posedAt(c, g, static_cast<float>(k) / static_cast<float>(samples)));
    return clip;
}

}  // namespace

Character makeHorse(Lod lod)
{
    Character c;
    c.name = "horse";
    std::vector<glm::vec3> at(kHorseJointCount);  // joint positions in bind space
    for (int j = 0; j < kHorseJointCount; ++j) {
        Joint joint;
        joint.name = kSpecs[j].name;
        joint.parent = kSpecs[j].parent;
        joint.restTranslation = kSpecs[j].offset;
        const glm::vec3 parentAt = joint.parent < 0 ? glm::vec3(0.0f) : at[std::size_t(joint.parent)];
        at[std::size_t(j)] = joint.restTranslation + parentAt;
        c.joints.push_back(joint);
    }
    SurfaceBuilder sb(c.mesh, lod);
    const glm::vec3 up(0.0f, 1.0f, 0.0f), ahead(1.0f, 0.0f, 0.0f);
    const MaterialSlot coat = MaterialSlot::Hair, dark = MaterialSlot::Shoes;
    auto tube = [&](std::vector<TubeSection> sections, std::vector<TubeBone> bones, glm::vec3 forward, float startCap,
                    float endCap, float blend = 0.08f, bool small = false) {
        Tube t;
        t.sections = std::move(sections);
        t.bones = std::move(bones);
        t.forward = forward;
        t.startCapM = startCap;
        t.endCapM = endCap;
        t.blendM = blend;
        t.small = small;
        sb.tube(t);
    };
    // The barrel, rump to breast, with the saddle cloth over the back.
    tube({{{-1.0f, 1.3f, 0.0f}, 0.14f, 0.12f, coat},
          {{-0.85f, 1.27f, 0.0f}, 0.29f, 0.24f, coat},
          {{-0.55f, 1.24f, 0.0f}, 0.35f, 0.29f, coat},
          {{-0.1f, 1.2f, 0.0f}, 0.36f, 0.3f, coat},
          {{0.35f, 1.22f, 0.0f}, 0.35f, 0.28f, coat},
          {{0.68f, 1.26f, 0.0f}, 0.31f, 0.24f, coat},
          {{0.86f, 1.28f, 0.0f}, 0.19f, 0.17f, coat}},
         {{kHorseBody, 0.0f}}, up, 0.08f, 0.1f);
    tube({{{-0.2f, 1.47f, 0.0f}, 0.1f, 0.3f, MaterialSlot::Body},
          {{0.05f, 1.49f, 0.0f}, 0.11f, 0.32f, MaterialSlot::Body},
          {{0.38f, 1.48f, 0.0f}, 0.1f, 0.3f, MaterialSlot::Body}},
         {{kHorseBody, 0.0f}}, up, 0.02f, 0.02f);
    // Neck, head, ears and mane.
    tube({{{0.66f, 1.33f, 0.0f}, 0.25f, 0.17f, coat},
          {{0.88f, 1.56f, 0.0f}, 0.19f, 0.12f, coat},
          {{1.05f, 1.78f, 0.0f}, 0.14f, 0.09f, coat},
          {{1.14f, 1.9f, 0.0f}, 0.12f, 0.08f, coat}},
         {{kHorseBody, 0.0f}, {kHorseNeck, 0.6f}, {kHorseHead, 2.7f}}, ahead, 0.1f, 0.06f);
    tube({{{1.1f, 1.95f, 0.0f}, 0.1f, 0.09f, coat},
          {{1.25f, 1.79f, 0.0f}, 0.11f, 0.09f, coat},
          {{1.42f, 1.59f, 0.0f}, 0.08f, 0.07f, coat},
          {{1.52f, 1.47f, 0.0f}, 0.07f, 0.06f, coat}},
         {{kHorseHead, 0.0f}}, ahead, 0.06f, 0.05f);
    for (float side : {-1.0f, 1.0f})
        tube({{{1.09f, 1.99f, side * 0.05f}, 0.03f, 0.025f, coat}, {{1.07f, 2.11f, side * 0.06f}, 0.012f, 0.01f, coat}},
             {{kHorseHead, 0.0f}}, ahead, -1.0f, 0.01f, 0.02f, true);
    tube({{{0.66f, 1.56f, 0.0f}, 0.03f, 0.025f, dark},
          {{0.86f, 1.73f, 0.0f}, 0.05f, 0.03f, dark},
          {{1.06f, 1.98f, 0.0f}, 0.04f, 0.025f, dark}},
         {{kHorseBody, 0.0f}, {kHorseNeck, 0.5f}, {kHorseHead, 1.8f}}, ahead, 0.02f, 0.02f, 0.06f, true);
    // Tail.
    tube({{{-0.94f, 1.36f, 0.0f}, 0.07f, 0.05f, dark},
          {{-1.1f, 1.05f, 0.0f}, 0.1f, 0.07f, dark},
          {{-1.14f, 0.68f, 0.0f}, 0.05f, 0.04f, dark}},
         {{kHorseTail, 0.0f}}, ahead, 0.03f, 0.04f);
    // Legs, upper joint to hoof: coat down to the fetlock, then the dark hoof.
    for (int leg = 0; leg < kLegs; ++leg) {
        const int upper = kUpper[std::size_t(leg)];
        const glm::vec3 top = at[std::size_t(upper)], knee = at[std::size_t(upper + 1)];
        const glm::vec3 foot = at[std::size_t(upper + 2)];
        const bool fore = isFore(leg);
        const float thigh = fore ? 0.13f : 0.2f;
        tube({{top + glm::vec3(fore ? 0.02f : -0.04f, 0.16f, 0.0f), thigh * 1.1f, 0.1f, coat},
              {top + glm::vec3(0.0f, -0.05f, 0.0f), thigh, 0.085f, coat},
              {glm::mix(top, knee, 0.55f), fore ? 0.085f : 0.1f, 0.07f, coat},
              {knee, 0.065f, 0.055f, coat},
              {glm::mix(knee, foot, 0.5f), 0.045f, 0.04f, coat},
              {foot + glm::vec3(0.0f, 0.05f, 0.0f), 0.055f, 0.05f, coat},
              {foot + glm::vec3(0.01f, 0.0f, 0.0f), 0.06f, 0.055f, dark},
              {foot + glm::vec3(0.02f, -kHoofM, 0.0f), 0.07f, 0.06f, dark}},
             {{upper, 0.0f}, {upper + 1, 3.0f}, {upper + 2, 5.0f}}, ahead, 0.06f, 0.0f, 0.06f);
    }
    // The rider: torso, head under a helmet, arms to the reins, legs astride (with the horse).
    const glm::vec3 seat = at[kHorseRiderHips];
    tube({{seat + glm::vec3(-0.02f, -0.04f, 0.0f), 0.1f, 0.16f, MaterialSlot::Bottom},
          {seat + glm::vec3(0.0f, 0.1f, 0.0f), 0.11f, 0.16f, MaterialSlot::Top},
          {seat + glm::vec3(0.01f, 0.32f, 0.0f), 0.12f, 0.19f, MaterialSlot::Top},
          {seat + glm::vec3(0.01f, 0.48f, 0.0f), 0.09f, 0.15f, MaterialSlot::Top}},
         {{kHorseRiderHips, 0.0f}, {kHorseRiderChest, 1.6f}}, ahead, 0.04f, 0.03f, 0.06f);
    const glm::vec3 head = at[kHorseRiderHead];
    tube({{head + glm::vec3(0.0f, -0.08f, 0.0f), 0.045f, 0.045f, MaterialSlot::Skin},
          {head + glm::vec3(0.01f, 0.04f, 0.0f), 0.1f, 0.085f, MaterialSlot::Skin},
          {head + glm::vec3(0.0f, 0.16f, 0.0f), 0.08f, 0.07f, MaterialSlot::Skin}},
         {{kHorseRiderChest, 0.0f}, {kHorseRiderHead, 0.8f}}, ahead, 0.02f, 0.03f, 0.04f);
    tube({{head + glm::vec3(-0.01f, 0.09f, 0.0f), 0.115f, 0.1f, MaterialSlot::Hat},
          {head + glm::vec3(-0.01f, 0.2f, 0.0f), 0.09f, 0.08f, MaterialSlot::Hat}},
         {{kHorseRiderHead, 0.0f}}, ahead, 0.0f, 0.04f);
    for (float side : {-1.0f, 1.0f}) {
        const int upperArm = side < 0.0f ? kHorseRiderUpperArmL : kHorseRiderUpperArmR;
        const glm::vec3 shoulder = at[std::size_t(upperArm)], elbow = at[std::size_t(upperArm + 1)];
        const glm::vec3 hand = at[std::size_t(upperArm + 2)];
        tube({{shoulder, 0.05f, 0.05f, MaterialSlot::Top},
              {elbow, 0.04f, 0.04f, MaterialSlot::Top},
              {hand + glm::vec3(-0.06f, 0.0f, side * 0.02f), 0.035f, 0.035f, MaterialSlot::Top},
              {hand, 0.03f, 0.025f, MaterialSlot::Skin}},
             {{kHorseRiderChest, 0.0f}, {upperArm, 0.2f}, {upperArm + 1, 1.0f}, {upperArm + 2, 2.6f}}, up, 0.04f,
             0.02f);
        tube({{seat + glm::vec3(0.0f, -0.02f, side * 0.12f), 0.08f, 0.08f, MaterialSlot::Bottom},
              {seat + glm::vec3(0.2f, -0.12f, side * 0.3f), 0.065f, 0.06f, MaterialSlot::Bottom},
              {seat + glm::vec3(0.26f, -0.2f, side * 0.33f), 0.055f, 0.055f, MaterialSlot::Bottom},
              {seat + glm::vec3(0.08f, -0.52f, side * 0.33f), 0.045f, 0.045f, dark},
              {seat + glm::vec3(0.12f, -0.6f, side * 0.33f), 0.04f, 0.04f, dark}},
             {{kHorseBody, 0.0f}}, up, 0.04f, 0.03f);
    }
    sb.setWornShare(MaterialSlot::Hat, 1.0f);
    sb.finish();
    c.mesh.inverseBindMatrices = restInverseBindMatrices(c.joints);

    // Standing square: every hoof under its upper joint; the rider upright.
    HorseGait stand = kWalk;
    stand.name = "idle";
    stand.path.strideM = 0.0f;
    stand.path.liftM = 0.0f;
    stand.nod = 0.0f;
    stand.riderLean = 0.0f;
    c.idle = makeCycle(c, stand, 1);
    c.idle.strideM = kWalk.path.strideM;
    for (const HorseGait* g : {&kWalk, &kTrot, &kCanter, &kGallop})
        c.ladder.push_back(makeCycle(c, *g, kHorseSamplesPerCycle));
    c.ladderSpeeds.assign(kLadderSpeeds.begin(), kLadderSpeeds.end());
    // Legs for the foot planter (FootPlanter.h): hooves locked where they land through
    // changes of gait and stops, and stood on the terrain.
    const std::vector<glm::mat4> standing = jointGlobalTransforms(c, sampleClip(c.idle, 0.0));
    for (const int upper : kUpper)
        c.legs.push_back({upper, upper + 1, upper + 2, glm::vec3(standing[std::size_t(upper + 2)][3])});
    c.walk = c.ladder.front();
    c.run = c.ladder.back();
    c.hasIdle = true;
    c.idleSpeed = 0.05f;
    c.walkSpeed = 0.4f;
    c.keyToleranceScale = 0.3f;  // 0.06 degrees by default: a hoof within 1.5 mm of its key
    c.runStartSpeed = kLadderSpeeds[2];
    c.runSpeed = kLadderSpeeds[3];
    addHorseActions(c);
    return c;
}

}  // namespace throng::exporting
