#pragma once
// Turns an agent's recorded motion into its character's clip state, frame by frame: the
// phase advances by distance travelled divided by stride (so planted feet stay planted),
// walk blends into run by speed, a stopped agent idles. Pure maths over the inputs.

#include "export/character/AgentVariation.h"
#include "export/character/Character.h"

#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace throng::exporting {

struct GaitFrame {
    double phase = 0.0;      // cycles since the clip's start, including the agent's offset
    float moveWeight = 1.0f; // 0 = idle pose, 1 = walk/run
    float runWeight = 0.0f;  // 0 = walk, 1 = run
};

// positions (m) and speeds (m/s) of one agent, one entry per frame; both the same length.
std::vector<GaitFrame> computeGait(const Character& character, std::span<const glm::vec3> positions,
                                   std::span<const float> speeds, const AgentVariation& variation);
// The character's pose for one gait frame.
Pose gaitPose(const Character& character, const GaitFrame& frame);
// Stride of one cycle at this blend, for a character scaled by heightScale, m.
double strideAt(const Character& character, float runWeight, float heightScale);

}  // namespace throng::exporting
