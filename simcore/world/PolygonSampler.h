#pragma once
// Uniform points inside a simple polygon (concave ones too), from three uniform numbers:
// one picks a triangle of its triangulation by area, two place the point in it. Built
// once per spawn group; holds no random state, so the same numbers give the same point.

#include "simcore/scene/GroundPolygon.h"

#include <glm/vec2.hpp>

#include <span>
#include <vector>

namespace throng::sim {

class PolygonSampler {
public:
    explicit PolygonSampler(std::span<const glm::vec2> corners);

    bool empty() const { return m_triangles.empty(); }
    // pick, u, v in [0, 1); a point of the polygon (or of its outline, at the edges).
    glm::vec2 at(float pick, float u, float v) const;

private:
    std::vector<GroundTriangle> m_triangles;
    std::vector<double> m_cumulativeArea;  // m², running sum over m_triangles
};

}  // namespace throng::sim
