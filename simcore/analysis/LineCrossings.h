#pragma once
// Counts the walkers crossing each measurement line of a scene, frame by frame, from the
// recorded positions, and turns the crossings into a flow over time. Reads a scene and a
// FrameCache; never simulates.

#include "simcore/scene/Scene.h"
#include "simcore/analysis/AnalysisStop.h"
#include "simcore/world/FrameCache.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace throng::sim {

struct LineCrossing {
    std::size_t frame = 0;   // the frame the walker is past the line on
    std::uint32_t agent = 0; // cache agent index
    bool forward = true;     // along the line's normal (Scene.h, Measurement)
};

struct LineFlow {
    std::string name;
    float lengthM = 0.0f;
    std::uint64_t forward = 0, backward = 0;
    std::vector<LineCrossing> crossings;  // in frame order, then agent order
};

// Every crossing of every measurement line (scene order of lines): a walker crosses on
// frame f when it stood on one side on frame f - 1 and on the other on frame f, with the
// step between them passing through the line. Walkers only; a walker counts while it is
// in the shot on f - 1 (so the step on which it leaves through an exit counts too).
// Told to stop, it returns the crossings up to where it stopped.
std::vector<LineFlow> countLineCrossings(const Scene& scene, const FrameCache& cache, StopFlag stop = nullptr);

// Persons per second over bins of binS seconds from 0 s: bin k holds the crossings on
// frames in [k binS, (k + 1) binS) of the recording, divided by binS. Both directions.
std::vector<double> flowPerSecond(const LineFlow& line, float fps, std::size_t frameCount, double binS);

}  // namespace throng::sim
