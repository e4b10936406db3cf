#pragma once
// The set in the FBX export: a node `set` with a node per part (set_ground, set_lanes,
// set_crosswalks, set_walls, set_obstacles, set_lights), a mesh per colour in each, as the
// editor's 3D view stands them up (SetSolids, SetSurfaces); and per light and lamp a lit
// lamp whose scale is keyed 1 on the frames the light's phase shows it and 10^-4 on the others.
#ifndef THRONG_EXPORT_BUILD
#error "a detail/ header, private to throng::export: include the module's public headers instead"
#endif

#include "export/detail/AssimpScene.h"
#include "simcore/scene/Scene.h"

#include <glm/vec2.hpp>

namespace throng::exporting::detail {

// Adds the set of `scene` less `origin` under `parent`; frame f is at f / fps seconds and
// shows the lights' phases at (firstFrame + f) / fps. Nothing when the scene has no set.
void addAssimpSet(AssimpScene& out, aiNode* parent, const sim::Scene& scene, glm::dvec2 origin, std::size_t frames,
                  float fps, std::size_t firstFrame);

// The scale of what is out of the shot: FBX readers rebuild a node's matrix from its keys,
// and neither assimp nor Blender keeps a scale of 0 (a matrix without an inverse).
inline constexpr float kHiddenScale = 1e-4f;

// Keys for a value that switches at frames (STEP): the old value just before each switch,
// the new one on its frame. `on[f]` per frame; values `off` and `onValue`.
std::vector<std::pair<double, glm::vec3>> stepKeys(const std::vector<std::uint8_t>& on, float fps, glm::vec3 off,
                                                   glm::vec3 onValue);

}  // namespace throng::exporting::detail
