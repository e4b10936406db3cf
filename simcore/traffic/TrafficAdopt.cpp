// Resuming a TrafficSystem after an edit of the road network or the vehicles (the rule is
// in simcore/world/WorldState.h): a system built from the edited scene takes the clock,
// the counters and each kept vehicle's state from the system that ran before the edit.
#include "simcore/traffic/TrafficSystem.h"

#include <cmath>
#include <map>
#include <tuple>

namespace throng::sim {

bool LaneNetwork::sameCentreLine(int a, const LaneNetwork& other, int b) const
{
    const LaneGeometry &x = m_lanes[std::size_t(a)], &y = other.m_lanes[std::size_t(b)];
    return x.loop == y.loop && x.points == y.points;
}

namespace {

// A stop line by what it is, not by its dense index: (light name, lane name, crosswalk
// centre line) -- an edit that adds a lane or a light renumbers every line after it.
using LineKey = std::tuple<std::string, std::string, float, float, float, float>;

LineKey lineKey(const LaneNetwork& net, const std::vector<TrafficLight>& lights, const StopLineThroughput& t)
{
    const std::string& light = lights[std::size_t(t.light)].name;
    if (t.lane >= 0)
        return {light, net.laneName(t.lane), 0.0f, 0.0f, 0.0f, 0.0f};
    const CrosswalkStrip& c = net.crosswalk(t.crosswalk);
    return {light, std::string(), c.a.x, c.a.y, c.b.x, c.b.y};
}

}  // namespace

void TrafficSystem::startAt(std::uint64_t step)
{
    m_step = step;
    // Green phases so far are not known for a line that did not exist: one when it starts
    // on green, as at time 0.
    for (StopLineThroughput& t : m_throughput)
        t.greenPhases = lightPhaseAt(m_lights[std::size_t(t.light)], timeS()) == LightPhase::Green ? 1 : 0;
    updatePositions();
    markBusyCrosswalks();
    buildVehicleGrid();
}

std::vector<std::int32_t> TrafficSystem::adoptFrom(const TrafficSystem& old)
{
    startAt(old.m_step);
    m_counters = old.m_counters;
    std::map<LineKey, std::size_t> oldLine;
    for (std::size_t k = 0; k < old.m_throughput.size(); ++k)
        oldLine.emplace(lineKey(old.m_net, old.m_lights, old.m_throughput[k]), k);
    std::vector<std::int32_t> lineNow(old.m_throughput.size(), -1);  // old line index -> this one's
    for (std::size_t k = 0; k < m_throughput.size(); ++k)
        if (const auto it = oldLine.find(lineKey(m_net, m_lights, m_throughput[k])); it != oldLine.end()) {
            m_throughput[k].crossings = old.m_throughput[it->second].crossings;
            m_throughput[k].greenPhases = old.m_throughput[it->second].greenPhases;
            lineNow[it->second] = std::int32_t(k);
        }

    std::map<std::uint32_t, std::size_t> oldIndex;
    for (std::size_t k = 0; k < old.m_id.size(); ++k)
        oldIndex.emplace(old.m_id[k], k);
    const bool brains = !old.m_brainSpeed.empty();
    if (brains)
        m_brainSpeed.assign(m_s.size(), std::nanf(""));
    std::vector<std::int32_t> previous(m_s.size(), -1);
    for (std::size_t i = 0; i < m_s.size(); ++i) {
        const auto it = oldIndex.find(m_id[i]);
        if (it == oldIndex.end())
            continue;
        const std::size_t k = it->second;
        const int lane = m_lane[i], was = old.m_lane[k];
        if (m_net.laneName(lane) != old.m_net.laneName(was))
            continue;  // the vehicle was put on another lane: it starts there afresh
        previous[i] = std::int32_t(k);
        m_speed[i] = old.m_speed[k];
        m_goTimer[i] = old.m_goTimer[k];
        m_stops[i] = old.m_stops[k];
        m_respawns[i] = old.m_respawns[k];
        m_active[i] = old.m_active[k];
        m_leftAtStep[i] = old.m_leftAtStep[k];
        if (brains)
            m_brainSpeed[i] = old.m_brainSpeed[k];
        if (!m_active[i])
            m_s[i] = m_net.length(lane);  // off stage at the lane's end, as commit() leaves it
        else if (m_net.sameCentreLine(lane, old.m_net, was))
            m_s[i] = old.m_s[k];
        else
            m_s[i] = m_net.wrap(lane, m_net.project(lane, old.m_pos[k]).s);
        // The yellow decision stays with its stop line while that line is still there.
        const std::int32_t line = old.m_decisionLine[k];
        const std::int32_t now = line >= 0 && std::size_t(line) < lineNow.size() ? lineNow[std::size_t(line)] : -1;
        m_decisionLine[i] = now;
        m_decision[i] = now >= 0 ? old.m_decision[k] : std::uint8_t(kNone);
    }
    updatePositions();
    markBusyCrosswalks();
    buildVehicleGrid();
    return previous;
}

}  // namespace throng::sim
