// The World's traffic phases: vehicles driven by the TrafficSystem and heroes by their
// keyframes are agents that others perceive and steer round but never push; walkers obey
// the crosswalk signals and keep off the carriageway (kerbs are walls). The call order is
// the one TrafficSystem.h gives; every per-agent loop writes only its own agent.
#include "simcore/world/World.h"

#include "simcore/world/Constraints.h"
#include "simcore/world/Sense.h"

#include "simcore/steering/TargetBehaviours.h"
#include "simcore/traffic/LightPhase.h"
#include "simcore/traffic/WalkerBarriers.h"
#include "simcore/world/detail/StepGeometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>

namespace throng::sim {

using namespace detail;

namespace {
constexpr float kEndLineMarginM = 1e-3f;    // m: how far behind a crosswalk's kerb line a held walker stays

glm::vec3 onGround(glm::vec2 p, float y) { return {p.x, y, p.y}; }
}  // namespace

void World::buildTraffic(const Scene& scene)
{
    if (!scene.lanes.empty() || !scene.vehicles.empty()) {
        TrafficOptions options;
        options.seed = m_seed;
        options.overrideSeed = true;
        options.threads = m_team.size();
        m_traffic.system.emplace(scene, options);
    }
    for (const Hero& h : scene.heroes)
        if (!h.keyframes.empty())
            m_traffic.heroes.emplace_back(h);
    for (const Lane& l : scene.lanes)
        m_traffic.laneNames.push_back(l.name);
    for (const Crosswalk& c : scene.crosswalks)
        m_traffic.crosswalkNames.push_back(c.name);
    for (const TrafficLight& l : scene.trafficLights)
        m_traffic.lightNames.push_back(l.name);
}

void World::appendKerbs(std::vector<Segment>& walls) const
{
    if (!m_traffic.system)
        return;
    for (const BarrierSegment& b : walkerBarriers(m_traffic.system->lanes()))
        walls.push_back({b.a, b.b});
}

void World::addTrafficAgents(const Scene& scene)
{
    auto typeOf = [&](const std::string& name) {
        for (std::size_t t = 0; t < scene.agentTypes.size(); ++t)
            if (scene.agentTypes[t].name == name)
                return std::uint16_t(t);
        return std::uint16_t(0);
    };
    const std::size_t walkers = m_agents.pos.size();
    if (m_traffic.system) {
        const TrafficSystem& ts = *m_traffic.system;
        std::map<std::uint32_t, std::string> typeById;
        for (const Vehicle& v : scene.vehicles)
            typeById[v.id] = v.type;
        for (std::size_t v = 0; v < ts.vehicleCount(); ++v) {
            const glm::vec2 p = ts.position(v), f = ts.forward(v);
            m_traffic.vehicleAgent.push_back(std::uint32_t(m_agents.pos.size()));
            addAgent(scene, ts.id(v), typeOf(typeById[ts.id(v)]), onGround(p, 0.0f), std::atan2(-f.y, f.x), -1, -1, 0);
            m_agents.vel.back() = glm::vec3(f.x, 0.0f, f.y) * ts.speed(v);
            m_agents.radius.back() = ts.radius(v);
        }
    }
    std::size_t k = 0;
    for (const Hero& h : scene.heroes) {
        if (h.keyframes.empty())
            continue;
        const HeroTrack& track = m_traffic.heroes[k++];
        const glm::vec2 f = track.forwardAt(0.0);
        m_traffic.heroAgent.push_back(std::uint32_t(m_agents.pos.size()));
        addAgent(scene, h.id, typeOf(h.type), glm::vec3(0.0f), std::atan2(-f.y, f.x), -1, -1, 0);
        m_agents.pos.back() = m_agents.nextPos.back() = m_agents.resolvedPos.back() = track.positionAt(0.0);
        m_agents.vel.back() = track.velocityAt(0.0);
    }
    const std::size_t n = m_agents.pos.size();
    m_traffic.driven.assign(n, 0);
    m_traffic.offStage.assign(n, 0);
    for (std::size_t i = walkers; i < n; ++i) {
        m_traffic.driven[i] = 1;
        // A driven agent counts as standing for the step's phases: it is never steered,
        // and a walker that overlaps it takes the whole correction.
        m_agents.stopped[i] = 1;
        m_agents.stoppedBefore[i] = 1;
    }
    for (std::size_t i = 0; i < walkers; ++i)
        if (m_types.params[m_agents.info[i].typeIndex].kind == AgentKind::Pedestrian)
            m_traffic.pedestrians.push_back(std::uint32_t(i));
    for (std::uint32_t h : m_traffic.heroAgent)
        m_traffic.pedestrians.push_back(h);
    m_traffic.before.resize(m_traffic.pedestrians.size());
    m_traffic.after.resize(m_traffic.pedestrians.size());
    m_traffic.signal.assign(m_traffic.system ? n : 0, PedestrianSignal{});
}

void World::trafficBeforeStep()
{
    if (!m_traffic.system)
        return;
    for (std::size_t k = 0; k < m_traffic.pedestrians.size(); ++k) {
        const std::uint32_t i = m_traffic.pedestrians[k];
        m_traffic.before[k] = {xz(m_agents.pos[i]), xz(m_agents.vel[i]), m_agents.radius[i]};
    }
    m_traffic.system->step(m_traffic.before);
}

glm::vec3 World::obeySignal(std::size_t i, const SteeringAgent& self, glm::vec3 force)
{
    if (m_traffic.signal.empty() || m_types.params[m_agents.info[i].typeIndex].kind != AgentKind::Pedestrian)
        return force;
    PedestrianSignal& sig = m_traffic.signal[i];
    sig = m_traffic.system->pedestrianSignal(xz(m_agents.pos[i]), wantedHeading(view(), i), glm::length(xz(m_agents.vel[i])),
                                             m_agents.radius[i], m_agents.info[i].id);
    if (sig.clearing) {
        // Red caught it on the road: to the nearer kerb at full speed, whatever its path says.
        return seek(self, onGround(sig.clearPoint, self.position.y));
    }
    if (!sig.mustStop || sig.onCrosswalk || sig.crosswalk < 0)
        return force;
    // Stop at the stop point instead of following the path onto the crosswalk.
    ArrivalParams arrival;
    arrival.slowingDistanceM = 1.0f;
    return arrive(self, onGround(sig.stopPoint, self.position.y), arrival);
}

void World::holdAtSignal(std::size_t i, glm::vec3& p) const
{
    if (m_traffic.signal.empty())
        return;
    const glm::vec2 q = holdBehindStopLine(m_traffic.signal[i], xz(p));
    p.x = q.x;
    p.z = q.y;
}

void World::driveTrafficAgents()
{
    if (m_traffic.system) {
        const TrafficSystem& ts = *m_traffic.system;
        m_traffic.anyOffStage = false;
        for (std::size_t v = 0; v < m_traffic.vehicleAgent.size(); ++v) {
            const std::size_t i = m_traffic.vehicleAgent[v];
            const glm::vec2 p = ts.position(v), f = ts.forward(v);
            m_traffic.offStage[i] = ts.active(v) ? 0 : 1;
            m_traffic.anyOffStage = m_traffic.anyOffStage || !ts.active(v);
            m_agents.nextPos[i] = onGround(p, m_set.groundHeight(p.x, p.y));
            m_agents.nextVel[i] = glm::vec3(f.x, 0.0f, f.y) * (ts.active(v) ? ts.speed(v) : 0.0f);
            m_agents.nextFwd[i] = glm::vec3(f.x, 0.0f, f.y);
            m_agents.nextSide[i] = glm::vec3(-f.y, 0.0f, f.x);
        }
    }
    const double t1 = double(m_clock.step + 1) * double(m_clock.dt);
    for (std::size_t h = 0; h < m_traffic.heroAgent.size(); ++h) {
        const std::size_t i = m_traffic.heroAgent[h];
        const HeroTrack& track = m_traffic.heroes[h];
        const glm::vec2 f = track.forwardAt(t1);
        m_agents.nextPos[i] = track.positionAt(t1);
        m_agents.nextVel[i] = track.velocityAt(t1);
        m_agents.nextFwd[i] = glm::vec3(f.x, 0.0f, f.y);
        m_agents.nextSide[i] = glm::vec3(-f.y, 0.0f, f.x);
    }
}

void World::trafficAfterCollide()
{
    if (m_traffic.heroAgent.empty() && m_traffic.signal.empty())
        return;
    const std::size_t n = m_agents.pos.size();
    m_team.forEach(n, 256, [&](std::size_t i) {
        if (m_agents.stopped[i] || m_types.params[m_agents.info[i].typeIndex].kind == AgentKind::Flier)
            return;
        glm::vec3 p = m_agents.nextPos[i];
        // Heroes are never pushed; a walker inside a hero's clearance steps out of it.
        bool moved = false;
        for (std::size_t h = 0; h < m_traffic.heroAgent.size(); ++h) {
            const std::size_t j = m_traffic.heroAgent[h];
            const HeroPush push = heroPush(xz(m_agents.nextPos[j]), xz(m_agents.nextVel[j]), m_traffic.heroes[h].clearanceM(),
                                           xz(p), m_agents.radius[i], m_agents.info[i].id);
            if (push.inside) {
                p.x += push.displacement.x;
                p.z += push.displacement.y;
                moved = true;
            }
        }
        if (moved)
            constrain(m_agents, m_set, m_clock.dt, i, m_agents.pos[i], p);
        // Crowd pushes and hero pushes may nudge a waiting walker, never past its stop point.
        holdAtSignal(i, p);
        keepOffRedCrosswalks(i, p);
        if (!moved && p == m_agents.nextPos[i])
            return;
        m_agents.nextPos[i] = p;
        m_agents.nextVel[i] = (p - m_agents.pos[i]) / m_clock.dt;
        m_agents.nextVel[i].y = 0.0f;
    });
}

void World::keepOffRedCrosswalks(std::size_t i, glm::vec3& p) const
{
    // A hard constraint like the walls: whoever is off a crosswalk's road part stays off it
    // while its light is red, however the crowd or a hero pushes (the signal answer already
    // stops those who walk up to the kerb; this catches a walker shoved over the kerb line,
    // or one that just left the road and is pushed back).
    if (!m_traffic.system)
        return;
    const LaneNetwork& net = m_traffic.system->lanes();
    // Red at either end of the step: the counters time a crossing within the step.
    const double t0 = double(m_clock.step) * double(m_clock.dt), t1 = double(m_clock.step + 1) * double(m_clock.dt);
    for (std::size_t c = 0; c < net.crosswalkCount(); ++c) {
        const CrosswalkStrip& s = net.crosswalk(int(c));
        if (s.light < 0 || (lightPhaseAt(m_set.lights[std::size_t(s.light)], t0) != LightPhase::Red &&
                            lightPhaseAt(m_set.lights[std::size_t(s.light)], t1) != LightPhase::Red))
            continue;
        if (!net.onRoadPart(int(c), xz(p)) || net.onRoadPart(int(c), xz(m_agents.pos[i])))
            continue;
        // Back over the kerb line it came from (roadU0 and roadU1 lie just off the carriageway).
        const float ub = glm::dot(xz(m_agents.pos[i]) - s.a, s.dir), ua = glm::dot(glm::vec2(p.x, p.z) - s.a, s.dir);
        const float back = ub < 0.5f * (s.roadU0 + s.roadU1) ? std::max(0.0f, ua - s.roadU0 + kEndLineMarginM)
                                                              : std::min(0.0f, ua - s.roadU1 - kEndLineMarginM);
        p.x -= s.dir.x * back;
        p.z -= s.dir.y * back;
    }
}

void World::trafficAfterStep()
{
    if (!m_traffic.system)
        return;
    for (std::size_t k = 0; k < m_traffic.pedestrians.size(); ++k) {
        const std::uint32_t i = m_traffic.pedestrians[k];
        m_traffic.after[k] = {xz(m_agents.pos[i]), xz(m_agents.vel[i]), m_agents.radius[i]};
    }
    m_traffic.system->observePedestrians(m_traffic.before, m_traffic.after);
}

}  // namespace throng::sim
