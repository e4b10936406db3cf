#pragma once
// A ground agent's step of the simple vehicle model (Reynolds 1999): from a finite
// position and velocity, the force truncated, the velocity it reaches within the top
// speed and flat, the position, and the heading from the velocity (the last one kept, made
// flat, below 1 mm/s). integrateVehicle (VehicleModel.h) steps its walkers with it, and
// the walker kernel (WalkKernel.cpp) with the same function. Internal to throng::simcore.
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include "simcore/steering/detail/SteeringConstants.h"
#include "simcore/steering/detail/SteeringMath.h"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace throng::sim::detail {

struct GroundMove {
    glm::vec3 position, velocity, forward;
};

// dtOverMass: dt over the effective mass (effectiveMass); maxForce as given (truncate
// treats a negative or non-finite one as 0); maxSpeed >= 0.
[[gnu::always_inline]] inline GroundMove groundMove(glm::vec3 position, glm::vec3 velocity, glm::vec3 forward,
                                                    glm::vec3 force, float maxForce, float dtOverMass,
                                                    float maxSpeed, float dt)
{
    const glm::vec3 f = truncate(finiteOrZero(force), maxForce);
    glm::vec3 v = truncate(velocity + f * dtOverMass, maxSpeed);
    v.y = 0.0f;
    GroundMove out;
    out.velocity = finiteOrZero(v);
    out.position = finiteOrZero(position + out.velocity * dt);
    out.velocity.y = 0.0f;
    const float speed = glm::length(out.velocity);
    if (speed > kStoppedSpeed) {
        out.forward = out.velocity / speed;
    } else {
        const glm::vec3 unit = normalizeOr(forward, glm::vec3(0.0f, 0.0f, 1.0f));
        out.forward = normalizeOr(glm::vec3(unit.x, 0.0f, unit.z), glm::vec3(0.0f, 0.0f, 1.0f));
    }
    return out;
}

}  // namespace throng::sim::detail
