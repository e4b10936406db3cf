#pragma once
// Brains in the World, as the scene check sees them: compiles every brain of a scene
// (with the scene's brains as the macro library) and reports, as file:line:col
// diagnostics, compiler errors and sensors the World cannot fill (an attribute agents do
// not have). Never runs one.

#include "simcore/brain/BrainProgram.h"
#include "simcore/base/Diagnostic.h"
#include "simcore/scene/Scene.h"

#include <string>
#include <vector>

namespace throng::sim {

// Every compiler error of every brain in `scene`, then every sensor a compiled brain
// reads that the World does not fill (naming the input node). Empty = all brains run.
std::vector<Diagnostic> checkSceneBrains(const Scene& scene);

// Why the World cannot fill `use` for this scene; empty when it can.
std::string worldSensorProblem(const BrainSensorUse& use, const Scene& scene);

}  // namespace throng::sim
