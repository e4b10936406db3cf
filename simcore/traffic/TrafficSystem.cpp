#include "simcore/traffic/TrafficSystem.h"

#include "simcore/scene/StepRate.h"

#include "simcore/base/Rng.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::sim {

namespace {
constexpr std::uint64_t kStreamRespawn = 0x7265737061776eull;

FollowingModel followingModel(CarFollowing model)
{
    switch (model) {
    case CarFollowing::GapTime: return FollowingModel::GapTime;
    case CarFollowing::Fuzzy: return FollowingModel::Fuzzy;
    case CarFollowing::Inherit:
    case CarFollowing::Idm: break;
    }
    return FollowingModel::Idm;
}
}  // namespace

TrafficSystem::TrafficSystem(const Scene& scene, const TrafficOptions& options)
    : m_opt(options), m_knobs(scene.traffic), m_net(scene), m_lights(scene.trafficLights)
{
    m_seed = options.overrideSeed ? options.seed : scene.settings.seed;
    m_dt = physicsStepS(scene.settings.fps);  // the World's step (StepRate.h)
    m_threads = ThreadTeam::resolve(options.threads);

    // One parameter set per (type, model): the model is the lane's, the type's or the scene's.
    std::vector<std::pair<std::string, FollowingModel>> paramKey;
    for (const Vehicle& v : scene.vehicles) {
        const int lane = m_net.findLane(v.lane);
        const AgentType* type = scene.findAgentType(v.type);
        if (lane < 0 || !type)
            continue;
        const FollowingModel model = followingModel(carFollowingOf(scene, scene.findLane(v.lane), type));
        auto known = std::find(paramKey.begin(), paramKey.end(), std::pair{v.type, model});
        if (known == paramKey.end()) {
            FollowingParams p;
            p.model = model;
            p.desiredSpeed = type->maxSpeed;
            for (const auto& [name, params] : options.modelByType)
                if (name == v.type)
                    p = params;
            paramKey.emplace_back(v.type, model);
            m_params.push_back(p);
            known = paramKey.end() - 1;
        }
        m_id.push_back(v.id);
        m_lane.push_back(lane);
        m_paramIndex.push_back(std::uint16_t(known - paramKey.begin()));
        m_s.push_back(m_net.wrap(lane, v.atM));
        m_speed.push_back(std::max(0.0f, v.speed));
        m_radius.push_back(type->radiusM);
        m_maxRadius = std::max(m_maxRadius, type->radiusM);
    }
    const std::size_t n = m_s.size();
    m_goTimer.assign(n, 0.0f);
    m_stops.assign(n, 0);
    m_respawns.assign(n, 0);
    m_active.assign(n, 1);
    m_decision.assign(n, kNone);
    m_decisionLine.assign(n, -1);
    m_leftAtStep.assign(n, 0);
    m_pos.resize(n);
    m_fwd.resize(n);
    m_next.resize(n);
    m_leader.assign(n, -1);
    m_order.reserve(n);
    m_laneBegin.assign(m_net.laneCount() + 1, 0);
    m_lanePeds.resize(m_net.laneCount());
    m_crosswalkPeds.resize(m_net.crosswalkCount());
    m_crosswalkBusy.assign(m_net.crosswalkCount(), 0);

    m_throughput.resize(m_net.stopLineCount());
    for (const LaneStopLine& line : m_net.stopLines())
        m_throughput[std::size_t(line.index)] = {line.light, line.lane, -1, 0, 0};
    for (std::size_t c = 0; c < m_net.crosswalkCount(); ++c)
        if (const int k = m_net.crosswalkStopLineIndex(int(c)); k >= 0)
            m_throughput[std::size_t(k)] = {m_net.crosswalk(int(c)).light, -1, int(c), 0, 0};
    for (StopLineThroughput& t : m_throughput)
        if (lightPhaseAt(m_lights[std::size_t(t.light)], 0.0) == LightPhase::Green)
            t.greenPhases = 1;
    updatePositions();
    markBusyCrosswalks();
    buildVehicleGrid();
}

LightPhase TrafficSystem::lightPhase(int light) const
{
    return lightPhaseAt(m_lights[std::size_t(light)], timeS());
}

void TrafficSystem::step(std::span<const PedestrianView> pedestrians)
{
    const double t0 = timeS();
    // Leaders: active vehicles ordered along each lane.
    sortByLane();
    // Pedestrians near crosswalks and inside lane corridors, in index order.
    collectPedestrians(pedestrians);
    // Each vehicle's next speed and position from the previous state only (threads pay
    // off only for a few hundred vehicles; the result is the same either way).
    const std::size_t n = m_s.size();
    auto advance = [&](std::size_t k) {
        m_next[k] = m_active[k] ? advanceVehicle(k, pedestrians)
                                : NextState{m_s[k], 0.0f, 0.0f, m_stops[k], kNone, -1};
    };
    if (n >= 256 && m_threads > 1) {
        if (!m_team)
            m_team = std::make_shared<ThreadTeam>(m_threads);
        m_team->forEach(n, 64, advance);
    } else {
        for (std::size_t k = 0; k < n; ++k)
            advance(k);
    }
    // Commit in index order: stop-line crossings, lane ends.
    commit(t0);
    ++m_step;
    // Vehicles waiting off stage re-enter open lanes when the entry is clear.
    respawn();
    updatePositions();
    markBusyCrosswalks();
    countGreenOnsets(t0, timeS());
    buildVehicleGrid();
    countVehicleContacts();
}

void TrafficSystem::sortByLane()
{
    m_order.clear();
    for (std::uint32_t i = 0; i < m_s.size(); ++i)
        if (m_active[i])
            m_order.push_back(i);
    std::sort(m_order.begin(), m_order.end(), [&](std::uint32_t a, std::uint32_t b) {
        if (m_lane[a] != m_lane[b])
            return m_lane[a] < m_lane[b];
        if (m_s[a] != m_s[b])
            return m_s[a] < m_s[b];
        return a < b;
    });
    std::fill(m_laneBegin.begin(), m_laneBegin.end(), 0u);
    for (std::uint32_t i : m_order)
        ++m_laneBegin[std::size_t(m_lane[i]) + 1];
    for (std::size_t l = 1; l < m_laneBegin.size(); ++l)
        m_laneBegin[l] += m_laneBegin[l - 1];
    std::fill(m_leader.begin(), m_leader.end(), -1);
    for (std::size_t l = 0; l + 1 < m_laneBegin.size(); ++l) {
        const std::uint32_t b = m_laneBegin[l], e = m_laneBegin[l + 1];
        for (std::uint32_t k = b; k < e; ++k) {
            if (k + 1 < e)
                m_leader[m_order[k]] = std::int32_t(m_order[k + 1]);
            else if (m_net.loops(int(l)))
                m_leader[m_order[k]] = std::int32_t(m_order[b]);  // through the wrap; itself when alone
        }
    }
}

float TrafficSystem::aheadM(int lane, float from, float to) const
{
    float d = to - from;
    if (m_net.loops(lane)) {
        const float len = m_net.length(lane);
        d = std::fmod(d, len);
        if (d < 0.0f)
            d += len;
    }
    return d;
}

float TrafficSystem::goDelayS(std::size_t i, std::uint32_t stops) const
{
    return rngRange(m_seed, m_id[i], stops, 0x676fu, m_knobs.driverStartDelayS.x, m_knobs.driverStartDelayS.y);
}

void TrafficSystem::commit(double t0)
{
    for (std::size_t i = 0; i < m_s.size(); ++i) {
        if (!m_active[i])
            continue;
        const NextState& nx = m_next[i];
        const int lane = m_lane[i];
        const float travel = nx.s - m_s[i];
        const float front = m_s[i] + m_radius[i];
        // A stop line is crossed when the front goes from before it to on or past it;
        // the light is read at the interpolated moment of crossing.
        for (const LaneStopLine& line : m_net.stopLinesOn(lane)) {
            const float d = aheadM(lane, front, line.s);
            if (d < 0.0f || !(d < travel))
                continue;
            const double tc = t0 + double(m_dt) * double(d / travel);
            if (lightPhaseAt(m_lights[std::size_t(line.light)], tc) == LightPhase::Red)
                ++m_counters.vehicleRedLightViolations;
            ++m_throughput[std::size_t(line.index)].crossings;
        }
        if (!std::isfinite(nx.s) || !std::isfinite(nx.speed))
            ++m_counters.nonFiniteValues;
        ++m_counters.vehicleSteps;
        m_speed[i] = nx.speed;
        m_goTimer[i] = nx.goTimer;
        m_stops[i] = nx.stops;
        m_decision[i] = nx.decision;
        m_decisionLine[i] = nx.decisionLine;
        const float len = m_net.length(lane);
        if (nx.s < len) {
            m_s[i] = nx.s;
        } else if (m_net.loops(lane)) {
            m_s[i] = m_net.wrap(lane, nx.s);
        } else {
            m_s[i] = len;
            m_speed[i] = 0.0f;
            m_active[i] = 0;
            m_leftAtStep[i] = m_step + 1;
            m_decision[i] = kNone;
            m_decisionLine[i] = -1;
        }
    }
}

void TrafficSystem::respawn()
{
    for (std::size_t l = 0; l < m_net.laneCount(); ++l) {
        const int lane = int(l);
        if (m_net.loops(lane))
            continue;
        // The longest-waiting vehicle whose own off-stage time is over (ties: lower index).
        std::ptrdiff_t pick = -1;
        for (std::size_t i = 0; i < m_s.size(); ++i) {
            if (m_active[i] || m_lane[i] != lane)
                continue;
            const double waited = double(m_step - m_leftAtStep[i]) * double(m_dt);
            const float delay = rngRange(m_seed, m_id[i], m_respawns[i], kStreamRespawn, m_opt.respawnDelayMinS,
                                         m_opt.respawnDelayMaxS);
            if (waited >= double(delay) && (pick < 0 || m_leftAtStep[i] < m_leftAtStep[std::size_t(pick)]))
                pick = std::ptrdiff_t(i);
        }
        if (pick < 0)
            continue;
        const std::size_t i = std::size_t(pick);
        const float v = entrySpeed(lane, i);
        if (v < 0.0f)
            continue;
        m_active[i] = 1;
        m_s[i] = 0.0f;
        m_speed[i] = v;
        m_goTimer[i] = 0.0f;
        ++m_respawns[i];
    }
}

float TrafficSystem::entrySpeed(int lane, std::size_t i) const
{
    const FollowingParams& p = m_params[m_paramIndex[i]];
    const float r = m_radius[i];
    float v = std::min(p.desiredSpeed, m_net.speedLimit(lane));
    // The nearest active vehicle to the lane's start must leave room for a safe entry.
    std::ptrdiff_t first = -1;
    for (std::size_t k = 0; k < m_s.size(); ++k)
        if (m_active[k] && m_lane[k] == lane && (first < 0 || m_s[k] < m_s[std::size_t(first)]))
            first = std::ptrdiff_t(k);
    if (first >= 0) {
        const std::size_t f = std::size_t(first);
        const float gap = m_s[f] - m_radius[f] - r;
        if (gap < p.minGapM + 1.0f)
            return -1.0f;
        v = std::min({v, m_speed[f], (gap - p.minGapM) / p.timeHeadwayS});
    }
    // Enter slowly enough to stop comfortably before the first stop line and crosswalk.
    for (const LaneStopLine& line : m_net.stopLinesOn(lane))
        if (line.s >= r) {
            v = std::min(v, std::sqrt(2.0f * p.comfortDecel * std::max(0.0f, line.s - r - m_opt.stopMarginM)));
            break;
        }
    for (const LaneStretch& st : m_net.stretchesOn(lane))
        if (st.s0 >= r) {
            v = std::min(v, std::sqrt(2.0f * p.comfortDecel * std::max(0.0f, st.s0 - r - 1.0f)));
            break;
        }
    return std::max(0.0f, v);
}

void TrafficSystem::updatePositions()
{
    for (std::size_t i = 0; i < m_s.size(); ++i) {
        m_pos[i] = m_net.positionAt(m_lane[i], m_s[i]);
        m_fwd[i] = m_net.tangentAt(m_lane[i], m_s[i]);
    }
}

void TrafficSystem::countGreenOnsets(double t0, double t1)
{
    for (StopLineThroughput& t : m_throughput) {
        const TrafficLight& light = m_lights[std::size_t(t.light)];
        if (lightPhaseAt(light, t1) == LightPhase::Green && lightPhaseAt(light, t0) != LightPhase::Green)
            ++t.greenPhases;
    }
}

}  // namespace throng::sim
