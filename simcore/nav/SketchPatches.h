#pragma once
// The solver behind SketchField: the RBF interpolant of stroke directions and boundary
// normals (Jin et al. 2008), solved as a partition of unity of local RBF fits
// (Wendland, "Scattered Data Approximation", ch. 15) so that the cost grows with the
// samples, not with their square: a quadtree splits the area until each patch sees at
// most a few hundred samples; each patch is one small dense Cholesky solve; evaluation
// blends the patches round a point with Wendland weights. A problem small enough for one
// patch is the plain global interpolant. Never touches a grid or a scene.

#include "simcore/nav/SketchSamples.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace throng::sim {

class SketchPatches {
public:
    // kernelLengthM > 0: the inverse multiquadric's scale; ridge >= 0: Tikhonov term.
    // [domainMin, domainMax] is where evaluate() will be asked (it may also be asked
    // outside). False (see error()) when a patch's system cannot be factorised. Patches
    // are solved on `threads` threads (0 = one per core); the result is the same for any.
    bool solve(std::span<const VectorSample> strokes, std::span<const BoundarySample> boundary, double kernelLengthM,
               double ridge, glm::vec2 domainMin, glm::vec2 domainMax, int threads = 0);
    // O(samples of the few patches round p).
    glm::vec2 evaluate(glm::vec2 p) const;
    std::size_t patchCount() const { return m_patches.size(); }
    const std::string& error() const { return m_error; }

private:
    struct Patch {
        glm::dvec2 centre{0.0};
        double radius = 0.0;                  // m: the weight's support; 0 = everywhere (one patch)
        std::vector<std::uint32_t> strokes;   // indices into m_strokes
        std::vector<std::uint32_t> boundary;  // indices into m_boundary
        std::vector<glm::dvec2> strokeWeights;
        std::vector<double> boundaryWeights;
    };

    void split(glm::dvec2 lo, double size, std::vector<std::uint32_t>&& members, int depth);
    void addPatch(glm::dvec2 centre, double radius, const std::vector<std::uint32_t>& members);
    bool solvePatch(Patch& patch, double ridge, std::string& error) const;
    glm::dvec2 evaluatePatch(const Patch& patch, glm::vec2 p) const;
    double kernel(glm::vec2 a, glm::vec2 b) const;
    void index();

    std::vector<VectorSample> m_strokes;
    std::vector<BoundarySample> m_boundary;
    std::vector<Patch> m_patches;
    double m_invLength2 = 1.0;
    std::string m_error;

    // Patches by a uniform grid of buckets over the domain: each bucket lists (ascending)
    // the patches whose support overlaps it; points outside use the nearest bucket.
    glm::dvec2 m_bucketMin{0.0};
    double m_bucketInv = 1.0;
    int m_bucketCols = 0, m_bucketRows = 0;
    std::vector<std::uint32_t> m_bucketStart, m_bucketItems;
};

}  // namespace throng::sim
