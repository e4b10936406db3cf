#pragma once
// The set in the USD export: `def Xform "Set"` with an Xform per part (Ground, Lanes,
// Crosswalks, Walls, Obstacles, Lights) as the editor's 3D view stands them up (SetSolids,
// SetSurfaces), a Mesh per colour in each; and per light and lamp a lit lamp whose
// visibility follows the light's phase frame by frame.
#ifndef THRONG_EXPORT_BUILD
#error "a detail/ header, private to throng::export: include the module's public headers instead"
#endif

#include "export/detail/UsdMaterials.h"
#include "simcore/scene/Scene.h"

#include <glm/vec2.hpp>

#include <string>

namespace throng::exporting::detail {

// Writes the set of `scene` less `origin` (the cache's, which the crowd's prim carries) at
// `depth`, under `path` (the Set prim's own path). Lamps: frame f's phase is the light's
// at (firstFrame + f) / fps; time code f is frame f. Returns false (and writes nothing)
// when the scene has no set at all.
bool writeUsdSet(std::string& out, int depth, const std::string& path, const sim::Scene& scene, glm::dvec2 origin,
                 std::size_t frames, float fps, std::size_t firstFrame, UsdMaterials& materials);

}  // namespace throng::exporting::detail
