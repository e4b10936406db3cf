// Separation, alignment, cohesion (Reynolds 1987, "Flocks, Herds, and Schools"; 1999).
#include "simcore/steering/FlockingBehaviours.h"

#include "simcore/steering/detail/BehaviourMath.h"
#include "simcore/steering/detail/SteeringMath.h"
#include "simcore/base/Rng.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace throng::sim {

using namespace detail;

namespace {

// A horizontal unit direction fixed by the unordered pair of ids, pointing from the lower id
// to the higher: two coincident agents compute the same axis and leave it in opposite senses.
glm::vec3 pairAxis(std::uint32_t lowId, std::uint32_t highId)
{
    const std::uint64_t h = mix64((std::uint64_t(lowId) << 32) | highId);
    // The half offsets keep both components away from zero, so the length is never zero.
    const float x = float(h & 0xffffu) - 32767.5f;
    const float z = float((h >> 16) & 0xffffu) - 32767.5f;
    return glm::normalize(glm::vec3(x, 0.0f, z));
}

}  // namespace

glm::vec3 separationAxis(std::uint32_t self, std::uint32_t other)
{
    if (self == other)
        return glm::vec3(1.0f, 0.0f, 0.0f);
    return self > other ? pairAxis(other, self) : -pairAxis(self, other);
}

glm::vec3 separate(const SteeringAgent& agent, std::span<const Neighbour> neighbours, const SeparationParams& params)
{
    const glm::vec3 p = finiteOrZero(agent.position);
    const glm::vec3 v = finiteOrZero(agent.velocity);
    const auto [range, damping] = behave::separationGains(params, effectiveMass(agent.mass));
    const float maxForce = nonNegative(agent.maxForce);
    glm::vec3 push(0.0f);
    behave::SeparationFloor floor;
    for (const Neighbour& n : neighbours) {
        const glm::vec3 rel = p - finiteOrZero(n.position);
        const float d = glm::length(rel);
        const float contact = nonNegative(agent.radius) + nonNegative(n.radius);
        behave::addSeparation(push, floor, rel, d, contact, range, maxForce, damping, v - finiteOrZero(n.velocity),
                              [&] { return separationAxis(agent.id, n.id); });
    }
    return push;
}

glm::vec3 align(const SteeringAgent& agent, std::span<const Neighbour> neighbours, const AlignmentParams& params)
{
    if (neighbours.empty())
        return glm::vec3(0.0f);
    glm::vec3 headings(0.0f), velocities(0.0f);
    for (const Neighbour& n : neighbours) {
        headings += normalizeOr(n.forward, glm::vec3(0.0f));
        velocities += finiteOrZero(n.velocity);
    }
    const behave::Alignment<float> a = behave::alignmentVelocity(headings, velocities, float(neighbours.size()),
                                                                 glm::length(finiteOrZero(agent.velocity)),
                                                                 nonNegative(agent.maxSpeed), params.matchSpeed);
    return a.aligned ? steerTowards(agent, a.desired, params.responseTimeS) : glm::vec3(0.0f);
}

glm::vec3 cohere(const SteeringAgent& agent, std::span<const Neighbour> neighbours, const CohesionParams& params)
{
    if (neighbours.empty())
        return glm::vec3(0.0f);
    glm::vec3 positions(0.0f);
    for (const Neighbour& n : neighbours)
        positions += finiteOrZero(n.position);
    const float slowing = std::max(nonNegative(params.slowingDistanceM), kTiny);
    return steerTowards(agent,
                        behave::cohesionVelocity(agent.position, positions, float(neighbours.size()),
                                                 nonNegative(agent.maxSpeed), slowing),
                        params.responseTimeS);
}

}  // namespace throng::sim
