// Test-only helpers for the steering suites.
#include "SteeringHarness.h"

#include "simcore/base/Rng.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>

namespace throng::test {

sim::SteeringAgent walker(glm::vec3 position, glm::vec3 velocity, std::uint32_t id)
{
    sim::SteeringAgent a;
    a.position = position;
    a.velocity = velocity;
    a.radius = 0.3f;
    a.maxSpeed = 1.4f;
    a.maxForce = 3.0f;
    a.mass = 1.0f;
    a.id = id;
    if (glm::length(velocity) > 1e-6f)
        a.forward = glm::normalize(velocity);
    a.up = {0.0f, 1.0f, 0.0f};
    a.side = glm::normalize(glm::cross(a.forward, a.up));
    return a;
}

sim::Neighbour asNeighbour(const sim::SteeringAgent& agent)
{
    return {agent.position, agent.velocity, agent.forward, agent.radius, agent.id};
}

sim::SteeringAgent advance(const sim::SteeringAgent& agent, glm::vec3 force, const sim::VehicleParams& params)
{
    return sim::integrateVehicle(agent, force, kDt, params);
}

float planarDistance(glm::vec3 a, glm::vec3 b) { return glm::length(glm::vec2(a.x - b.x, a.z - b.z)); }

bool crossesSegment(glm::vec3 p0, glm::vec3 p1, glm::vec3 a, glm::vec3 b)
{
    auto cross = [](glm::vec2 u, glm::vec2 v) { return u.x * v.y - u.y * v.x; };
    const glm::vec2 P0{p0.x, p0.z}, P1{p1.x, p1.z}, A{a.x, a.z}, B{b.x, b.z};
    const float d1 = cross(B - A, P0 - A), d2 = cross(B - A, P1 - A);
    const float d3 = cross(P1 - P0, A - P0), d4 = cross(P1 - P0, B - P0);
    return ((d1 >= 0.0f && d2 <= 0.0f) || (d1 <= 0.0f && d2 >= 0.0f)) &&
           ((d3 >= 0.0f && d4 <= 0.0f) || (d3 <= 0.0f && d4 >= 0.0f)) && P0 != P1;
}

float angleBetween(glm::vec3 a, glm::vec3 b)
{
    const float la = glm::length(a), lb = glm::length(b);
    if (la <= 0.0f || lb <= 0.0f)
        return 0.0f;
    return std::acos(std::clamp(glm::dot(a, b) / (la * lb), -1.0f, 1.0f));
}

bool isFinite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool isFinite(const sim::SteeringAgent& a)
{
    return isFinite(a.position) && isFinite(a.velocity) && isFinite(a.forward) && isFinite(a.side) && isFinite(a.up);
}

glm::vec3 signedRandom3(std::uint64_t seed, std::uint32_t id, std::uint64_t step)
{
    return {sim::rngRange(seed, id, step, 0, -1.0f, 1.0f), sim::rngRange(seed, id, step, 1, -1.0f, 1.0f),
            sim::rngRange(seed, id, step, 2, -1.0f, 1.0f)};
}

}  // namespace throng::test
