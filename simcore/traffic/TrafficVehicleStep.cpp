// One vehicle's step: the smallest of the accelerations its leader, the next stop line
// and the pedestrians ahead allow, then a reaction delay before a standing car moves off.
#include "simcore/traffic/TrafficSystem.h"
#include "simcore/traffic/detail/LaneMaths.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::sim {

namespace {
constexpr float kStandingSpeed = 0.1f;  // m/s: below this a vehicle counts as standing
constexpr float kGoAccel = 0.2f;        // m/s^2: a standing driver moves off only for more than this
constexpr float kYieldBeforeM = 1.0f;   // m: where a yielding vehicle waits before a crosswalk strip
constexpr float kLineSlackM = 0.05f;    // m: short of the stop line where a late stop must end
}  // namespace

using detail::inRange;

TrafficSystem::NextState TrafficSystem::advanceVehicle(std::size_t i, std::span<const PedestrianView> peds) const
{
    const int lane = m_lane[i];
    const float v = m_speed[i], r = m_radius[i];
    FollowingParams q = m_params[m_paramIndex[i]];
    q.desiredSpeed = std::min(q.desiredSpeed, m_net.speedLimit(lane));
    NextState next{m_s[i], v, m_goTimer[i], m_stops[i], m_decision[i], m_decisionLine[i]};

    // Leader on the same lane; on a looping lane through the wrap (itself when alone).
    float gap = kFreeRoad, leaderSpeed = 0.0f;
    if (const std::int32_t ld = m_leader[i]; ld >= 0) {
        const std::size_t l = std::size_t(ld);
        const float d = l == i ? m_net.length(lane) : aheadM(lane, m_s[i], m_s[l]);
        gap = d - r - m_radius[l];
        leaderSpeed = m_speed[l];
    }
    // The car-following model, the stop line and the pedestrians bound every vehicle; a
    // brain only ever lowers that (it cannot close the gap, run a red or hit a walker).
    float a =
        std::min({followingAcceleration(q, v, gap, leaderSpeed), stopLineLimit(i, q, next), yieldLimit(i, q, peds)});
    if (i < m_brainSpeed.size() && !std::isnan(m_brainSpeed[i]))
        a = std::min(a, brainAcceleration(i, q));

    // Start-up delay: a standing driver moves off only after being free to go for its
    // own random delay, so a queue leaves one car after another, not as one block.
    if (v < kStandingSpeed) {
        if (a > std::min(kGoAccel, 0.5f * q.maxAccel)) {
            next.goTimer += m_dt;
            if (next.goTimer < goDelayS(i, m_stops[i]))
                a = std::min(a, 0.0f);
        } else {
            next.goTimer = 0.0f;
            a = std::min(a, 0.0f);
        }
    } else {
        next.goTimer = 0.0f;
    }
    const SpeedStep st = advanceSpeed(v, a, m_dt);
    next.s = m_s[i] + st.distanceM;
    next.speed = st.speed;
    if (v >= kStandingSpeed && st.speed < kStandingSpeed)
        ++next.stops;
    return next;
}

float TrafficSystem::stopLineLimit(std::size_t i, const FollowingParams& q, NextState& next) const
{
    const int lane = m_lane[i];
    const float front = m_s[i] + m_radius[i];
    const LaneStopLine* nearest = nullptr;
    float dist = 0.0f;
    for (const LaneStopLine& line : m_net.stopLinesOn(lane)) {
        const float d = aheadM(lane, front, line.s);
        if (d >= 0.0f && d <= m_opt.lookaheadM && (!nearest || d < dist)) {
            nearest = &line;
            dist = d;
        }
    }
    if (!nearest) {
        next.decision = kNone;
        next.decisionLine = -1;
        return holdPastLine(i);
    }
    if (next.decisionLine != nearest->index) {
        next.decision = kNone;
        next.decisionLine = nearest->index;
    }
    const float v = m_speed[i];
    const float toWait = dist - m_opt.stopMarginM;
    switch (lightPhaseAt(m_lights[std::size_t(nearest->light)], timeS())) {
    case LightPhase::Green:
        next.decision = kNone;
        return holdPastLine(i);
    case LightPhase::Yellow:
        // The dilemma zone: stop only when that needs no more than the yellow deceleration.
        if (next.decision == kNone)
            next.decision = canStopWithin(v, toWait, q.yellowDecel) ? kStop : kGo;
        break;
    case LightPhase::Red:
        // A driver committed on yellow keeps going unless full braking still stops it before
        // the line itself (a car slowed by its brain crept over the line on red when only
        // its waiting point, past which it already was, was checked).
        if (next.decision != kGo || canStopWithin(v, toWait, q.maxDecel) ||
            canStopWithin(v, dist - kLineSlackM, q.maxDecel))
            next.decision = kStop;
        break;
    }
    if (next.decision != kStop)
        return holdPastLine(i);
    // The waiting point acts as a standing leader: the model halts minGap behind a
    // leader, so the obstacle is placed minGap beyond the waiting point.
    const float a = followingAcceleration(q, v, toWait + q.minGapM, 0.0f);
    // The model brakes softly for a small gap at a low speed: where that would carry the
    // front over the line, brake as hard as it takes (up to maxDecel) to stop before it.
    const float need = v * v / (2.0f * std::max(dist - kLineSlackM, 1e-3f));
    return need > -a && (toWait <= 0.0f || need >= q.comfortDecel) ? std::max(-need, -q.maxDecel) : a;
}

float TrafficSystem::holdPastLine(std::size_t i) const
{
    // A vehicle standing past its stop line (it stopped late, or yielded there) on red
    // stays until green: a car that stopped 3 cm past its line on the car brain then
    // drove over the crosswalk on red. Only before the first crosswalk after the line:
    // beyond it, in a junction, it clears the way.
    if (m_speed[i] >= kStandingSpeed)
        return kFreeRoad;
    const int lane = m_lane[i];
    const float front = m_s[i] + m_radius[i];
    float previousS0 = -kFreeRoad;
    for (const LaneStretch& st : m_net.stretchesOn(lane)) {
        const bool first = st.boxEntryS < st.s0 && previousS0 <= st.boxEntryS;
        previousS0 = st.s0;
        if (!first || front < st.boxEntryS || front >= st.s0)
            continue;
        for (const LaneStopLine& line : m_net.stopLinesOn(lane))
            if (line.s == st.boxEntryS && lightPhaseAt(m_lights[std::size_t(line.light)], timeS()) == LightPhase::Red)
                return 0.0f;
    }
    return kFreeRoad;
}

float TrafficSystem::yieldLimit(std::size_t i, const FollowingParams& q, std::span<const PedestrianView> peds) const
{
    float a = kFreeRoad;
    if (peds.empty())
        return a;
    const int lane = m_lane[i];
    const float v = m_speed[i], r = m_radius[i], s = m_s[i];
    const float front = s + r;
    // Crosswalks ahead: wait before one a pedestrian is on, or about to step into our path.
    for (const LaneStretch& st : m_net.stretchesOn(lane)) {
        const float d = aheadM(lane, front, st.s0);
        const float onIt = aheadM(lane, st.s0, front);  // how far the front is past the strip's start
        if (onIt >= 0.0f && onIt <= st.s1 - st.s0 + 2.0f * r)
            continue;  // on the strip already: the pedestrian check below brakes if needed
        if (d < 0.0f || d > m_opt.lookaheadM)
            continue;
        const CrosswalkStrip& strip = m_net.crosswalk(st.crosswalk);
        const float uLane = glm::dot(m_net.positionAt(lane, 0.5f * (st.s0 + st.s1)) - strip.a, strip.dir);
        const float corridor = r + m_knobs.walkerClearanceM;  // the body's half width and a buffer around the centre line
        // Past the stop line guarding the crosswalk, walkers wait for this vehicle (see
        // markBusyCrosswalks): it yields only to those already on the strip.
        const bool inBox =
            st.boxEntryS < st.s0 && inRange(aheadM(lane, st.boxEntryS, front), 0.0f, st.s0 - st.boxEntryS);
        if (crosswalkConflict(st.crosswalk, uLane, corridor, !inBox, peds))
            a = std::min(a, followingAcceleration(q, v, d - kYieldBeforeM + q.minGapM, 0.0f));
    }
    // Anyone inside the vehicle's own corridor ahead, on a crosswalk or not.
    for (const LanePed& lp : m_lanePeds[std::size_t(lane)]) {
        const PedestrianView& p = peds[lp.ped];
        // The buffer only on the carriageway: a walker waiting at the kerb, its body clear
        // of the vehicle's, is passed (with the buffer, a car in a junction waited for a
        // walker at the kerb who waited for the car).
        if (std::abs(lp.lateralM) > r + p.radiusM + (lp.onCarriageway ? m_knobs.walkerClearanceM : 0.0f))
            continue;
        const float d = aheadM(lane, s, lp.s);
        if (d < 0.0f || d > m_opt.lookaheadM)
            continue;
        a = std::min(a, followingAcceleration(q, v, d - r - p.radiusM - m_knobs.walkerClearanceM, 0.0f));
    }
    return a;
}

bool TrafficSystem::crosswalkConflict(int crosswalk, float uLane, float corridorM, bool approachingCount,
                                      std::span<const PedestrianView> peds) const
{
    const CrosswalkStrip& strip = m_net.crosswalk(crosswalk);
    const bool walkGreen = approachingCount && (strip.light < 0 || lightPhaseAt(m_lights[std::size_t(strip.light)],
                                                                                timeS()) == LightPhase::Green);
    for (std::uint32_t k : m_crosswalkPeds[std::size_t(crosswalk)]) {
        const PedestrianView& p = peds[k];
        const float u = glm::dot(p.position - strip.a, strip.dir);
        // On the road part; one waiting at the kerb, even a little past its stop point, is not.
        const bool onRoad = m_net.onRoadPart(crosswalk, p.position);
        if (!onRoad && !walkGreen)
            continue;  // waiting at the kerb for its own green
        const float apart = std::abs(u - uLane) - (corridorM + p.radiusM);
        if (apart <= 0.0f)
            return true;
        const float toward = glm::dot(p.velocity, strip.dir) * (uLane > u ? 1.0f : -1.0f);
        if (toward > m_knobs.waitingSpeed && apart < toward * m_knobs.yieldHorizonS)
            return true;
    }
    return false;
}

}  // namespace throng::sim
