#pragma once
// What `throng-cli check` warns about the set's geometry before a run trips on it: far
// coordinates the scene file cannot hold finely, agents that start inside walls or
// obstacles, goals some agents cannot reach, exits no body of a type's size can enter.
// Builds the World once to see where spawned agents stand; never runs a step.

#include "simcore/base/Diagnostic.h"
#include "simcore/scene/Scene.h"

#include <string>
#include <vector>

namespace throng::sim {

// Warnings only (the scene is valid), each naming the scene `file`, the key (settings,
// agents[k], groups[k], goals[k]) and what the run will do about it.
std::vector<Diagnostic> checkSceneGeometry(const Scene& scene, const std::string& file);

}  // namespace throng::sim
