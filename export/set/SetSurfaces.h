#pragma once
// The set's flat parts as the exports lay them on the ground: the ground over the scene's
// bounds (following the terrain where it has heights), the lanes' asphalt with a dashed
// centre line, and the crosswalks' zebra bars. Each lies a little above what it covers,
// so that no two fight in a renderer. Builds SolidMesh triangles from plain scene data.

#include "export/set/SolidMesh.h"
#include "simcore/scene/Scene.h"

namespace throng::exporting {

class SetSurfaces {
public:
    static constexpr float kLaneLiftM = 0.01f;    // above the ground
    static constexpr float kMarkingLiftM = 0.02f; // centre lines and zebra bars

    // The bounds as one quad on flat ground, or as a grid of the terrain's cells.
    static void addGround(const sim::Scene& scene, SolidMesh& mesh);
    // Each lane as a strip of its width along its points, round at its bends, with its
    // centre line dashed 1.5 m on, 1.5 m off.
    static void addLanes(const sim::Scene& scene, SolidMesh& mesh);
    // Each crosswalk's bars, 0.5 m wide and 0.5 m apart, along the walking direction.
    static void addCrosswalks(const sim::Scene& scene, SolidMesh& mesh);
};

}  // namespace throng::exporting
