#pragma once
// Turns an agent's recorded motion into its character's clip state, frame by frame: the
// phase advances by distance travelled divided by stride (so planted feet stay planted),
// walk blends into run by speed (or up a character's gait ladder: walk, trot, canter,
// gallop), a stopped agent idles. An action its brain picked plays
// over that (in full while it stands, on the upper body while it walks), blended in and
// out over the action's blend time; a one-shot (fall, get_up) plays once from the frame it
// starts, in full, and holds its last pose. Pure maths over the inputs.

#include "export/character/AgentVariation.h"
#include "export/character/Character.h"
#include "simcore/scene/Clip.h"

#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace throng::exporting {

// One action as a frame plays it.
struct ActionLayer {
    int action = -1;      // index into Character::actions, -1 = none
    double phase = 0.0;   // cycles
    float weight = 0.0f;  // 0 = not at all, 1 = in full
};

struct GaitFrame {
    double phase = 0.0;      // cycles since the clip's start, including the agent's offset
    float moveWeight = 1.0f; // 0 = idle pose, 1 = walk/run
    float runWeight = 0.0f;  // 0 = walk, 1 = run; with a gait ladder, the place along it (0 first, 1 last)
    ActionLayer fading;      // the action before, blending out
    ActionLayer action;      // the recorded action, blending in
};

// The recorded clips (sim::AgentFrame::clip) and each frame's action phase
// (sim::actionPhase: the frame's time and the agent's id), one per frame, and the frame
// rate; empty spans: no actions.
struct RecordedClips {
    std::span<const sim::Clip> clips;
    std::span<const float> phases;
    float fps = 24.0f;
    float blendS = -1.0f;  // the type's action_blend: every action blends over it; < 0 = each its own
};

// The locomotion of computeGait one frame at a time, for a reader that steps through the
// frames itself (the viewport, from checkpoints): the phase so far and the frame before's
// place on the walk-run blend or gait ladder and position.
struct GaitClock {
    double phase = 0.0;        // cycles, from the variation's phase offset
    float runWeight = 0.0f;    // the frame before's
    glm::vec3 position{0.0f};  // the frame before's, m
    bool started = false;      // false before the first frame
};
GaitClock startGait(const AgentVariation& variation);
// The gait (no actions) of the frame at `position` (m) and `speed` (m/s) after the clock's,
// which moves to it: the phase advances by the distance from the frame before over the
// stride the two frames' blends average to. computeGait calls it for every frame.
GaitFrame advanceGait(const Character& character, const AgentVariation& variation, GaitClock& clock,
                      glm::vec3 position, float speed);

// positions (m) and speeds (m/s) of one agent, one entry per frame; all the same length.
std::vector<GaitFrame> computeGait(const Character& character, std::span<const glm::vec3> positions,
                                   std::span<const float> speeds, const AgentVariation& variation,
                                   const RecordedClips& recorded = {});
// The character's pose for one gait frame.
Pose gaitPose(const Character& character, const GaitFrame& frame);
// Whether the frame plays a one-shot action (fall, get_up) at any weight.
bool playsOneShot(const Character& character, const GaitFrame& frame);
// Stride of one cycle at this blend, for a character scaled by heightScale, m.
double strideAt(const Character& character, float runWeight, float heightScale);

}  // namespace throng::exporting
