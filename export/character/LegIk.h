#pragma once
// Two-bone IK for a character's legs: turns the thigh and the shin so the ankle reaches a
// target, the knee bending in the plane it already bends in, and keeps the foot's
// orientation (a sole stays as level as it was). Pure functions of a pose; the base of
// foot planting now and of terrain adaptation later.

#include "export/character/Character.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <span>

namespace throng::exporting {

// Moves `leg`'s ankle in `pose` to `target` (the character's space, m), or as near as the
// leg reaches. Only the leg's three joints change.
void reachWithLeg(const Character& character, const Leg& leg, const glm::vec3& target, Pose& pose);
// The same with the pose's joint transforms (jointGlobalTransforms) already worked out:
// they stay valid for the other legs afterwards. `footTurn` turns the foot in the
// character's space after the reach (a sole tilted to a slope); identity keeps it.
void reachWithLeg(const Character& character, const Leg& leg, std::span<const glm::mat4> globals,
                  const glm::vec3& target, const glm::quat& footTurn, Pose& pose);
// The shortest turn taking direction `from` to direction `to` (both non-zero).
glm::quat turnBetween(const glm::vec3& from, const glm::vec3& to);

// Over a standing agent (`share`: how far it stands, 1 - moveWeight) pulls each ankle the
// pose moved back towards where the idle pose plants it (Leg::plantedAnkle): an action's
// blend, sitting down included, slides no foot.
void plantFeet(const Character& character, Pose& pose, float share);

}  // namespace throng::exporting
