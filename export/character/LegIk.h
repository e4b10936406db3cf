#pragma once
// Two-bone IK for a character's legs: turns the thigh and the shin so the ankle reaches a
// target, the knee bending in the plane it already bends in, and keeps the foot's
// orientation (a sole stays as level as it was). Pure functions of a pose; the base of
// foot planting now and of terrain adaptation later.

#include "export/character/Character.h"

#include <glm/vec3.hpp>

namespace throng::exporting {

// Moves `leg`'s ankle in `pose` to `target` (the character's space, m), or as near as the
// leg reaches. Only the leg's three joints change.
void reachWithLeg(const Character& character, const Leg& leg, const glm::vec3& target, Pose& pose);

// Over a standing agent (`share`: how far it stands, 1 - moveWeight) pulls each ankle the
// pose moved back towards where the idle pose plants it (Leg::plantedAnkle): an action's
// blend, sitting down included, slides no foot.
void plantFeet(const Character& character, Pose& pose, float share);

}  // namespace throng::exporting
