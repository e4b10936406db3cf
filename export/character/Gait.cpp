#include "export/character/Gait.h"

#include "export/character/LegIk.h"
#include "export/character/PoseMaths.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <optional>
#include <utility>

namespace throng::exporting {

namespace {

// Where runWeight puts a character with a gait ladder: the rung below and the share of
// the one above (runWeight runs over the whole ladder, 0 the first rung, 1 the last).
std::pair<std::size_t, float> rungAt(const Character& c, float runWeight)
{
    const float r = std::clamp(runWeight, 0.0f, 1.0f) * static_cast<float>(c.ladder.size() - 1);
    const std::size_t k = std::min(static_cast<std::size_t>(r), c.ladder.size() - 2);
    return {k, r - static_cast<float>(k)};
}

// runWeight for `speed`: along the ladder by its speeds (each rung blending into the next
// up to its speed), else from walk to run between runStartSpeed and runSpeed.
float runWeightAt(const Character& c, float speed, float k)
{
    if (c.ladder.empty())
        return smoothstep(c.runStartSpeed * k, c.runSpeed * k, speed);
    const std::size_t n = c.ladder.size();
    for (std::size_t r = 0; r + 1 < n; ++r)
        if (speed < c.ladderSpeeds[r + 1] * k)
            return (static_cast<float>(r) + smoothstep(c.ladderSpeeds[r] * k, c.ladderSpeeds[r + 1] * k, speed)) /
                   static_cast<float>(n - 1);
    return 1.0f;
}

}  // namespace

double strideAt(const Character& c, float runWeight, float heightScale)
{
    if (!c.ladder.empty()) {
        const auto [k, t] = rungAt(c, runWeight);
        const double lo = c.ladder[k].strideM, hi = c.ladder[k + 1].strideM;
        return (lo + (hi - lo) * static_cast<double>(t)) * static_cast<double>(heightScale);
    }
    const double walk = c.walk.strideM, run = c.run.strideM;
    return (walk + (run - walk) * static_cast<double>(runWeight)) * static_cast<double>(heightScale);
}

namespace {

// The action each frame plays, blended: a new action fades in over its blend time while
// the one before fades out from where it was; one that ends fades out. An action already
// playing on the first frame plays in full from it. A one-shot's phase runs from the frame
// it started (sim::oneShotProgress) to its last sample, where it stays.
void layerActions(const Character& c, const RecordedClips& recorded, std::vector<GaitFrame>& out)
{
    if (c.actions.empty() || recorded.clips.size() != out.size() || recorded.phases.size() != out.size())
        return;
    const float dt = recorded.fps > 0.0f ? 1.0f / recorded.fps : 0.0f;
    // Weight gained or lost per frame, and cycles played per frame, of action a.
    auto rate = [&](int a) {
        const float blend = recorded.blendS >= 0.0f ? recorded.blendS : c.actions[static_cast<std::size_t>(a)].blendS;
        return blend > 0.0f ? dt / blend : 1.0f;
    };
    auto cyclesPerFrame = [&](int a) {
        const std::optional<sim::Clip> clip = sim::clipFromName(c.actions[static_cast<std::size_t>(a)].clip.name);
        const float cycle = clip ? sim::clipCycleS(*clip) : 0.0f;
        return cycle > 0.0f ? static_cast<double>(dt / cycle) : 0.0;
    };
    // A one-shot's last sample, in cycles: where it stops and stays.
    auto lastPhase = [&](int a) {
        const std::size_t n = c.actions[static_cast<std::size_t>(a)].clip.samples.size();
        return n > 1 ? static_cast<double>(n - 1) / static_cast<double>(n) : 0.0;
    };
    auto oneShot = [&](int a) { return a >= 0 && c.actions[static_cast<std::size_t>(a)].oneShot; };
    ActionLayer current, fading;
    std::size_t started = 0;  // the frame the current action started on
    for (std::size_t f = 0; f < out.size(); ++f) {
        const sim::Clip clip = recorded.clips[f];
        const int action = sim::isAction(clip) ? c.actionIndex(sim::toString(clip)) : -1;
        if (fading.action >= 0) {
            fading.phase += cyclesPerFrame(fading.action) * (oneShot(fading.action) ? lastPhase(fading.action) : 1.0);
            if (oneShot(fading.action))
                fading.phase = std::min(fading.phase, lastPhase(fading.action));
            fading.weight -= rate(fading.action);
            if (fading.weight <= 0.0f)
                fading = {};
        }
        // The weights count time from the frame of the switch: the new action is at 0 there
        // and the old at its last weight, so the two sum to what was playing, and each
        // frame after moves both by dt / blend.
        if (action != current.action) {
            if (current.action >= 0)
                fading = current;
            current = {action, 0.0, f == 0 ? 1.0f : 0.0f};
            started = f;
        } else if (current.action >= 0) {
            current.weight = std::min(1.0f, current.weight + rate(current.action));
        }
        if (oneShot(current.action))
            current.phase = lastPhase(current.action) *
                            static_cast<double>(sim::oneShotProgress(clip, static_cast<double>(f - started) * dt));
        else if (current.action >= 0)
            current.phase = static_cast<double>(recorded.phases[f]);
        out[f].action = current;
        out[f].fading = fading;
    }
}

}  // namespace

GaitClock startGait(const AgentVariation& v)
{
    GaitClock clock;
    clock.phase = v.phaseOffset;
    return clock;
}

GaitFrame advanceGait(const Character& c, const AgentVariation& v, GaitClock& clock, glm::vec3 position, float speed)
{
    // Thresholds grow with the body (longer legs walk faster) and with the agent's pace.
    const float k = v.heightScale * v.speedFactor;
    GaitFrame g;
    g.moveWeight = c.hasIdle ? smoothstep(c.idleSpeed * k, c.walkSpeed * k, speed) : 1.0f;
    g.runWeight = runWeightAt(c, speed, k);
    if (clock.started) {
        const double distance = glm::length(glm::dvec3(position) - glm::dvec3(clock.position));
        const float w = 0.5f * (g.runWeight + clock.runWeight);
        clock.phase += distance / strideAt(c, w, v.heightScale);
    }
    g.phase = clock.phase;
    clock.runWeight = g.runWeight;
    clock.position = position;
    clock.started = true;
    return g;
}

std::vector<GaitFrame> computeGait(const Character& c, std::span<const glm::vec3> positions,
                                   std::span<const float> speeds, const AgentVariation& v,
                                   const RecordedClips& recorded)
{
    std::vector<GaitFrame> out(positions.size());
    GaitClock clock = startGait(v);
    for (std::size_t f = 0; f < positions.size(); ++f)
        out[f] = advanceGait(c, v, clock, positions[f], speeds[f]);
    layerActions(c, recorded, out);
    return out;
}

bool playsOneShot(const Character& c, const GaitFrame& g)
{
    for (const ActionLayer* layer : {&g.fading, &g.action})
        if (layer->action >= 0 && layer->weight > 0.0f && c.actions[static_cast<std::size_t>(layer->action)].oneShot)
            return true;
    return false;
}

Pose gaitPose(const Character& c, const GaitFrame& g)
{
    Pose moving;
    if (!c.ladder.empty()) {
        const auto [k, t] = rungAt(c, g.runWeight);
        moving = sampleClip(c.ladder[k], g.phase);
        if (t > 0.0f)
            moving = blendPoses(moving, sampleClip(c.ladder[k + 1], g.phase), t);
    } else {
        moving = sampleClip(c.walk, g.phase);
        if (g.runWeight > 0.0f)
            moving = blendPoses(moving, sampleClip(c.run, g.phase), g.runWeight);
    }
    Pose pose =
        g.moveWeight >= 1.0f ? std::move(moving) : blendPoses(sampleClip(c.idle, g.phase), moving, g.moveWeight);
    // Actions over the gait: the upper body in full, the legs and hips only as far as the
    // agent stands (a walker's legs keep walking).
    for (const ActionLayer* layer : {&g.fading, &g.action}) {
        if (layer->action < 0 || layer->weight <= 0.0f)
            continue;
        const ActionClip& a = c.actions[static_cast<std::size_t>(layer->action)];
        if (a.oneShot)  // the whole body, the hips' height included, whether it moves or not
            pose = blendPoses(pose, sampleClip(a.clip, layer->phase), layer->weight);
        else
            pose = blendPosesLayered(pose, sampleClip(a.clip, layer->phase), a.layered, layer->weight,
                                     layer->weight * (1.0f - g.moveWeight));
    }
    // Standing, the feet stay where the idle pose plants them through any blend (a fall
    // or getting up moves them as its clip does).
    if (g.moveWeight < 1.0f && (g.action.weight > 0.0f || g.fading.weight > 0.0f) && !playsOneShot(c, g))
        plantFeet(c, pose, 1.0f - g.moveWeight);
    return pose;
}

}  // namespace throng::exporting
