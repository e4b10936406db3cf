#pragma once
// The speed-density relation measured in a scene's measurement areas: on each sampled
// frame, the walkers inside an area per m² and their mean speed (the classical method of
// the pedestrian-dynamics literature), with Weidmann's fundamental diagram to compare.
// Reads a scene and a FrameCache; never simulates.

#include "simcore/scene/Scene.h"
#include "simcore/analysis/AnalysisStop.h"
#include "simcore/world/FrameCache.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace throng::sim {

struct SpeedDensitySample {
    std::size_t frame = 0;
    double densityPerM2 = 0.0;
    double speedMps = 0.0;     // mean of the walkers' recorded speeds
    std::uint32_t walkers = 0; // >= 1: frames with nobody inside give no sample
};

struct AreaSpeedDensity {
    std::string name;
    double areaM2 = 0.0;
    std::vector<SpeedDensitySample> samples;
};

// One series per measurement area (scene order), sampling every `everyFrames` frame (>= 1).
// Told to stop, the series end where it stopped.
std::vector<AreaSpeedDensity> measureSpeedDensity(const Scene& scene, const FrameCache& cache,
                                                  std::size_t everyFrames = 1, StopFlag stop = nullptr);

// Weidmann (1993): v(rho) = 1.34 (1 - exp(-1.913 (1 / rho - 1 / 5.4))) m/s for rho persons
// per m² in (0, 5.4]; 1.34 at 0 and 0 from 5.4 on.
double weidmannSpeed(double densityPerM2);

}  // namespace throng::sim
