#pragma once
// Applies a scene's layout layer (LayoutLayer.h) to a recording: the agents each enabled
// operation selects, on the frames it names, moved, turned, retimed, mirrored, removed or
// spread, operation after operation. Agents no operation selects keep their frames byte
// for byte. Reads Scene and FrameCache; never simulates.

#include "simcore/layout/LayoutLayer.h"
#include "simcore/scene/Scene.h"
#include "simcore/world/FrameCache.h"

#include <string>
#include <vector>

namespace throng::sim {

// The cache agents (indices) each operation of `layer` selects in `recorded`, and what
// the user should hear about: an operation that selects nobody (its agents no longer
// exist after a re-simulation, say), ids the recording lacks, names no group or type has.
struct LayoutSelection {
    std::vector<std::vector<std::size_t>> agents;  // per operation, sorted
    std::vector<std::string> messages;
};
LayoutSelection selectLayoutAgents(const Scene& scene, const LayoutLayer& layer, const FrameCache& recorded);

// `recorded` with `scene.layout` applied; `messages` (when given) gets selectLayoutAgents'.
FrameCache applyLayout(const Scene& scene, const FrameCache& recorded, std::vector<std::string>* messages = nullptr);

}  // namespace throng::sim
