#include "simcore/world/FlockFigures.h"

#include "simcore/world/World.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>

namespace throng::sim {

// Sums in double and in agent order, so the figures do not depend on the thread count.
FlockFigures FlockFigures::of(const World& world)
{
    FlockFigures f;
    const auto pos = world.positions();
    const auto vel = world.velocities();
    glm::dvec3 heading(0.0), centre(0.0), followerCentre(0.0), leaderCentre(0.0);
    auto isFlier = [&](std::size_t i) { return world.agentKind(i) == AgentKind::Flier; };
    for (std::size_t i = 0; i < world.agentCount(); ++i) {
        if (!isFlier(i))
            continue;
        ++f.fliers;
        centre += glm::dvec3(pos[i]);
        const double speed = glm::length(glm::dvec3(vel[i]));
        if (speed > 1e-9)
            heading += glm::dvec3(vel[i]) / speed;
        if (const std::int32_t l = world.leaderOf(i); l >= 0) {
            ++f.followers;
            followerCentre += glm::dvec3(pos[i]);
            leaderCentre += glm::dvec3(pos[std::size_t(l)]);
        }
    }
    if (f.fliers == 0)
        return f;
    const double n = double(f.fliers);
    f.polarisation = glm::length(heading) / n;
    centre /= n;
    double sum = 0.0;
    for (std::size_t i = 0; i < world.agentCount(); ++i)
        if (isFlier(i)) {
            const glm::dvec3 d = glm::dvec3(pos[i]) - centre;
            sum += glm::dot(d, d);
        }
    f.spreadM = std::sqrt(sum / n);
    if (f.followers > 0)
        f.centreToLeaderM = glm::length(followerCentre - leaderCentre) / double(f.followers);
    return f;
}

}  // namespace throng::sim
