#include "export/character/Gait.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace throng::exporting {

namespace {

float smoothstep(float lo, float hi, float x)
{
    if (!(hi > lo))
        return x >= hi ? 1.0f : 0.0f;
    const float t = std::clamp((x - lo) / (hi - lo), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

}  // namespace

double strideAt(const Character& c, float runWeight, float heightScale)
{
    const double walk = c.walk.strideM, run = c.run.strideM;
    return (walk + (run - walk) * static_cast<double>(runWeight)) * static_cast<double>(heightScale);
}

std::vector<GaitFrame> computeGait(const Character& c, std::span<const glm::vec3> positions,
                                   std::span<const float> speeds, const AgentVariation& v)
{
    // Thresholds grow with the body (longer legs walk faster) and with the agent's pace.
    const float k = v.heightScale * v.speedFactor;
    std::vector<GaitFrame> out(positions.size());
    double phase = v.phaseOffset;
    for (std::size_t f = 0; f < positions.size(); ++f) {
        GaitFrame& g = out[f];
        const float speed = speeds[f];
        g.moveWeight = c.hasIdle ? smoothstep(c.idleSpeed * k, c.walkSpeed * k, speed) : 1.0f;
        g.runWeight = smoothstep(c.runStartSpeed * k, c.runSpeed * k, speed);
        if (f > 0) {
            const double distance = glm::length(glm::dvec3(positions[f]) - glm::dvec3(positions[f - 1]));
            const float w = 0.5f * (g.runWeight + out[f - 1].runWeight);
            phase += distance / strideAt(c, w, v.heightScale);
        }
        g.phase = phase;
    }
    return out;
}

Pose gaitPose(const Character& c, const GaitFrame& g)
{
    Pose moving = sampleClip(c.walk, g.phase);
    if (g.runWeight > 0.0f)
        moving = blendPoses(moving, sampleClip(c.run, g.phase), g.runWeight);
    if (g.moveWeight >= 1.0f)
        return moving;
    return blendPoses(sampleClip(c.idle, g.phase), moving, g.moveWeight);
}

}  // namespace throng::exporting
