#pragma once
// Adds one agent's nodes to the model: the root `agent_<id>_<type>` (root motion, height
// scale), its own joints under it, and a scene-root body node with the agent's own mesh
// entry and skin over the character's shared accessors. No animation data.
#ifndef THRONG_EXPORT_BUILD
#error "a detail/ header, private to throng::export: include the module's public headers instead"
#endif

#include "export/character/Character.h"
#include "export/detail/CharacterAssets.h"

#include <tiny_gltf.h>

#include <string>

namespace throng::exporting::detail {

struct AgentRig {
    int root = -1;
    int firstJoint = -1;  // joint j is node firstJoint + j
};

struct AgentRigSpec {
    std::string name;          // agent_<id>_<type>
    std::vector<int> partMaterials;  // per part of partsOf(mesh): its material, or -1 = not worn
    float heightScale = 1.0f;
    glm::vec3 translation{0.0f};
    glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
    tinygltf::Value extras;
};

AgentRig addAgentRig(tinygltf::Model& model, const Character& character, const CharacterAccessors& assets,
                     const AgentRigSpec& spec, const Pose& firstPose);

}  // namespace throng::exporting::detail
