#include "simcore/world/World.h"

#include "simcore/traffic/LightPhase.h"
#include "simcore/world/Rng.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <omp.h>

#include <algorithm>
#include <cmath>

namespace throng::sim {

namespace {

// Random streams: each use of randomness has its own, so adding one never shifts another.
enum Stream : std::uint64_t { kSpawnX = 1, kSpawnZ, kSpawnHeading, kSpeedFactor, kPhaseOffset, kStride };

constexpr float kDefaultSeparation = 1.0f;

float weightOf(const AgentType& t, const char* behaviour, float fallback)
{
    for (const BehaviourWeight& b : t.behaviours)
        if (b.behaviour == behaviour)
            return b.weight;
    return t.behaviours.empty() ? fallback : 0.0f;
}

// A follower joins its path where it stands: it heads for the end of the nearest segment
// rather than walking back to the first point.
int firstWaypoint(const Path& path, glm::vec2 p)
{
    int best = 0;
    float bestDist = 1e30f;
    const std::size_t segments = path.closed ? path.points.size() : path.points.size() - 1;
    for (std::size_t k = 0; k < segments; ++k) {
        const glm::vec2 a = path.points[k], b = path.points[(k + 1) % path.points.size()];
        const glm::vec2 ab = b - a;
        const float len2 = glm::dot(ab, ab);
        const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
        const float d = glm::distance(p, a + ab * t);
        if (d < bestDist) {
            bestDist = d;
            best = int((k + 1) % path.points.size());
        }
    }
    return best;
}

}  // namespace

World::World(const Scene& scene, const WorldOptions& options)
{
    m_seed = options.overrideSeed ? options.seed : scene.settings.seed;
    m_dt = 1.0f / scene.settings.fps;
    m_threads = options.threads > 0 ? options.threads : omp_get_max_threads();

    float maxPerception = 1.0f;
    for (const AgentType& t : scene.agentTypes) {
        m_types.push_back({t.radiusM, t.maxSpeed, t.maxForce, t.mass, t.perceptionM, t.kind,
                           weightOf(t, "separation", kDefaultSeparation)});
        maxPerception = std::max(maxPerception, std::min(t.perceptionM, 4.0f * t.radiusM + 1.0f));
    }
    std::vector<Segment> segments;
    for (const Wall& w : scene.walls)
        for (std::size_t k = 0; k + 1 < w.points.size(); ++k)
            segments.push_back({w.points[k], w.points[k + 1]});
    for (const Obstacle& o : scene.obstacles) {
        if (o.shape == ObstacleShape::Circle) {
            m_circles.push_back({o.center, o.radiusM});
            continue;
        }
        const float a = glm::radians(o.angleDeg);
        const glm::vec2 ax(std::cos(a), -std::sin(a)), az(std::sin(a), std::cos(a));
        const glm::vec2 h = o.size * 0.5f;
        const glm::vec2 c[4] = {o.center - ax * h.x - az * h.y, o.center + ax * h.x - az * h.y,
                                o.center + ax * h.x + az * h.y, o.center - ax * h.x + az * h.y};
        for (int k = 0; k < 4; ++k)
            segments.push_back({c[k], c[(k + 1) % 4]});
    }
    m_walls.build(segments, 4.0f);
    m_goals = scene.goals;
    m_paths = scene.paths;
    m_lights = scene.trafficLights;
    for (const Crosswalk& c : scene.crosswalks) {
        int light = -1;
        for (std::size_t l = 0; l < scene.trafficLights.size(); ++l)
            for (const StopLine& s : scene.trafficLights[l].stopLines)
                if (s.crosswalk == c.name)
                    light = int(l);
        m_crosswalks.push_back({c.from, c.to, c.widthM * 0.5f, light});
    }
    buildAgents(scene);
    m_grid.configure(scene.settings.boundsMin, scene.settings.boundsMax, maxPerception);
    m_grid.rebuild(m_pos);
}

void World::buildAgents(const Scene& scene)
{
    auto typeIndex = [&](const std::string& name) {
        for (std::size_t t = 0; t < scene.agentTypes.size(); ++t)
            if (scene.agentTypes[t].name == name)
                return std::uint16_t(t);
        return std::uint16_t(0);
    };
    auto indexOf = [](const auto& items, const std::string& name) {
        for (std::size_t k = 0; k < items.size(); ++k)
            if (items[k].name == name)
                return int(k);
        return -1;
    };
    std::size_t total = scene.agents.size();
    for (const SpawnGroup& g : scene.groups)
        total += g.count;
    m_info.reserve(total);

    for (const Agent& a : scene.agents)
        addAgent(scene, a.id, typeIndex(a.type), a.position, glm::radians(a.headingDeg), indexOf(scene.goals, a.goal),
                 indexOf(scene.paths, a.path));
    for (std::size_t g = 0; g < scene.groups.size(); ++g)
        spawnGroup(scene, scene.groups[g], g);
}

void World::spawnGroup(const Scene& scene, const SpawnGroup& group, std::size_t groupIndex)
{
    AgentId next = 1;
    for (const Agent& a : scene.agents) next = std::max(next, a.id + 1);
    for (const Vehicle& v : scene.vehicles) next = std::max(next, v.id + 1);
    for (const Hero& h : scene.heroes) next = std::max(next, h.id + 1);
    for (const AgentInfo& info : m_info) next = std::max(next, info.id + 1);

    std::uint16_t type = 0;
    for (std::size_t t = 0; t < scene.agentTypes.size(); ++t)
        if (scene.agentTypes[t].name == group.type)
            type = std::uint16_t(t);
    int goal = -1, path = -1;
    for (std::size_t k = 0; k < scene.goals.size(); ++k)
        if (scene.goals[k].name == group.goal) goal = int(k);
    for (std::size_t k = 0; k < scene.paths.size(); ++k)
        if (scene.paths[k].name == group.path) path = int(k);

    // Keys are (group, member), not the running id, so editing one group never moves
    // the members of another.
    for (std::uint32_t k = 0; k < group.count; ++k) {
        const std::uint64_t key = (std::uint64_t(groupIndex + 1) << 32) | k;
        const float u = rngUniform(m_seed, key, 0, kSpawnX), v = rngUniform(m_seed, key, 0, kSpawnZ);
        glm::vec2 p;
        if (group.shape == AreaShape::Rect) {
            p = group.min + (group.max - group.min) * glm::vec2(u, v);
        } else {
            const float r = group.radiusM * std::sqrt(u), a = 6.28318531f * v;
            p = group.center + r * glm::vec2(std::cos(a), std::sin(a));
        }
        float heading = 6.28318531f * rngUniform(m_seed, key, 0, kSpawnHeading);
        if (goal >= 0) {
            const glm::vec2 d = scene.goals[std::size_t(goal)].position - p;
            if (glm::dot(d, d) > 1e-6f)
                heading = std::atan2(-d.y, d.x);
        }
        addAgent(scene, next++, type, glm::vec3(p.x, 0.0f, p.y), heading, goal, path);
    }
}

void World::addAgent(const Scene& scene, AgentId id, std::uint16_t type, glm::vec3 pos, float headingRad, int goal,
                     int path)
{
    const AgentType& t = scene.agentTypes[type];
    m_info.push_back({id, type});
    m_pos.push_back(pos);
    m_vel.push_back(glm::vec3(0.0f));
    // Heading is counter-clockwise seen from above (+y up, z south): forward = (cos, 0, -sin).
    m_fwd.push_back(glm::vec3(std::cos(headingRad), 0.0f, -std::sin(headingRad)));
    m_radius.push_back(t.radiusM);
    m_speedFactor.push_back(rngRange(m_seed, id, 0, kSpeedFactor, t.variation.speedFactor.x, t.variation.speedFactor.y));
    m_phase.push_back(rngRange(m_seed, id, 0, kPhaseOffset, t.variation.phaseOffset.x, t.variation.phaseOffset.y));
    // Stride length scales with body size; 1.4 m is an adult's walking stride.
    m_stride.push_back(t.kind == AgentKind::Pedestrian ? 1.4f * std::max(0.5f, t.radiusM / 0.3f) *
                                                             rngRange(m_seed, id, 0, kStride, 0.95f, 1.05f)
                                                       : 2.0f * t.radiusM * 3.14159265f);
    m_goal.push_back(goal);
    m_path.push_back(path);
    m_waypoint.push_back(path >= 0 ? firstWaypoint(scene.paths[std::size_t(path)], glm::vec2(pos.x, pos.z)) : 0);
    m_arrived.push_back(0);
    m_onCrosswalk.push_back(0);
    m_nextPos.push_back(pos);
    m_nextVel.push_back(glm::vec3(0.0f));
}

std::size_t World::agentsWithGoal() const
{
    std::size_t count = 0;
    for (std::size_t i = 0; i < m_pos.size(); ++i)
        if ((m_path[i] >= 0 && !m_paths[std::size_t(m_path[i])].closed) || (m_path[i] < 0 && m_goal[i] >= 0))
            ++count;
    return count;
}

int World::lightState(std::size_t light) const
{
    return int(lightPhaseAt(m_lights[light], timeS()));
}

void World::snapshot(std::vector<AgentFrame>& out) const
{
    out.resize(m_pos.size());
    for (std::size_t i = 0; i < m_pos.size(); ++i) {
        const float speed = glm::length(m_vel[i]);
        AgentFrame& f = out[i];
        f.position = m_pos[i];
        f.headingRad = std::atan2(-m_fwd[i].z, m_fwd[i].x);
        f.speed = speed;
        f.phase = m_phase[i];
        // Clip thresholds relative to a walker: below 0.1 m/s stand, above 2.5 m/s run.
        f.clip = speed < 0.1f ? Clip::Idle : (speed < 2.5f ? Clip::Walk : Clip::Run);
    }
}

void World::startRecording(FrameCache& cache) const
{
    cache.reset(m_info, 1.0f / m_dt);
    std::vector<AgentFrame> frame;
    snapshot(frame);
    cache.append(frame);
}

}  // namespace throng::sim
