#pragma once
// Small vector helpers shared by the steering behaviours: safe normalisation, truncation,
// the planar (x, z) view and the desired-velocity-to-force conversion. Internal to
// simcore/steering. Every helper returns finite values for finite and non-finite input.
#ifndef THRONG_SIMCORE_BUILD
#error "a detail/ header, private to throng::simcore: include the module's public headers instead"
#endif

#include "simcore/base/detail/PlanarSegments.h"
#include "simcore/steering/SteeringAgent.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace throng::sim::detail {

inline constexpr float kTiny = 1e-6f;             // lengths below this count as zero
inline constexpr float kMinMassKg = 1e-3f;        // zero or negative mass is clamped to 1 g
inline constexpr float kMinResponseTimeS = 1e-3f; // response times are clamped to 1 ms
inline const glm::vec3 kWorldUp{0.0f, 1.0f, 0.0f};

inline constexpr float kInfinity = std::numeric_limits<float>::infinity();

// These run dozens of times per agent per step, so they are written as plain compares:
// x * 0 is 0 for every finite x and NaN for an infinity or a NaN, so a sum of such
// products is 0 exactly when all are finite (one branch instead of one per component).
inline bool isFinite(float x) { return std::isfinite(x); }
inline bool isFinite(glm::vec2 v) { return v.x * 0.0f + v.y * 0.0f == 0.0f; }
inline bool isFinite(glm::vec3 v) { return v.x * 0.0f + v.y * 0.0f + v.z * 0.0f == 0.0f; }

inline float finiteOr(float x, float fallback) { return std::isfinite(x) ? x : fallback; }
inline glm::vec3 finiteOrZero(glm::vec3 v) { return isFinite(v) ? v : glm::vec3(0.0f); }

// A limit parameter made usable: non-finite or negative becomes 0 (NaN fails both compares).
inline float nonNegative(float x) { return x > 0.0f && x < kInfinity ? x : 0.0f; }

inline float effectiveMass(float massKg) { return massKg > kMinMassKg && massKg < kInfinity ? massKg : kMinMassKg; }

// One division and a multiply per component (not three divisions): these run several
// times per agent per step.
inline glm::vec3 normalizeOr(glm::vec3 v, glm::vec3 fallback)
{
    const float l = glm::length(v);
    return l > kTiny && l < kInfinity ? v * (1.0f / l) : fallback;
}

inline glm::vec2 normalizeOr(glm::vec2 v, glm::vec2 fallback)
{
    const float l = glm::length(v);
    return l > kTiny && l < kInfinity ? v * (1.0f / l) : fallback;
}

// Shortens v to at most maxLength (<= 0 gives zero); keeps its direction.
inline glm::vec3 truncate(glm::vec3 v, float maxLength)
{
    maxLength = nonNegative(maxLength);
    const float l2 = glm::dot(v, v);  // >= 0, +inf or NaN
    if (!(l2 < kInfinity))
        return glm::vec3(0.0f);
    return l2 > maxLength * maxLength ? v * (maxLength / std::sqrt(l2)) : v;
}

inline glm::vec3 fromXz(glm::vec2 v) { return {v.x, 0.0f, v.y}; }

// The right-hand horizontal perpendicular of a planar direction (x, z): for heading +z it is -x,
// the same side as cross(forward, +y).
inline glm::vec2 rightOf(glm::vec2 d) { return {-d.y, d.x}; }

inline float cross2(glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; }

// The agent's planar heading: its velocity when moving, else its forward; zero when both are
// vertical or zero.
inline glm::vec2 planarHeading(const SteeringAgent& agent)
{
    const glm::vec2 v = xz(agent.velocity);
    const float l = glm::length(v);
    if (l > kTiny && l < kInfinity)
        return v * (1.0f / l);
    return normalizeOr(xz(agent.forward), glm::vec2(0.0f));
}

// The agent's heading in 3D: velocity when moving, else forward, else +z.
inline glm::vec3 heading(const SteeringAgent& agent)
{
    const float l = glm::length(agent.velocity);
    if (l > kTiny && l < kInfinity)
        return agent.velocity * (1.0f / l);
    return normalizeOr(agent.forward, glm::vec3(0.0f, 0.0f, 1.0f));
}

// The right of a 3D forward direction with world up; falls back to -x when forward is vertical.
inline glm::vec3 rightOfForward(glm::vec3 forward)
{
    return normalizeOr(glm::cross(forward, kWorldUp), glm::vec3(-1.0f, 0.0f, 0.0f));
}

// The force per unit of velocity change that reaches it in responseTimeS (clamped to at
// least kMinResponseTimeS; a non-finite time counts as the minimum): mass / time.
inline float responseGain(float mass, float responseTimeS)
{
    return mass / (std::isfinite(responseTimeS) ? std::max(responseTimeS, kMinResponseTimeS) : kMinResponseTimeS);
}

}  // namespace throng::sim::detail
