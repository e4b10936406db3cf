#pragma once
// The path of a foot (or hoof) over one gait cycle and the two-bone angles that reach a
// point of it: shared by the humanoid's and the horse's clips. On the ground the foot moves
// back under the body at one stride per cycle, so a gait whose phase advances by
// distance / stride keeps it where it touched down; in the air it swings forward, lifted.

#include <glm/vec2.hpp>

#include <utility>

namespace throng::exporting {

struct FootPath {
    float strideM = 1.0f;  // the distance the body covers in one cycle, m
    float duty = 0.5f;     // the share of the cycle the foot is on the ground
    float liftM = 0.1f;    // how high it swings, m
    // The share of the stance's speed (back under the body) the swing leaves and meets
    // the ground with: 1 lands a foot without moving over the ground, at the cost of
    // reaching past where it lands first; 0 eases it to a stop relative to the body.
    float landingSpeedShare = 0.0f;
};

// The foot's target at leg phase s in [0, 1) (s = 0: it touches down): x forward of the
// joint the leg hangs from, y above the ground (`groundM`: the foot joint's height
// standing).
glm::vec2 footTarget(const FootPath& path, float s, float groundM);

// Two-bone IK in the leg's plane: the upper and lower joint angles about +Z (positive
// swings the foot forward) that put the foot at `toFoot` (x forward, y up, from the upper
// joint). The lower joint bends backward (a knee) or, with `bendForward`, forward (a
// horse's hind leg at the hock).
std::pair<float, float> legAngles(glm::vec2 toFoot, float upperM, float lowerM, bool bendForward = false);

}  // namespace throng::exporting
