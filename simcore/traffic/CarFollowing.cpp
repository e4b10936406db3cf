#include "simcore/traffic/CarFollowing.h"

#include <algorithm>
#include <cmath>

namespace throng::sim {

namespace {
float finiteOr(float x, float fallback) { return std::isfinite(x) ? x : fallback; }
float ramp(float x, float lo, float hi) { return std::clamp((x - lo) / (hi - lo), 0.0f, 1.0f); }
float tri(float x, float lo, float mid, float hi) { return std::min(ramp(x, lo, mid), 1.0f - ramp(x, mid, hi)); }

// Inputs made safe once: a NaN speed is treated as standing, a NaN gap as touching.
struct Clean {
    float v, gap, vl;
    bool free;
};
Clean clean(float speed, float gapM, float leaderSpeed)
{
    Clean c;
    c.v = std::max(0.0f, finiteOr(speed, 0.0f));
    c.free = gapM == kFreeRoad;
    c.gap = std::isnan(gapM) ? 0.0f : gapM;
    c.vl = std::max(0.0f, finiteOr(leaderSpeed, 0.0f));
    return c;
}
float bound(const FollowingParams& p, float a) { return std::clamp(finiteOr(a, -p.maxDecel), -p.maxDecel, p.maxAccel); }
}  // namespace

const char* toString(FollowingModel model)
{
    switch (model) {
    case FollowingModel::Idm: return "idm";
    case FollowingModel::GapTime: return "gap_time";
    case FollowingModel::Fuzzy: return "fuzzy";
    }
    return "idm";
}

float followingAcceleration(const FollowingParams& p, float speed, float gapM, float leaderSpeed)
{
    switch (p.model) {
    case FollowingModel::GapTime: return gapTimeAcceleration(p, speed, gapM, leaderSpeed);
    case FollowingModel::Fuzzy: return fuzzyAcceleration(p, speed, gapM, leaderSpeed);
    case FollowingModel::Idm: break;
    }
    return idmAcceleration(p, speed, gapM, leaderSpeed);
}

float idmAcceleration(const FollowingParams& p, float speed, float gapM, float leaderSpeed)
{
    const Clean c = clean(speed, gapM, leaderSpeed);
    const float v0 = std::max(p.desiredSpeed, 0.01f);
    const float free = p.maxAccel * (1.0f - std::pow(c.v / v0, p.delta));
    if (c.free)
        return bound(p, free);
    if (c.gap <= 0.0f)
        return -p.maxDecel;
    // Desired dynamical gap s* = s0 + max(0, vT + v dv / (2 sqrt(ab))).
    const float dv = c.v - c.vl;
    const float sStar =
        p.minGapM + std::max(0.0f, c.v * p.timeHeadwayS + c.v * dv / (2.0f * std::sqrt(p.maxAccel * p.comfortDecel)));
    const float ratio = sStar / std::max(c.gap, 1e-3f);
    return bound(p, free - p.maxAccel * ratio * ratio);
}

float gapTimeAcceleration(const FollowingParams& p, float speed, float gapM, float leaderSpeed)
{
    const Clean c = clean(speed, gapM, leaderSpeed);
    const float v0 = std::max(p.desiredSpeed, 0.0f);
    if (c.free)
        return bound(p, (v0 - c.v) / p.relaxS);
    // The gap divided by the time constant, but never faster than a speed that can
    // still stop within the gap at the comfortable rate if the leader stopped at it too:
    // without that cap the model overshoots a standing obstacle (it needs v / T m/s^2).
    const float room = std::max(0.0f, c.gap - p.minGapM);
    const float target = std::min({v0, room / p.timeHeadwayS, std::sqrt(c.vl * c.vl + 2.0f * p.comfortDecel * room)});
    return bound(p, (target - c.v) / p.relaxS);
}

float fuzzyAcceleration(const FollowingParams& p, float speed, float gapM, float leaderSpeed)
{
    const Clean c = clean(speed, gapM, leaderSpeed);
    const float v0 = std::max(p.desiredSpeed, 0.01f);
    if (!c.free && c.gap <= 0.0f)
        return -p.maxDecel;
    // Inputs: the gap against a safe gap, the closing speed, and the deceleration that
    // closing at this speed would need, as a share of the comfortable one.
    const float safeGap = std::max(p.minGapM + c.v * p.timeHeadwayS, 0.1f);
    const float r = c.free ? 10.0f : c.gap / safeGap;
    const float closing = c.free ? 0.0f : c.v - c.vl;
    const float need =
        closing > 0.0f ? closing * closing / (2.0f * std::max(c.gap - p.minGapM, 0.01f)) / p.comfortDecel : 0.0f;

    const float gapClose = 1.0f - ramp(r, 0.5f, 1.0f);
    const float gapOk = tri(r, 0.5f, 1.0f, 2.0f);
    const float gapFar = ramp(r, 1.0f, 2.0f);
    const float closingFast = ramp(closing, 0.0f, 3.0f);
    const float steady = tri(closing, -2.0f, 0.0f, 2.0f);
    const float opening = 1.0f - ramp(closing, -2.0f, 0.0f);
    const float under = ramp(v0 - c.v, 0.0f, 0.2f * v0);
    const float over = ramp(c.v - v0, 0.0f, 0.1f * v0);

    // Rules: AND = min, OR = max (Mamdani); defuzzified as a weighted average of the
    // candidate accelerations.
    // An emergency overrides the milder rules (they carry AND NOT hardBrake), so the
    // weighted average cannot dilute full braking when the kinematics demand it.
    const float hardBrake = std::max(ramp(need, 1.0f, 1.5f), std::min(gapClose, ramp(closing, 0.0f, 1.0f)));
    const float calm = 1.0f - hardBrake;
    const float accelerate =
        std::min({std::max(gapFar, std::min(gapOk, opening)), under, 1.0f - ramp(need, 0.0f, 0.3f), calm});
    const float keep = std::min(std::max(std::min(gapOk, steady), std::min(gapFar, 1.0f - under)), calm);
    const float brake =
        std::min(std::max({ramp(need, 0.3f, 0.8f), std::min(gapOk, closingFast), over, gapClose}), calm);

    const float sum = accelerate + keep + brake + hardBrake;
    if (!(sum > 0.0f))
        return 0.0f;
    const float a = (accelerate * p.maxAccel - brake * p.comfortDecel - hardBrake * p.maxDecel) / sum;
    return bound(p, a);
}

SpeedStep advanceSpeed(float speed, float accel, float dt)
{
    const float v = std::max(0.0f, finiteOr(speed, 0.0f));
    const float a = finiteOr(accel, 0.0f);
    const float next = v + a * dt;
    if (next < 0.0f)
        return {0.0f, a < 0.0f ? -v * v / (2.0f * a) : 0.0f};
    return {next, std::max(0.0f, v * dt + 0.5f * a * dt * dt)};
}

bool canStopWithin(float speed, float distanceM, float decel)
{
    const float v = std::max(0.0f, finiteOr(speed, 0.0f));
    return v * v <= 2.0f * decel * distanceM;
}

}  // namespace throng::sim
