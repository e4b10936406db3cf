#pragma once
// One frame's local crowd density (persons per m², the Gaussian kernel of
// simcore/world/LocalDensity.h) on a grid of square ground cells, drawn as translucent
// quads on a fixed colour scale. Pure: holds the last build only; owns no GL, reads no document.

#include "editor/viewport/ShapeMesh.h"
#include "simcore/world/FrameCache.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstddef>
#include <span>
#include <vector>

namespace throng::editor {

class DensityHeatmap {
public:
    static constexpr float kDefaultCellM = 1.0f;
    static constexpr std::size_t kMaxCells = 40000;

    // A point of the colour scale: colours blend linearly between stops; below the first
    // stop (density 0) nothing shows, at and past the last the last stop's colour holds.
    struct ScaleStop {
        float density = 0.0f;  // persons/m²
        glm::vec4 colour{0.0f};
    };
    // 0 transparent, 1/m² blue, 2 green, 4 yellow, 6 and more red (for the legend too).
    static std::span<const ScaleStop> scale();
    static glm::vec4 colourFor(float densityPerM2);

    // Density at each cell centre from the agents' ground positions (x, z of each; y is
    // ignored). Cells of cellM (m, at least 0.25) tile the bounds from boundsMin, cellM
    // raised until there are at most kMaxCells. The kernel is LocalDensity's (sigma 0.5 m,
    // cut at 3 sigma) while cells are up to 1 m; over bigger cells sigma grows to half a
    // cell, so every agent still counts towards the cells round it. O(agents), one thread.
    void build(std::span<const glm::vec3> positions, glm::vec2 boundsMin, glm::vec2 boundsMax,
               float cellM = kDefaultCellM);
    // The same over a cached frame: agents not present or already out are left out.
    void build(std::span<const sim::AgentFrame> frame, glm::vec2 boundsMin, glm::vec2 boundsMax,
               float cellM = kDefaultCellM);

    // Persons/m² at the centre of the cell that holds p; 0 outside the cells.
    float densityAt(glm::vec2 p) const;
    float maxDensity() const { return m_max; }
    float cellM() const { return m_cellM; }
    float sigmaM() const { return m_sigmaM; }
    int cols() const { return m_cols; }
    int rows() const { return m_rows; }

    // One quad (two triangles) per cell whose colour is not fully transparent.
    void addCells(ShapeMesh& mesh) const;

private:
    void reset(glm::vec2 boundsMin, glm::vec2 boundsMax, float cellM);
    void splat(glm::vec2 p);
    void finish();

    static constexpr float kMinCellM = 0.25f;  // finer cells would only resample the kernel

    glm::vec2 m_origin{0.0f};
    float m_cellM = kDefaultCellM;
    int m_cols = 0, m_rows = 0;
    float m_sigmaM = 0.5f, m_reachM = 1.5f, m_norm = 0.0f;
    std::vector<float> m_density;  // rows * cols, row-major along x, persons/m²
    float m_max = 0.0f;
};

}  // namespace throng::editor
