// The traffic phase (WorldTraffic.h): vehicles driven by the TrafficSystem and heroes by
// their keyframes are agents that others perceive and steer round but never push; walkers
// obey the crosswalk signals and keep off the carriageway (kerbs are walls). The call
// order is the one TrafficSystem.h gives; every per-agent loop writes only its own agent.
#include "simcore/world/WorldTraffic.h"

#include "simcore/world/Constraints.h"
#include "simcore/world/Sense.h"
#include "simcore/world/StepView.h"

#include "simcore/steering/TargetBehaviours.h"
#include "simcore/traffic/LightPhase.h"
#include "simcore/traffic/WalkerBarriers.h"
#include "simcore/world/detail/StepGeometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::sim {

using namespace detail;

namespace {
constexpr float kEndLineMarginM = 1e-3f;    // m: how far behind a crosswalk's kerb line a held walker stays

glm::vec3 onGround(glm::vec2 p, float y) { return {p.x, y, p.y}; }
}  // namespace

void WorldTraffic::build(const Scene& scene, std::uint64_t seed, int threads)
{
    if (!scene.lanes.empty() || !scene.vehicles.empty()) {
        TrafficOptions options;
        options.seed = seed;
        options.overrideSeed = true;
        options.threads = threads;
        system.emplace(scene, options);
    }
    for (const Hero& h : scene.heroes)
        if (!h.keyframes.empty())
            heroes.emplace_back(h);
    for (const Lane& l : scene.lanes)
        laneNames.push_back(l.name);
    for (const Crosswalk& c : scene.crosswalks)
        crosswalkNames.push_back(c.name);
    for (const TrafficLight& l : scene.trafficLights)
        lightNames.push_back(l.name);
}

void WorldTraffic::appendKerbs(std::vector<Segment>& walls) const
{
    if (!system)
        return;
    for (const BarrierSegment& b : walkerBarriers(system->lanes()))
        walls.push_back({b.a, b.b});
}

void WorldTraffic::markAgents(const AgentColumns& agents, const AgentTypes& types, std::size_t firstDriven)
{
    const std::size_t n = agents.pos.size();
    driven.assign(n, 0);
    offStage.assign(n, 0);
    for (std::size_t i = firstDriven; i < n; ++i)
        driven[i] = 1;
    for (std::size_t i = 0; i < firstDriven; ++i)
        if (types.params[agents.info[i].typeIndex].kind == AgentKind::Pedestrian)
            pedestrians.push_back(std::uint32_t(i));
    for (std::uint32_t h : heroAgent)
        pedestrians.push_back(h);
    before.resize(pedestrians.size());
    after.resize(pedestrians.size());
    signal.assign(system ? n : 0, PedestrianSignal{});
}

void WorldTraffic::beforeStep(const AgentColumns& agents)
{
    if (!system)
        return;
    for (std::size_t k = 0; k < pedestrians.size(); ++k) {
        const std::uint32_t i = pedestrians[k];
        before[k] = {xz(agents.pos[i]), xz(agents.vel[i]), agents.radius[i]};
    }
    system->step(before);
}

glm::vec3 WorldTraffic::obeySignal(const StepView& v, std::size_t i, const SteeringAgent& self, glm::vec3 force)
{
    if (signal.empty() || v.types.params[v.agents.info[i].typeIndex].kind != AgentKind::Pedestrian)
        return force;
    PedestrianSignal& sig = signal[i];
    sig = system->pedestrianSignal(xz(v.agents.pos[i]), wantedHeading(v, i), glm::length(xz(v.agents.vel[i])),
                                   v.agents.radius[i], v.agents.info[i].id);
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

void WorldTraffic::holdAtSignal(std::size_t i, glm::vec3& p) const
{
    if (signal.empty())
        return;
    const glm::vec2 q = holdBehindStopLine(signal[i], xz(p));
    p.x = q.x;
    p.z = q.y;
}

void WorldTraffic::drive(const StepClock& clock, const StaticSet& set, AgentColumns& agents)
{
    if (system) {
        const TrafficSystem& ts = *system;
        anyOffStage = false;
        for (std::size_t v = 0; v < vehicleAgent.size(); ++v) {
            const std::size_t i = vehicleAgent[v];
            const glm::vec2 p = ts.position(v), f = ts.forward(v);
            offStage[i] = ts.active(v) ? 0 : 1;
            anyOffStage = anyOffStage || !ts.active(v);
            agents.nextPos[i] = onGround(p, set.groundHeight(p.x, p.y));
            agents.nextVel[i] = glm::vec3(f.x, 0.0f, f.y) * (ts.active(v) ? ts.speed(v) : 0.0f);
            agents.nextFwd[i] = glm::vec3(f.x, 0.0f, f.y);
            agents.nextSide[i] = glm::vec3(-f.y, 0.0f, f.x);
        }
    }
    const double t1 = double(clock.step + 1) * double(clock.dt);
    for (std::size_t h = 0; h < heroAgent.size(); ++h) {
        const std::size_t i = heroAgent[h];
        const HeroTrack& track = heroes[h];
        const glm::vec2 f = track.forwardAt(t1);
        agents.nextPos[i] = track.positionAt(t1);
        agents.nextVel[i] = track.velocityAt(t1);
        agents.nextFwd[i] = glm::vec3(f.x, 0.0f, f.y);
        agents.nextSide[i] = glm::vec3(-f.y, 0.0f, f.x);
    }
}

void WorldTraffic::afterCollide(const StepView& v, AgentColumns& agents)
{
    if (heroAgent.empty() && signal.empty())
        return;
    const std::size_t n = agents.pos.size();
    v.team.forEach(n, 256, [&](std::size_t i) {
        if (agents.stopped[i] || v.types.params[agents.info[i].typeIndex].kind == AgentKind::Flier)
            return;
        glm::vec3 p = agents.nextPos[i];
        // Heroes are never pushed; a walker inside a hero's clearance steps out of it.
        bool moved = false;
        for (std::size_t h = 0; h < heroAgent.size(); ++h) {
            const std::size_t j = heroAgent[h];
            const HeroPush push = heroPush(xz(agents.nextPos[j]), xz(agents.nextVel[j]), heroes[h].clearanceM(),
                                           xz(p), agents.radius[i], agents.info[i].id);
            if (push.inside) {
                p.x += push.displacement.x;
                p.z += push.displacement.y;
                moved = true;
            }
        }
        if (moved)
            constrain(agents, v.set, v.clock.dt, i, agents.pos[i], p);
        // Crowd pushes and hero pushes may nudge a waiting walker, never past its stop point.
        holdAtSignal(i, p);
        keepOffRedCrosswalks(v, i, p);
        if (!moved && p == agents.nextPos[i])
            return;
        agents.nextPos[i] = p;
        agents.nextVel[i] = (p - agents.pos[i]) / v.clock.dt;
        agents.nextVel[i].y = 0.0f;
    });
}

void WorldTraffic::keepOffRedCrosswalks(const StepView& v, std::size_t i, glm::vec3& p) const
{
    // A hard constraint like the walls: whoever is off a crosswalk's road part stays off it
    // while its light is red, however the crowd or a hero pushes (the signal answer already
    // stops those who walk up to the kerb; this catches a walker shoved over the kerb line,
    // or one that just left the road and is pushed back).
    if (!system)
        return;
    const LaneNetwork& net = system->lanes();
    // Red at either end of the step: the counters time a crossing within the step.
    const double t0 = double(v.clock.step) * double(v.clock.dt), t1 = double(v.clock.step + 1) * double(v.clock.dt);
    for (std::size_t c = 0; c < net.crosswalkCount(); ++c) {
        const CrosswalkStrip& s = net.crosswalk(int(c));
        if (s.light < 0 || (lightPhaseAt(v.set.lights[std::size_t(s.light)], t0) != LightPhase::Red &&
                            lightPhaseAt(v.set.lights[std::size_t(s.light)], t1) != LightPhase::Red))
            continue;
        if (!net.onRoadPart(int(c), xz(p)) || net.onRoadPart(int(c), xz(v.agents.pos[i])))
            continue;
        // Back over the kerb line it came from (roadU0 and roadU1 lie just off the carriageway).
        const float ub = glm::dot(xz(v.agents.pos[i]) - s.a, s.dir), ua = glm::dot(glm::vec2(p.x, p.z) - s.a, s.dir);
        const float back = ub < 0.5f * (s.roadU0 + s.roadU1) ? std::max(0.0f, ua - s.roadU0 + kEndLineMarginM)
                                                              : std::min(0.0f, ua - s.roadU1 - kEndLineMarginM);
        p.x -= s.dir.x * back;
        p.z -= s.dir.y * back;
    }
}

void WorldTraffic::afterStep(const AgentColumns& agents)
{
    if (!system)
        return;
    for (std::size_t k = 0; k < pedestrians.size(); ++k) {
        const std::uint32_t i = pedestrians[k];
        after[k] = {xz(agents.pos[i]), xz(agents.vel[i]), agents.radius[i]};
    }
    system->observePedestrians(before, after);
}

}  // namespace throng::sim
