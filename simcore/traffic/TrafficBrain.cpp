// Vehicles driven by brains: the acceleration a brain's wanted speed gives, and the stop
// line ahead that a vehicle's light_state / stop_line_distance sensors read.
#include "simcore/traffic/TrafficSystem.h"

#include <algorithm>
#include <cmath>

namespace throng::sim {

namespace {
constexpr float kBrainResponseS = 1.0f;  // s: the brain's speed is the one wanted this long from now
}  // namespace

void TrafficSystem::setBrainSpeeds(std::span<const float> wantedMps)
{
    m_brainSpeed.assign(wantedMps.begin(), wantedMps.end());
    m_brainSpeed.resize(wantedMps.empty() ? 0 : m_s.size(), std::nanf(""));
}

float TrafficSystem::brainAcceleration(std::size_t i, const FollowingParams& q) const
{
    // A brain slows at most at the comfortable rate: braking beyond it is the safety
    // model's alone (leader, stop line, pedestrians), so a brain's sudden stop cannot
    // outbrake the car-following of the vehicles behind it.
    const float wanted = std::min(m_brainSpeed[i], m_net.speedLimit(m_lane[i]));
    return std::clamp((wanted - m_speed[i]) / kBrainResponseS, -q.comfortDecel, q.maxAccel);
}

VehicleStopLine TrafficSystem::stopLineAhead(std::size_t i) const
{
    VehicleStopLine out;
    if (!m_active[i])
        return out;
    const int lane = m_lane[i];
    const float front = m_s[i] + m_radius[i];
    for (const LaneStopLine& line : m_net.stopLinesOn(lane)) {
        const float d = aheadM(lane, front, line.s);
        if (d >= 0.0f && d <= m_opt.lookaheadM && (!out.found || d < out.distanceM)) {
            out.found = true;
            out.distanceM = d;
            out.light = line.light;
        }
    }
    if (out.found)
        out.phase = lightPhase(out.light);
    return out;
}

}  // namespace throng::sim
