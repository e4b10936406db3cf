// The pedestrian side of traffic: who is near a crosswalk or inside a lane (for the
// vehicles' step), the stop answer a walker asks for, and the counts of what walkers did.
#include "simcore/traffic/TrafficSystem.h"
#include "simcore/traffic/detail/LaneMaths.h"

#include "simcore/base/Rng.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::sim {

namespace {
constexpr float kApproachM = 3.0f;     // m before a crosswalk end where a walker counts as approaching
constexpr float kStopBackM = 0.1f;     // m between a waiting walker's body and the end line
constexpr float kClearSideM = 0.2f;    // m: a clearing walker's aim, inside the strip's side walls
constexpr float kAlongCos = 0.5f;      // heading within 60 degrees of a crosswalk's axis: walking along it
constexpr std::uint64_t kStreamPedGo = 0x706564676full;
}  // namespace

using detail::inRange;
using detail::leftOf;

void TrafficSystem::collectPedestrians(std::span<const PedestrianView> peds)
{
    for (auto& list : m_crosswalkPeds)
        list.clear();
    for (auto& list : m_lanePeds)
        list.clear();
    if (m_s.empty())
        return;
    for (std::uint32_t k = 0; k < peds.size(); ++k) {
        const PedestrianView& p = peds[k];
        for (std::size_t c = 0; c < m_net.crosswalkCount(); ++c) {
            const CrosswalkStrip& s = m_net.crosswalk(int(c));
            const glm::vec2 d = p.position - s.a;
            const float u = glm::dot(d, s.dir), w = glm::dot(d, leftOf(s.dir));
            const float reach = kApproachM + p.radiusM;
            if (std::abs(w) <= s.halfWidthM + p.radiusM && u >= -reach && u <= s.lengthM + reach)
                m_crosswalkPeds[c].push_back(k);
        }
        int onCarriageway = -1;  // unknown until a lane's corridor holds it
        for (std::size_t l = 0; l < m_net.laneCount(); ++l) {
            const LaneProjection pr = m_net.project(int(l), p.position);
            if (pr.distanceM > m_maxRadius + p.radiusM + m_knobs.walkerClearanceM)
                continue;
            if (onCarriageway < 0)
                onCarriageway = m_net.carriagewayAt(p.position).lane >= 0 ? 1 : 0;
            m_lanePeds[l].push_back({k, pr.s, pr.lateralM, onCarriageway != 0});
        }
    }
}

PedestrianSignal TrafficSystem::pedestrianSignal(glm::vec2 p, glm::vec2 heading, float speed, float radiusM,
                                                 std::uint32_t pedId) const
{
    PedestrianSignal best;
    float bestDist = kFreeRoad;
    glm::vec2 inward{0.0f}, linePoint{0.0f};
    for (std::size_t c = 0; c < m_net.crosswalkCount(); ++c) {
        const CrosswalkStrip& s = m_net.crosswalk(int(c));
        const glm::vec2 side = leftOf(s.dir);
        const glm::vec2 d = p - s.a;
        const float u = glm::dot(d, s.dir), w = glm::dot(d, side);
        if (std::abs(w) > s.halfWidthM)
            continue;
        const LightPhase phase =
            s.light >= 0 ? lightPhaseAt(m_lights[std::size_t(s.light)], timeS()) : LightPhase::Green;
        const float headingLength = glm::length(heading);
        const float alignment = headingLength > 0.0f ? glm::dot(heading, s.dir) / headingLength : 0.0f;
        const float wClamped =
            std::clamp(w, -std::max(0.0f, s.halfWidthM - radiusM), std::max(0.0f, s.halfWidthM - radiusM));
        // On the road part and walking along the strip; strips that meet at a corner may
        // overlap, and a walker crossing one sideways there is not on that crossing. The
        // walk from a strip's end over the pavement to the kerb is no crossing yet: the
        // kerb line is where it waits (walkers stepped onto the lane from there on red).
        const bool onRoad = m_net.onRoadPart(int(c), p);
        if (onRoad && std::abs(alignment) >= kAlongCos) {
            PedestrianSignal on{int(c), true, false, phase, p, 0.0f};
            if (phase == LightPhase::Red) {
                // Caught on the road by the red: off it by the shorter way, never standing in a lane.
                const bool back = u - s.roadU0 <= s.roadU1 - u;
                const float clearU = back ? s.roadU0 - radiusM - kStopBackM : s.roadU1 + radiusM + kStopBackM;
                // Aimed a little inside the strip's sides: along a side, the kerb's corner
                // held a walker on the road through a whole red.
                const float wInside = std::max(0.0f, s.halfWidthM - radiusM - kClearSideM);
                on.clearing = true;
                on.clearPoint = s.a + s.dir * clearU + side * std::clamp(w, -wInside, wInside);
            }
            return on;
        }
        const float along = alignment;
        float dist = kFreeRoad;
        glm::vec2 in{0.0f}, at{0.0f};
        // Approaching: from kApproachM before the strip's end (or before the kerb line, where
        // the strip's end lies on the road) up to the kerb line.
        const float middle = 0.5f * (s.roadU0 + s.roadU1);
        if (!onRoad && u < middle && u >= std::min(0.0f, s.roadU0) - (kApproachM + radiusM) && along >= kAlongCos) {
            dist = std::max(0.0f, s.roadU0 - u);
            in = s.dir;
            at = s.a + s.dir * s.roadU0 + side * wClamped;
        } else if (!onRoad && u > middle && u <= std::max(s.lengthM, s.roadU1) + kApproachM + radiusM &&
                   along <= -kAlongCos) {
            dist = std::max(0.0f, u - s.roadU1);
            in = -s.dir;
            at = s.a + s.dir * s.roadU1 + side * wClamped;
        }
        if (dist < bestDist) {
            bestDist = dist;
            best = PedestrianSignal{int(c), false, false, phase, {}, dist};
            inward = in;
            linePoint = at;
        }
    }
    if (best.crosswalk < 0 || best.onCrosswalk)
        return best;
    best.stopPoint = linePoint - inward * (radiusM + kStopBackM);
    best.inward = inward;
    best.vehicleCrossing = m_crosswalkBusy[std::size_t(best.crosswalk)] != 0;
    const CrosswalkStrip& strip = m_net.crosswalk(best.crosswalk);
    if (strip.light < 0) {
        best.mustStop = best.vehicleCrossing;
        return best;
    }
    const TrafficLight& light = m_lights[std::size_t(strip.light)];
    switch (best.phase) {
    case LightPhase::Green: {
        // Each walker steps off its own reaction delay after the green begins.
        const double cycle = double(light.greenS) + double(light.yellowS) + double(light.redS);
        const double shifted = timeS() + double(light.offsetS);
        const double cycleIndex = std::floor(shifted / cycle);
        const double sinceGreen = shifted - cycleIndex * cycle;
        const float delay = rngRange(m_seed, pedId, std::uint64_t(std::int64_t(cycleIndex)), kStreamPedGo,
                                     m_knobs.walkerStartDelayS.x, m_knobs.walkerStartDelayS.y);
        best.mustStop = sinceGreen < double(delay);
        break;
    }
    case LightPhase::Yellow: {
        // Stop when it still can, and when it would reach the kerb line only in the yellow's
        // last step or later (it stepped onto the road as the red began).
        const double cycle = double(light.greenS) + double(light.yellowS) + double(light.redS);
        const double shifted = timeS() + double(light.offsetS);
        const double yellowLeftS =
            double(light.greenS) + double(light.yellowS) - (shifted - std::floor(shifted / cycle) * cycle);
        const bool lateForYellow = double(best.distanceToLineM) >= double(speed) * (yellowLeftS - double(m_dt));
        best.mustStop =
            lateForYellow || canStopWithin(speed, best.distanceToLineM - radiusM - kStopBackM, m_opt.pedestrianDecel);
        break;
    }
    case LightPhase::Red:
        best.mustStop = true;
        break;
    }
    best.mustStop = best.mustStop || best.vehicleCrossing;
    return best;
}

glm::vec2 holdBehindStopLine(const PedestrianSignal& signal, glm::vec2 to)
{
    if (!signal.mustStop || signal.onCrosswalk || signal.crosswalk < 0)
        return to;
    const float past = glm::dot(to - signal.stopPoint, signal.inward);
    return past > 0.0f ? to - signal.inward * past : to;
}

void TrafficSystem::markBusyCrosswalks()
{
    std::fill(m_crosswalkBusy.begin(), m_crosswalkBusy.end(), std::uint8_t(0));
    for (std::size_t i = 0; i < m_s.size(); ++i) {
        if (!m_active[i])
            continue;
        const int lane = m_lane[i];
        const float r = m_radius[i], front = m_s[i] + r, v = m_speed[i];
        const FollowingParams& q = m_params[m_paramIndex[i]];
        for (const LaneStretch& st : m_net.stretchesOn(lane)) {
            const float past = aheadM(lane, st.s0 - m_knobs.crossingMarginM, front);  // front beyond the strip's start
            const bool on = past >= 0.0f && past <= st.s1 - st.s0 + 2.0f * (r + m_knobs.crossingMarginM);
            // In the junction box (past the stop line guarding the strip): it will cross, so
            // walkers let it clear instead of stranding it in the junction.
            const bool inBox = st.boxEntryS < st.s0 &&
                               inRange(aheadM(lane, st.boxEntryS, front), 0.0f, st.s0 - st.boxEntryS);
            const float d = aheadM(lane, front, st.s0);
            const bool committed = v > 0.1f && d >= 0.0f && d <= m_opt.lookaheadM &&
                                   !canStopWithin(v, std::max(0.0f, d - 1.0f), q.comfortDecel);
            if (on || committed || inBox)
                m_crosswalkBusy[std::size_t(st.crosswalk)] = 1;
        }
    }
}

void TrafficSystem::observePedestrians(std::span<const PedestrianView> before, std::span<const PedestrianView> after)
{
    const std::size_t n = std::min(before.size(), after.size());
    const double t1 = timeS();
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t c = 0; c < m_net.crosswalkCount(); ++c) {
            const int k = m_net.crosswalkStopLineIndex(int(c));
            if (k < 0)
                continue;
            // Onto the road part on red (the World's stats count the same way).
            const CrosswalkStrip& s = m_net.crosswalk(int(c));
            if (m_net.onRoadPart(int(c), after[i].position) && !m_net.onRoadPart(int(c), before[i].position) &&
                lightPhaseAt(m_lights[std::size_t(s.light)], t1) == LightPhase::Red)
                ++m_counters.pedestrianRedLightViolations;
            // Throughput: stepping onto the strip across one of its end lines.
            const float ub = glm::dot(before[i].position - s.a, s.dir);
            const float ua = glm::dot(after[i].position - s.a, s.dir);
            const float wa = glm::dot(after[i].position - s.a, leftOf(s.dir));
            if (std::abs(wa) > s.halfWidthM)
                continue;
            if ((ub < 0.0f && ua >= 0.0f) || (ub > s.lengthM && ua <= s.lengthM))
                ++m_throughput[std::size_t(k)].crossings;
        }
    }
    countPedestrianContacts(after.subspan(0, n));
}

}  // namespace throng::sim
