// Humanoid idle, walk and run. Legs are placed by two-bone IK on a foot path that holds
// the stance foot still on the ground while the body covers one stride per cycle, so a
// gait that advances the phase by distance / stride keeps planted feet where they are.
#include "export/character/BuiltinCharacters.h"
#include "export/character/PoseMaths.h"
#include "export/character/StrideMaths.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace throng::exporting {

namespace {

constexpr int kWalkSamplesPerCycle = 24;

struct GaitShape {
    float strideM;       // per cycle
    float duty;          // fraction of the cycle a foot is on the ground
    float reachM;        // stance leg length, hip joint to ankle
    float liftM;         // swing foot height
    float flightRiseM;   // hips rise while both feet are off the ground
    float armSwing, elbow, lean, chestTwist;  // rad
};

FootPath pathOf(const GaitShape& g)
{
    return {g.strideM, g.duty, g.liftM};
}

// Height of the hip joints above the ground at body phase p: over the stance foot's
// straight-ish leg (an inverted pendulum), rising ballistically while airborne.
float legRootHeight(const GaitShape& g, float p, float ankleM)
{
    const float half = 0.5f * g.duty * g.strideM;
    float best = -1.0f;
    for (float s : {p, std::fmod(p + 0.5f, 1.0f)}) {
        if (s < g.duty) {
            const float x = footTarget(pathOf(g), s, ankleM).x;
            const float h = std::sqrt(std::max(0.0f, g.reachM * g.reachM - x * x));
            best = best < 0.0f ? h : std::min(best, h);
        }
    }
    if (best >= 0.0f)
        return ankleM + best;
    const float edge = std::sqrt(std::max(0.0f, g.reachM * g.reachM - half * half));
    const float flight = 0.5f - g.duty;
    const float v = std::fmod(p, 0.5f) - g.duty;  // time into the flight of this half cycle
    return ankleM + edge + g.flightRiseM * std::sin(kPi * v / flight);
}

Pose posedAt(const Character& c, const GaitShape& g, float p, float scale)
{
    using L = HumanoidLegs;
    const float thigh = L::kThighM * scale, shin = L::kShinM * scale, ankle = L::kAnkleM * scale;
    Pose pose;
    pose.rotations.assign(c.joints.size(), glm::quat(1.0f, 0.0f, 0.0f, 0.0f));
    const float legRoot = legRootHeight(g, p, ankle);
    const float hipToLegRoot = -c.joints[kUpperLegL].restTranslation.y;
    pose.rootTranslation = {0.0f, legRoot + hipToLegRoot, 0.0f};
    for (int side = 0; side < 2; ++side) {
        const float s = std::fmod(p + 0.5f * static_cast<float>(side), 1.0f);
        const glm::vec2 foot = footTarget(pathOf(g), s, ankle);
        const auto [hip, knee] = legAngles({foot.x, foot.y - legRoot}, thigh, shin);
        const int upper = side == 0 ? kUpperLegL : kUpperLegR;
        pose.rotations[upper] = aboutZ(hip);
        pose.rotations[upper + 1] = aboutZ(knee);
        pose.rotations[upper + 2] = aboutZ(-(hip + knee));  // sole parallel to the ground
    }
    const float swing = std::cos(2.0f * kPi * p);
    pose.rotations[kUpperArmL] = aboutZ(-g.armSwing * swing);
    pose.rotations[kUpperArmR] = aboutZ(g.armSwing * swing);
    pose.rotations[kLowerArmL] = aboutZ(g.elbow * (1.0f - 0.3f * swing));
    pose.rotations[kLowerArmR] = aboutZ(g.elbow * (1.0f + 0.3f * swing));
    pose.rotations[kSpine] = aboutZ(-g.lean);
    pose.rotations[kChest] = aboutY(g.chestTwist * swing);
    pose.rotations[kNeck] = aboutY(-g.chestTwist * swing) * aboutZ(0.6f * g.lean);
    return pose;
}

CycleClip makeCycle(const Character& c, const char* name, const GaitShape& g, float scale, int samples)
{
    CycleClip clip;
    clip.name = name;
    clip.strideM = g.strideM;
    for (int k = 0; k < samples; ++k)
        clip.samples.push_back(posedAt(c, g, static_cast<float>(k) / static_cast<float>(samples), scale));
    return clip;
}

}  // namespace

void addHumanoidClips(Character& c, float scale)
{
    using L = HumanoidLegs;
    const float leg = (L::kThighM + L::kShinM) * scale;
    // Walk: a foot is down half of the cycle; run: 35 %, with two flights per cycle.
    const GaitShape walk{1.5f * leg, 0.5f, 0.985f * leg, 0.1f * leg, 0.0f, 0.35f, 0.25f, 0.03f, 0.08f};
    const GaitShape run{3.0f * leg, 0.35f, 0.93f * leg, 0.22f * leg, 0.05f * leg, 0.7f, 1.3f, 0.18f, 0.15f};
    // Idle: feet together under the hips, legs as at the walk's mid-stance, arms down.
    GaitShape stand = walk;
    stand.strideM = 0.0f;
    stand.armSwing = 0.0f;
    stand.elbow = 0.08f;
    stand.chestTwist = 0.0f;
    stand.lean = 0.0f;
    c.idle = makeCycle(c, "idle", stand, scale, 1);
    c.idle.strideM = walk.strideM;
    c.walk = makeCycle(c, "walk", walk, scale, kWalkSamplesPerCycle);
    c.run = makeCycle(c, "run", run, scale, kWalkSamplesPerCycle);
    c.hasIdle = true;
    c.idleSpeed = 0.05f * scale;
    c.walkSpeed = 0.4f * scale;
    c.runStartSpeed = 2.2f * scale;
    c.runSpeed = 3.0f * scale;
}

}  // namespace throng::exporting
