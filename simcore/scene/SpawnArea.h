#pragma once
// A spawn group's area on the ground, whatever its shape (rectangle, circle or polygon):
// its size, its bounding box, containment and the nearest point inside. Pure functions
// over one SpawnGroup; they never change it.

#include "simcore/scene/Scene.h"

#include <glm/vec2.hpp>

namespace throng::sim {

double spawnAreaM2(const SpawnGroup& group);

struct GroundBounds {
    glm::vec2 min{0.0f}, max{0.0f};
};
GroundBounds spawnAreaBounds(const SpawnGroup& group);

bool spawnAreaContains(const SpawnGroup& group, glm::vec2 p);

// p when the area holds it, else the nearest point of the area's edge.
glm::vec2 clampToSpawnArea(const SpawnGroup& group, glm::vec2 p);

}  // namespace throng::sim
