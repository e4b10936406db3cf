// The simple vehicle model (Reynolds 1999, "A Simple Vehicle Model"), with banking for
// fliers as in OpenSteer's SimpleVehicle::applySteeringForce.
#include "simcore/steering/VehicleModel.h"

#include "simcore/steering/detail/BehaviourMath.h"
#include "simcore/steering/detail/GroundMove.h"
#include "simcore/steering/detail/SteeringConstants.h"
#include "simcore/steering/detail/SteeringMath.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::sim {

using namespace detail;

namespace {

SteeringAgent sanitised(const SteeringAgent& s)
{
    SteeringAgent out = s;
    out.position = finiteOrZero(s.position);
    out.velocity = finiteOrZero(s.velocity);
    out.forward = normalizeOr(s.forward, glm::vec3(0.0f, 0.0f, 1.0f));
    out.up = normalizeOr(s.up, kWorldUp);
    out.side = normalizeOr(s.side, rightOfForward(out.forward));
    return out;
}

void flyingFrame(SteeringAgent& s, glm::vec3 acceleration, float dt, const VehicleParams& params)
{
    const float speed = glm::length(s.velocity);
    if (speed > kStoppedSpeed)
        s.forward = s.velocity / speed;
    // Bank: up leans toward the lateral acceleration, smoothed so a step change of force tilts gradually.
    // The blend is the same for every agent of a type each step: remembered, not recomputed.
    thread_local float lastDt = 0.0f, lastResponse = 0.0f, lastBlend = 0.0f;
    if (dt != lastDt || params.bankingResponseS != lastResponse) {
        lastDt = dt;
        lastResponse = params.bankingResponseS;
        lastBlend = behave::bankingBlend(params.bankingResponseS, dt);
    }
    const glm::vec3 up =
        behave::bankedUp(s.up, s.forward, acceleration, nonNegative(params.bankingGainS2PerM), lastBlend);
    // Orthonormalise; a forward parallel to up keeps the previous side.
    behave::SquareFrame<float> frame = behave::squareFrame<float>(s.forward, up);
    if (!frame.square)
        frame = behave::squareFrameAlong(s.forward, up, s.side);
    s.side = frame.side;
    s.up = frame.up;
}

}  // namespace

SteeringAgent integrateVehicle(const SteeringAgent& state, glm::vec3 force, float dt, const VehicleParams& params)
{
    if (!(std::isfinite(dt) && dt > 0.0f))
        return sanitised(state);
    // A walker's frame is rebuilt from scratch, so only its position and velocity need
    // sanitising first (the old forward matters only when it stands: groundMove, the
    // walker kernel's step too).
    if (!params.flying) {
        SteeringAgent s = state;
        const GroundMove move =
            groundMove(finiteOrZero(state.position), finiteOrZero(state.velocity), state.forward, force,
                       state.maxForce, dt / effectiveMass(state.mass), nonNegative(state.maxSpeed), dt);
        s.position = move.position;
        s.velocity = move.velocity;
        s.forward = move.forward;
        s.up = kWorldUp;
        s.side = rightOfForward(s.forward);
        return s;
    }
    SteeringAgent s = sanitised(state);
    const float maxSpeed = nonNegative(s.maxSpeed);
    const glm::vec3 f = truncate(finiteOrZero(force), s.maxForce);
    const glm::vec3 before = s.velocity;
    const glm::vec3 v = behave::flierVelocity(before, f, dt / effectiveMass(s.mass), maxSpeed,
                                              std::min(nonNegative(params.minSpeed), maxSpeed), s.forward);
    s.velocity = finiteOrZero(v);
    s.position = finiteOrZero(s.position + s.velocity * dt);
    flyingFrame(s, (s.velocity - before) / dt, dt, params);
    return s;
}

}  // namespace throng::sim
