// World::describeAgent: the steering annotations of one agent for a DebugSink (the
// editor's debug overlays). Reads the state after the last step; steers as the general
// path does, with the sink listening, and keeps nothing.
#include "simcore/world/World.h"

#include "simcore/world/Sense.h"
#include "simcore/world/Steer.h"

#include "simcore/world/DebugSink.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace throng::sim {

namespace {

// The feelers of a body heading `h` (unit, x z): one ahead at full length, two to the
// sides at half length (WallAvoidance.cpp and ObstacleAvoidance.cpp draw them alike).
void publishFeelers(DebugSink& sink, glm::vec3 p, glm::vec2 h, float length, float sideAngleRad)
{
    if (!(length > 0.0f) || h == glm::vec2(0.0f))
        return;
    const glm::vec2 right(-h.y, h.x);
    const float c = std::cos(sideAngleRad), s = std::sin(sideAngleRad);
    const std::array<glm::vec2, 3> dirs{h, h * c + right * s, h * c - right * s};
    const std::array<float, 3> lengths{length, 0.5f * length, 0.5f * length};
    for (std::size_t k = 0; k < dirs.size(); ++k)
        sink.feeler(p, p + glm::vec3(dirs[k].x, 0.0f, dirs[k].y) * lengths[k]);
}

void publishField(const StepView& v, std::size_t i, DebugSink& sink)
{
    // Its goal's navigation flow field, where it walks by one, else the scene's flow
    // strokes, where its type follows them; sampled on a square about it.
    const std::int32_t goal = v.agents.goal[i];
    const FlowField* navField = nullptr;
    if (v.nav.active && i < v.nav.mode.size() && v.nav.mode[i] == Navigation::FlowField && goal >= 0 &&
        std::size_t(goal) < v.nav.hasField.size() && v.nav.hasField[std::size_t(goal)])
        navField = &v.nav.fields[std::size_t(goal)];
    const bool strokes =
        !v.set.flow.empty() && v.types.steering[v.agents.info[i].typeIndex].on(Behaviour::FlowFieldFollowing);
    if (!navField && !strokes)
        return;
    const float step = navField ? v.nav.grid.cellM() : kFlowSampleStepM;
    const glm::vec3 p = v.agents.pos[i];
    constexpr int kHalf = kFieldSamples / 2;
    for (int dz = -kHalf; dz <= kHalf; ++dz) {
        for (int dx = -kHalf; dx <= kHalf; ++dx) {
            const float x = p.x + float(dx) * step, z = p.z + float(dz) * step;
            const glm::vec3 at(x, v.set.groundHeight(x, z), z);
            glm::vec3 direction;
            if (navField) {
                const glm::vec2 d = navField->sample(glm::vec2(x, z));
                direction = glm::vec3(d.x, 0.0f, d.y);
            } else {
                direction = flowDirection(v, at);
            }
            sink.field(at, direction);
        }
    }
}

}  // namespace

void DebugRecorder::agent(AgentId id, glm::vec3 position, glm::vec3 forward, glm::vec3 velocity, float radiusM)
{
    AgentDebug& a = m_agents.emplace_back();
    a.id = id;
    a.position = position;
    a.forward = forward;
    a.velocity = velocity;
    a.radiusM = radiusM;
}

AgentDebug& DebugRecorder::current()
{
    if (m_agents.empty())
        m_agents.emplace_back();
    return m_agents.back();
}

void DebugRecorder::viewCone(float rangeM, float viewAngleRad)
{
    current().rangeM = rangeM;
    current().viewAngleRad = viewAngleRad;
}

void DebugRecorder::neighbour(AgentId other, glm::vec3 position) { current().neighbours.push_back({other, position}); }

void DebugRecorder::force(Behaviour behaviour, glm::vec3 force, float weight)
{
    current().forces.push_back({behaviour, force, weight});
}

void DebugRecorder::steering(glm::vec3 force) { current().steering = force; }

void DebugRecorder::feeler(glm::vec3 from, glm::vec3 to) { current().feelers.push_back({from, to}); }

void DebugRecorder::plannedPath(std::span<const glm::vec3> points)
{
    current().path.assign(points.begin(), points.end());
}

void DebugRecorder::target(glm::vec3 point)
{
    current().hasTarget = true;
    current().target = point;
}

void DebugRecorder::field(glm::vec3 at, glm::vec3 direction) { current().field.push_back({at, direction}); }

void World::describeAgent(std::size_t i, DebugSink& sink) const
{
    if (i >= m_agents.pos.size())
        return;
    const glm::vec3 p = m_agents.pos[i];
    sink.agent(m_agents.info[i].id, p, m_agents.fwd[i], m_agents.vel[i], m_agents.radius[i]);
    if (m_agents.out[i] != 0 || isDriven(i))
        return;  // gone, or moved by traffic or keyframes: nothing steers it
    const TypeParams& t = m_types.params[m_agents.info[i].typeIndex];
    const TypeSteering& s = m_types.steering[m_agents.info[i].typeIndex];
    sink.viewCone(t.perception, 2.0f * std::acos(std::clamp(t.cosHalfView, -1.0f, 1.0f)));

    // Whom it sensed at the last step, where they are now.
    std::array<Neighbour, kMaxNeighbours> near;
    const std::size_t count = std::min<std::size_t>(m_agents.nearCount[i], kMaxNeighbours);
    for (std::size_t k = 0; k < count; ++k) {
        const std::size_t j = m_agents.nearIndex[i * kMaxNeighbours + k];
        near[k] = {m_agents.pos[j], m_agents.vel[j], m_agents.fwd[j], m_agents.radius[j], m_agents.info[j].id};
        sink.neighbour(m_agents.info[j].id, m_agents.pos[j]);
    }

    const SteeringAgent self = steeringAgent(m_agents, m_types, i);
    const glm::vec2 h = glm::length(glm::vec2(m_agents.fwd[i].x, m_agents.fwd[i].z)) > 0.0f
                            ? glm::normalize(glm::vec2(m_agents.fwd[i].x, m_agents.fwd[i].z))
                            : glm::vec2(0.0f);
    const float speed = glm::length(m_agents.vel[i]);
    if (s.on(Behaviour::WallFollowing) && !m_set.walls.segments().empty())
        publishFeelers(sink, p, h, s.walls.feelerMinM + speed * s.walls.feelerLookaheadS, s.walls.sideFeelerAngleRad);
    if (s.on(Behaviour::ObstacleAvoidance) && (!m_set.circles.empty() || !m_set.boxes.empty()))
        publishFeelers(sink, p, h, s.obstacles.minLengthM + speed * s.obstacles.lookaheadS,
                       s.obstacles.whiskerAngleRad);

    WanderState wander;
    sink.steering(steer(view(), m_brains, i, self, {near.data(), count}, wander, &sink));

    // The way ahead: an A* walker's waypoints from the current one, or its path's points.
    std::vector<glm::vec3> way;
    if (m_nav.active && i < m_nav.plan.size() && m_nav.plan[i] && m_nav.plan[i]->found()) {
        const std::vector<glm::vec2>& points = m_nav.plan[i]->waypoints;
        way.push_back(p);
        for (std::size_t k = std::min<std::size_t>(m_nav.waypoint[i], points.size()); k < points.size(); ++k)
            way.emplace_back(points[k].x, m_set.groundHeight(points[k].x, points[k].y), points[k].y);
    } else if (m_agents.path[i] >= 0) {
        const std::vector<glm::vec3>& points = m_set.pathPoints[std::size_t(m_agents.path[i])];
        way.assign(points.begin(), points.end());
    }
    if (!way.empty())
        sink.plannedPath(way);
    if (m_agents.goal[i] >= 0) {
        const glm::vec2 spot = m_agents.goalSpot[i];
        sink.target(m_nav.goal(i, glm::vec3(spot.x, m_set.groundHeight(spot.x, spot.y), spot.y)));
    }
    publishField(view(), i, sink);
}

}  // namespace throng::sim
