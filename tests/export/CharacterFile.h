#pragma once
// Writes a small rigged glTF character the way a DCC tool would (facing +Z, under an
// "Armature" node, clips as animations), built from one of Throng's own characters, plus
// deliberately broken variants. Test-only; a stand-in for a user's own file.

#include "export/character/Character.h"

#include <string>
#include <vector>

namespace throng::test {

struct CharacterFileSpec {
    bool skin = true;                                             // false: a plain mesh
    // animations, cut from the character's clips; one named after an action (Wave) from it
    std::vector<std::string> clips{"Idle", "Walk", "Run"};
};

// False with `error` when tinygltf cannot write the file.
bool writeCharacterFile(const exporting::Character& character, const CharacterFileSpec& spec, const std::string& path,
                        std::string& error);

}  // namespace throng::test
