#pragma once
// Everything a run's report and the editor's Analysis dock plot, computed once from the
// recorded frames: trajectories, the density heatmap, speed against density in the
// measurement areas, flow over the measurement lines and out of the exits, the agents in
// the scene over time and the time to evacuate. Reads a scene and a FrameCache; never
// simulates and never draws.

#include "simcore/analysis/DensityMap.h"
#include "simcore/analysis/LineCrossings.h"
#include "simcore/analysis/Occupancy.h"
#include "simcore/analysis/SpeedDensity.h"

#include <glm/vec2.hpp>

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace throng::sim {

struct AnalysisOptions {
    double densityCellM = 1.0;      // heatmap cells, m
    double flowBinS = 0.0;          // flow bins, s; <= 0: 1, 2, 5 or 10 s, about 80 bins over the run
    std::size_t maxTrajectories = 2'000;   // walkers drawn (evenly picked by cache index)
    std::size_t maxTrajectoryPoints = 400; // points per trajectory (evenly picked frames)
};

// How an analysis run off the caller's thread reports and stops: `progress` hears, between
// its stages, the share done (0 to 1) and what comes next; `stop` (AnalysisStop.h) is read
// once a frame, and an analysis told to stop returns early with `complete` false.
struct AnalysisControl {
    std::function<void(double done, const std::string& next)> progress;
    StopFlag stop = nullptr;
};

struct Trajectory {
    std::uint32_t agent = 0;          // cache agent index
    std::vector<glm::dvec2> points;   // (x, z) while in the shot; a gap starts a new trajectory
};

struct RunAnalysis {
    float fps = 24.0f;
    std::size_t frames = 0;
    double durationS = 0.0;
    glm::dvec2 boundsMin{0.0}, boundsMax{0.0};
    std::size_t walkers = 0;  // cache agents that were walkers in the shot on some frame
    std::vector<Trajectory> trajectories;
    DensityMap density;       // over the whole recording
    std::vector<AreaSpeedDensity> speedDensity;
    std::vector<LineFlow> lines;
    std::vector<std::vector<double>> lineFlowPerSecond;  // per line, bins of flowBinS
    double flowBinS = 1.0;
    Occupancy occupancy;
    bool complete = true;  // false: stopped early (AnalysisControl), the figures partial
};

RunAnalysis analyseRun(const Scene& scene, const FrameCache& cache, const AnalysisOptions& options = {},
                       const AnalysisControl& control = {});

}  // namespace throng::sim
