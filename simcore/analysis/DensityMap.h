#pragma once
// A density heatmap of the walkers over the scene's bounds: on a grid of square cells,
// the mean number of walkers in each cell over a span of recorded frames. Reads a scene
// and a FrameCache; never simulates.

#include "simcore/scene/Scene.h"
#include "simcore/analysis/AnalysisStop.h"
#include "simcore/world/FrameCache.h"

#include <glm/vec2.hpp>

#include <cstddef>
#include <vector>

namespace throng::sim {

struct DensityMap {
    glm::dvec2 min{0.0};         // (x, z) corner of cell (0, 0)
    double cellM = 1.0;          // > 0
    std::size_t cols = 0, rows = 0;
    std::vector<double> persons;  // rows * cols, row-major along x: mean walkers in the cell
    std::size_t frames = 0;       // frames averaged
    double outsidePersons = 0.0;  // mean walkers in the shot but outside the bounds (not in a cell)

    double personsAt(std::size_t col, std::size_t row) const { return persons[row * cols + col]; }
    // Persons per m².
    double densityAt(std::size_t col, std::size_t row) const { return personsAt(col, row) / (cellM * cellM); }
    // The mean number of walkers in the cells: the walkers inside the bounds.
    double totalPersons() const;
    double peakDensity() const;
};

// Over frames [firstFrame, lastFrame) (clamped to the recording); cells of cellM metres
// (> 0) over the scene's bounds, at most maxCells of them (coarser cells otherwise). Told
// to stop, it returns the frames it has counted.
DensityMap densityMap(const Scene& scene, const FrameCache& cache, double cellM, std::size_t firstFrame,
                      std::size_t lastFrame, std::size_t maxCells = 250'000, StopFlag stop = nullptr);

}  // namespace throng::sim
