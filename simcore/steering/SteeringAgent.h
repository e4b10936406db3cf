#pragma once
// What a steering behaviour reads about the agent it steers: its kinematic state, local
// frame and limits. Plain data filled by the caller; it never points into the World.

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cstdint>

namespace throng::sim {

struct SteeringAgent {
    glm::vec3 position{0.0f};               // m, world frame, y up
    glm::vec3 velocity{0.0f};               // m/s; ground agents keep y = 0
    glm::vec3 forward{0.0f, 0.0f, 1.0f};    // unit: heading
    glm::vec3 side{-1.0f, 0.0f, 0.0f};      // unit: the agent's right, cross(forward, up)
    glm::vec3 up{0.0f, 1.0f, 0.0f};         // unit: +y for ground agents, banks for fliers
    float radius = 0.3f;                    // m, >= 0: body radius
    float maxSpeed = 1.4f;                  // m/s, >= 0
    float maxForce = 3.0f;                  // N, >= 0
    float mass = 1.0f;                      // kg, > 0 (smaller values are clamped to 1 g)
    std::uint32_t id = 0;                   // stable agent id: breaks ties between agents

    float speed() const { return glm::length(velocity); }
};

}  // namespace throng::sim
