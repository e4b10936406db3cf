#pragma once
// One nearby agent as a steering behaviour sees it, gathered by the caller from the
// neighbour grid and already filtered by perception radius and view cone. Plain data.

#include <glm/vec3.hpp>

#include <cstdint>

namespace throng::sim {

struct Neighbour {
    glm::vec3 position{0.0f};             // m
    glm::vec3 velocity{0.0f};             // m/s
    glm::vec3 forward{0.0f, 0.0f, 1.0f};  // unit: heading
    float radius = 0.3f;                  // m, >= 0
    std::uint32_t id = 0;                 // stable agent id, for deterministic tie-breaking
};

}  // namespace throng::sim
