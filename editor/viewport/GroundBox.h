#pragma once
// An axis-aligned box on the ground (x, z) in metres, grown point by point; the extent
// the cameras frame. Holds no scene data itself.

#include "simcore/scene/Scene.h"

#include <glm/vec2.hpp>

namespace throng::editor {

struct GroundBox {
    glm::vec2 min{0.0f};
    glm::vec2 max{0.0f};
    bool empty = true;

    // Grows the box to hold a disc of `radiusM` (>= 0) around `point`.
    void include(glm::vec2 point, float radiusM = 0.0f);
    void include(const GroundBox& other);
    glm::vec2 centre() const { return 0.5f * (min + max); }
    glm::vec2 size() const { return max - min; }
};

// Everything drawn of the set: walls, paths with their radius, obstacles, goals, lanes,
// crosswalks, lights, spawn areas and placed agents. Empty for an empty scene.
GroundBox setExtent(const sim::Scene& scene);

}  // namespace throng::editor
