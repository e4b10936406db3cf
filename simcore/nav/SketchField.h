#pragma once
// A sketched vector field (Jin et al., "Interactive Control of Large-Crowd Navigation in
// Virtual Environments Using Vector Fields", IEEE CG&A 2008): the user's stroke directions
// interpolated with radial basis functions over the walkable area, walls acting as boundary
// constraints (the field's normal component is zero at boundary samples), then baked onto a
// NavGrid for O(1) lookup where no cell's direction leads into a blocked cell.
// Solves through SketchPatches (local dense Cholesky solves, blended); never steers agents itself.

#include "simcore/nav/NavGrid.h"
#include "simcore/nav/SketchPatches.h"
#include "simcore/nav/SketchSamples.h"

#include <glm/vec2.hpp>

#include <cmath>
#include <span>
#include <string>
#include <vector>

namespace throng::sim {

struct SketchParams {
    float sampleSpacingM = 1.0f;    // m, > 0: direction samples along strokes
    float boundarySpacingM = 1.0f;  // m, > 0: normal samples along walls and obstacles
    float kernelLengthM = 2.0f;     // m, > 0: the inverse multiquadric's scale, 1 / sqrt(1 + (r / l)^2)
    float wallReachM = 12.0f;       // m, >= 0: boundary samples farther from every stroke sample are left out
    float ridge = 1e-3f;            // >= 0: Tikhonov term relative to the kernel's peak (1): keeps dense
                                    // samples well conditioned; 1e-6 lets a 0.25 m spacing ring by 60 degrees
    int threads = 0;                // solve and bake on this many threads; 0 = one per core
};

class SketchField {
public:
    // Solves for the RBF weights. False (see error()) when there is no stroke sample or the
    // system cannot be factorised.
    // [domainMin, domainMax]: where the field will be evaluated (the grid's extent), when known.
    bool solve(std::span<const VectorSample> strokes, std::span<const BoundarySample> boundary,
               const SketchParams& params, glm::vec2 domainMin = glm::vec2(INFINITY),
               glm::vec2 domainMax = glm::vec2(-INFINITY));
    // strokeSamples + boundarySamples of the scene's strokes, walls and obstacles, then solve and bake.
    bool build(const Scene& scene, const NavGrid& grid, const SketchParams& params = {});

    // The interpolated field at p (not unit; its length says how strongly strokes act there).
    // O(samples of the patches round p).
    glm::vec2 evaluate(glm::vec2 p) const;

    // Samples evaluate() at every walkable cell centre (rows on all cores; each cell is
    // independent, so the result does not depend on the thread count), then turns any cell
    // direction that leads into a blocked cell along the boundary.
    void bake(const NavGrid& grid, int threads = 0);
    const NavGrid& grid() const { return m_grid; }
    // Unit direction at a cell after bake; zero for blocked cells or where the field vanishes.
    glm::vec2 direction(NavCell c) const;
    // Field length at a cell centre after bake (0 where blocked).
    float strength(NavCell c) const;
    // O(1): bilinear blend of cell directions around p, normalised, falling back to the own
    // cell's direction (or zero) where the blend would lead into a blocked cell.
    glm::vec2 sample(glm::vec2 p) const;

    std::size_t strokeSampleCount() const { return m_strokeCount; }
    std::size_t boundarySampleCount() const { return m_boundaryCount; }
    std::size_t patchCount() const { return m_solution.patchCount(); }
    const std::string& error() const { return m_error; }

private:
    std::size_t m_strokeCount = 0, m_boundaryCount = 0;
    SketchPatches m_solution;
    std::string m_error;

    NavGrid m_grid;
    std::vector<glm::vec2> m_dir;
    std::vector<float> m_strength;
};

}  // namespace throng::sim
