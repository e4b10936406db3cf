#pragma once
// Loads a user's rigged glTF/GLB character (skinned mesh, skeleton, animation clips) into
// a Character, mapping its clips to idle, walk and run by name. Reads one file; never
// writes, and refuses a file without a skin or without clips with a message saying so.

#include "export/character/Character.h"

#include <optional>
#include <string>

namespace throng::exporting {

// Clip names in the file; an empty name is found by matching: the shortest clip name
// containing "idle" or "stand", "walk", "run" (case-insensitive).
struct ClipNames {
    std::string idle, walk, run;
};

// The file's character faces +Z (glTF's convention) and is turned to face +X like the
// built-ins. Without an idle clip it idles in its rest pose; without run it runs its walk.
// Stride: the horizontal root travel of a root-motion clip, else 0.8 x the character's
// height for walk and 1.6 x for run. nullopt with `error` naming the file when it fails.
std::optional<Character> loadCharacterFile(const std::string& path, const ClipNames& clips, std::string& error);

}  // namespace throng::exporting
