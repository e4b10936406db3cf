// The horse's actions (sim::Clip's) and its rider's: each a loop over the standing pose.
// The horse waits (head low, tail swishing), looks around (neck and head turn, the rider
// looks too) and shifts its weight (the rider settles in the saddle). The rider waves,
// points ahead, cheers and talks with the right hand; those play over any gait, the arms
// and the rider's head on top of the horse's motion. The horse cannot sit, fall, get up or
// phone: a brain's sit, fall, get_up or phone leaves it in its gait (docs/export.md).
#include "export/character/BuiltinCharacters.h"
#include "export/character/PoseMaths.h"

#include "simcore/scene/Clip.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <functional>
#include <initializer_list>
#include <vector>

namespace throng::exporting {

namespace {

constexpr int kHorseSamplesPerAction = 16;

// The joints an action plays over a gait: `joints`; the rest only as far as the horse stands.
std::vector<std::uint8_t> maskOf(std::initializer_list<int> joints)
{
    std::vector<std::uint8_t> mask(kHorseJointCount, 0);
    for (int j : joints)
        mask[std::size_t(j)] = 1;
    return mask;
}

// One loop: the standing pose changed by `pose(phase in radians, pose)`.
ActionClip makeHorseAction(const Character& c, sim::Clip clip, std::vector<std::uint8_t> layered,
                      const std::function<void(float, Pose&)>& pose)
{
    ActionClip a;
    a.clip.name = sim::toString(clip);
    a.clip.strideM = 1.0f;  // unused: an action's phase runs by time
    a.layered = std::move(layered);
    a.blendS = 0.3f;
    for (int k = 0; k < kHorseSamplesPerAction; ++k) {
        Pose p = c.idle.samples.front();
        pose(2.0f * kPi * static_cast<float>(k) / static_cast<float>(kHorseSamplesPerAction), p);
        a.clip.samples.push_back(std::move(p));
    }
    return a;
}

// The shortest rotation taking direction `from` to direction `to` (not opposite).
glm::quat turning(glm::vec3 from, glm::vec3 to)
{
    from = glm::normalize(from);
    to = glm::normalize(to);
    return glm::normalize(glm::quat(1.0f + glm::dot(from, to), glm::cross(from, to)));
}

}  // namespace

void addHorseActions(Character& c)
{
    // Joint rotations are absolute (every rest rotation is identity); standing, the rider's
    // frame is the horse's. The rider's arms reach forward and down to the reins.
    const std::vector<std::uint8_t> rider =
        maskOf({kHorseRiderChest, kHorseRiderHead, kHorseRiderUpperArmL, kHorseRiderLowerArmL, kHorseRiderHandL,
                kHorseRiderUpperArmR, kHorseRiderLowerArmR, kHorseRiderHandR});
    c.actions.push_back(makeHorseAction(c, sim::Clip::Wait, maskOf({}), [](float t, Pose& p) {
        p.rotations[kHorseNeck] = aboutZ(-0.3f + 0.03f * std::sin(t));
        p.rotations[kHorseHead] = aboutZ(-0.15f);
        p.rotations[kHorseTail] = aboutZ(-0.25f) * aboutY(0.3f * std::sin(2.0f * t));
        p.rotations[kHorseRiderChest] = aboutZ(0.05f);
    }));
    c.actions.push_back(makeHorseAction(c, sim::Clip::LookAround, maskOf({kHorseRiderHead}), [](float t, Pose& p) {
        p.rotations[kHorseNeck] = aboutY(0.35f * std::sin(t)) * aboutZ(0.05f);
        p.rotations[kHorseHead] = aboutY(0.25f * std::sin(t)) * aboutZ(0.05f * std::sin(2.0f * t));
        p.rotations[kHorseRiderHead] = aboutY(0.8f * std::sin(t + 0.5f));
        p.rotations[kHorseRiderChest] = aboutY(0.15f * std::sin(t + 0.5f));
    }));
    c.actions.push_back(makeHorseAction(c, sim::Clip::ShiftWeight, maskOf({}), [](float t, Pose& p) {
        p.rotations[kHorseRiderHips] = aboutX(0.08f * std::sin(t));
        p.rotations[kHorseRiderChest] = aboutX(-0.06f * std::sin(t));
        p.rotations[kHorseNeck] = aboutZ(-0.1f) * aboutY(0.1f * std::sin(t));
        p.rotations[kHorseTail] = aboutZ(-0.25f) * aboutY(0.15f * std::sin(t));
    }));
    // The rider's arm on `side` (+1 right, -1 left) aimed: the upper arm along `upper`, the
    // forearm along `fore` (directions in the rider's frame, x ahead, y up, z right).
    auto aim = [&c](Pose& p, float side, glm::vec3 upper, glm::vec3 fore) {
        const int arm = side > 0.0f ? kHorseRiderUpperArmR : kHorseRiderUpperArmL;
        const glm::vec3 restUpper = c.joints[std::size_t(arm + 1)].restTranslation;
        const glm::vec3 restFore = c.joints[std::size_t(arm + 2)].restTranslation;
        const glm::vec3 mirror(1.0f, 1.0f, side);
        const glm::quat u = turning(restUpper, upper * mirror);
        p.rotations[std::size_t(arm)] = u;
        p.rotations[std::size_t(arm + 1)] = glm::inverse(u) * turning(restFore, fore * mirror);
    };
    c.actions.push_back(makeHorseAction(c, sim::Clip::Wave, rider, [&](float t, Pose& p) {
        aim(p, 1.0f, {0.15f, 0.8f, 0.6f}, {0.05f, 1.0f, 0.2f + 0.5f * std::sin(2.0f * t)});
        p.rotations[kHorseRiderHead] = aboutY(-0.2f);
    }));
    c.actions.push_back(makeHorseAction(c, sim::Clip::Point, rider, [&](float t, Pose& p) {
        const glm::vec3 ahead(1.0f, 0.05f + 0.03f * std::sin(t), 0.25f);
        aim(p, 1.0f, ahead, ahead);
        p.rotations[kHorseRiderHead] = aboutZ(0.05f);
    }));
    c.actions.push_back(makeHorseAction(c, sim::Clip::Cheer, rider, [&](float t, Pose& p) {
        const float pump = 0.5f + 0.5f * std::sin(2.0f * t);
        for (const float side : {-1.0f, 1.0f})
            aim(p, side, {0.1f, 0.9f, 0.35f}, {0.1f + 0.3f * pump, 1.0f, 0.1f});
        p.rotations[kHorseRiderHead] = aboutZ(0.25f);
    }));
    c.actions.push_back(makeHorseAction(c, sim::Clip::Talk, rider, [&](float t, Pose& p) {
        aim(p, 1.0f, {0.3f, -0.85f, 0.35f}, {0.9f, 0.35f + 0.3f * std::sin(2.0f * t), 0.2f});
        p.rotations[kHorseRiderHead] = aboutZ(0.08f * std::sin(3.0f * t)) * aboutY(-0.3f);
    }));
}

}  // namespace throng::exporting
