#pragma once
// The set in the glTF export: a node `set` with a child per part (the ground, the lanes,
// the crosswalks, the walls, the obstacles and the traffic lights' poles and heads), each a
// mesh with a primitive per colour, as the editor's 3D view stands them up (SetSolids,
// SetSurfaces). Each light's three lamps are nodes of their own, lit by a STEP scale
// channel that follows the light's phase frame by frame.
#ifndef THRONG_EXPORT_BUILD
#error "a detail/ header, private to throng::export: include the module's public headers instead"
#endif

#include "export/detail/AnimationChannels.h"
#include "export/detail/GltfBuilder.h"
#include "simcore/scene/Scene.h"

#include <glm/vec2.hpp>

namespace throng::exporting::detail {

// Adds the set of `scene`, less `origin` (the cache's: the set then sits with the agents
// under scene_origin), to the model's scene 0; the lamps' channels go through `channels`
// on `frames` (the time of every frame, `fps` frames a second: a lamp's phase on frame f
// is the light's at (firstFrame + f) / fps, as in the simulation). Nothing when the scene
// has no set at all. Returns the `set` node, or -1.
int addSetNodes(GltfBuilder& builder, AnimationChannels& channels, const sim::Scene& scene, glm::dvec2 origin,
                const Clock& frames, float fps, std::size_t firstFrame);

}  // namespace throng::exporting::detail
