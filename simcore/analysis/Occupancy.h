#pragma once
// Who is in the shot over time: the agents in the scene and those out through exits on
// every recorded frame, the exit each one left by (the exit goal or exit path end it
// stood in when it left), and the time to evacuate. Reads a scene and a FrameCache;
// never simulates.

#include "simcore/scene/Scene.h"
#include "simcore/analysis/AnalysisStop.h"
#include "simcore/world/FrameCache.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace throng::sim {

struct ExitOutflow {
    std::string exit;                 // an exit goal's name, or an exit path's
    std::vector<std::size_t> frames;  // the frame each agent left on, in order
    std::uint64_t agentsOut() const { return frames.size(); }
};

struct Occupancy {
    std::vector<std::uint32_t> inScene;  // per frame: agents present and not out
    std::vector<std::uint32_t> out;      // per frame: agents out through an exit on or before it
    std::vector<ExitOutflow> exits;      // every exit of the scene, scene order (goals, then paths)
    std::uint64_t peakInScene = 0;
    // Seconds from the start to the first frame from which nobody is in the scene, once at
    // least one agent has left; < 0 when the recording ends with agents still in it.
    double evacuationS = -1.0;
};

// Told to stop, it returns the frames it has counted.
Occupancy measureOccupancy(const Scene& scene, const FrameCache& cache, StopFlag stop = nullptr);

}  // namespace throng::sim
