#pragma once
// Reading a user character's glTF data: accessors as floats, its skinned mesh remapped to
// our joint order, and its animations sampled into looping clips. Used by UserCharacter
// only; the tinygltf model stays read-only.

#include "export/character/Character.h"
#include "export/character/UserCharacter.h"

#include <tiny_gltf.h>

#include <map>
#include <string>
#include <vector>

namespace throng::exporting {

// Every component of an accessor as float (normalised integers scaled to [0, 1]/[-1, 1]).
std::vector<float> readFloats(const tinygltf::Model& model, int accessor);
// Merges the triangle primitives of the node's mesh; JOINTS_0 remapped through jointOfNode.
bool readSkinnedMesh(const tinygltf::Model& model, const tinygltf::Node& node, const tinygltf::Skin& skin,
                     const std::map<int, int>& jointOfNode, CharacterMesh& mesh, std::string& error);
// Fills idle, walk and run (see loadCharacterFile for the rules); false with error.
bool sampleUserClips(const tinygltf::Model& model, Character& character, const std::map<int, int>& jointOfNode,
                     const ClipNames& names, std::string& error);

}  // namespace throng::exporting
