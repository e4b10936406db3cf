#pragma once
// Writes a run's recorded frames as one animated glTF 2.0 scene: one shared stand-in body
// mesh per agent type, one node per agent, one "crowd" animation sharing one time
// accessor. Reads Scene and FrameCache only; never simulates, never leaves partial files.

#include "export/ExportResult.h"
#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"

#include <string>

namespace throng::exporting {

struct GltfOptions {
    std::string path;                         // ends in .glb: one binary file; else .gltf + .bin beside it
    float bodyHeightPerRadius = 1.7f / 0.3f;  // stand-in body height = type radius x this, > 0
    float maxBodyHeightM = 2.5f;              // caps it, so vehicle-sized radii stay plausible; m, > 0
    bool prettyJson = true;                   // .gltf only: indented JSON
};

// Node `agent_<id>_<type>` per agent (AgentId, type name), in the cache's dense order, its
// translation (m) and rotation (about +Y by AgentFrame::headingRad, body nose on +X)
// keyed at time frame / fps for every recorded frame, starting at frame 0's pose.
// Scene and asset extras carry generator "Throng", fps, frameCount and agentCount.
// writtenPaths: {path} for .glb, {path, <stem>.bin} for .gltf (the .bin name keeps only
// [A-Za-z0-9._~-], others become '_', so its URI needs no escaping).
// Errors (naming the file): empty cache, an agent type index the scene lacks, a .glb over
// 4 GiB, any I/O failure. Files go to temporaries beside the target and are renamed in.
ExportResult exportGltf(const sim::Scene& scene, const sim::FrameCache& cache, const GltfOptions& options,
                        const ProgressFn& progress = {});

}  // namespace throng::exporting
