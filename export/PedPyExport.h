#pragma once
// Writes a run's walkers for PedPy, the analysis library of JuPedSim (pedpy.readthedocs.io),
// and for the field's other tools: the trajectories as PedPy's text format, and the set's
// geometry as WKT beside them. Reads the Scene and the FrameCache only; never simulates and
// never leaves a partial file at either path.

#include "export/ExportResult.h"
#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"

#include <string>

namespace throng::exporting {

// `path` (the trajectories): comment lines, which say the frame rate ("# framerate: 24")
// and the unit ("x/m"), then "id frame x y z" rows separated by spaces, frame-major, the
// agents in the cache's order. id: AgentId; frame: cache frame index (time = frame / fps);
// x, y, z in metres, PedPy's axes: x = Throng's x (east), y = -Throng's z (north: seen from
// above as Throng's top view shows it, not mirrored), z = height. Walkers only (agents of a
// pedestrian type, heroes included): vehicles and fliers are left out. An agent has no row
// on a frame where it is absent or has left through an exit.
//
// `path` with the suffix .wkt (the set): one WKT GEOMETRYCOLLECTION in the same axes, in
// this order: the scene's bounds as a POLYGON (the outline of the walkable area), then the
// walls walkers meet as LINESTRINGs (every wall polyline, then the lanes' kerbs and the
// crosswalks' sides), then every obstacle as a POLYGON (a circle as 32 corners round its
// edge). docs/export.md shows how PedPy's WalkableArea is made from it.
//
// Both are written to temporary files beside their paths, then renamed over them.
ExportResult writePedPyTrajectories(const sim::Scene& scene, const sim::FrameCache& cache, const std::string& path,
                                    const ProgressFn& progress = {});

// The .wkt path that goes with trajectories at `path`: its suffix replaced by .wkt.
std::string pedPyGeometryPath(const std::string& path);

}  // namespace throng::exporting
