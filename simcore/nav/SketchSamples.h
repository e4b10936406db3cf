#pragma once
// The constraints of a sketched vector field: direction samples taken along the user's
// flow strokes, and normal samples along walls and obstacle outlines where the field must
// run parallel to the boundary. Plain data; never solves anything.

#include "simcore/nav/NavShapes.h"

#include <glm/vec2.hpp>

#include <span>
#include <vector>

namespace throng::sim {

struct VectorSample {
    glm::vec2 position{0.0f};   // m
    glm::vec2 direction{1.0f, 0.0f};  // unit: the stroke's direction of travel there
};

struct BoundarySample {
    glm::vec2 position{0.0f};  // m, on a wall or an obstacle outline
    glm::vec2 normal{0.0f, 1.0f};  // unit, across the boundary (either side)
};

// Samples every spacingM (> 0) of arc length along each stroke, from its first point;
// the direction is the tangent of the segment the sample lies on. Zero-length strokes
// give nothing.
std::vector<VectorSample> strokeSamples(std::span<const FlowStroke> strokes, float spacingM);

// Samples every spacingM (> 0) along wall segments, box sides and circle outlines.
// Only samples within reachM of some point of `near` are kept (all when near is empty):
// far walls hardly bend the field and would only grow the linear system.
std::vector<BoundarySample> boundarySamples(const NavShapes& shapes, float spacingM,
                                            std::span<const VectorSample> near = {}, float reachM = 0.0f);

}  // namespace throng::sim
