#pragma once
// Loads a user's rigged glTF/GLB character (skinned mesh, skeleton, animation clips) into
// a Character, mapping its clips to idle, walk and run by name. Reads one file; never
// writes, and refuses a file without a skin or without clips with a message saying so.

#include "export/character/Character.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace throng::exporting {

// Clip names in the file; an empty name is found by matching: the shortest clip name
// containing "idle" or "stand", "walk", "run" (case-insensitive).
struct ClipNames {
    std::string idle, walk, run;
    // Action (sim::Clip's names: wave, talk, ...) -> the clip that plays it, by exact name.
    std::vector<std::pair<std::string, std::string>> actions;
};

// The file's character faces +Z (glTF's convention) and is turned to face +X like the
// built-ins. Without an idle clip it idles in its rest pose; without run it runs its walk.
// A clip mapped to an action is stretched over the action's cycle (sim::clipCycleS) and
// played over walking on the joints that are not the root, the hips or a leg (by name:
// hip, pelvis, leg, thigh, knee, shin, calf, ankle, foot, toe, and their children).
// Stride: the horizontal root travel of a root-motion clip, else 0.8 x the character's
// height for walk and 1.6 x for run. nullopt with `error` naming the file when it fails.
std::optional<Character> loadCharacterFile(const std::string& path, const ClipNames& clips, std::string& error);

}  // namespace throng::exporting
