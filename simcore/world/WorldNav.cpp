// The navigation phase of World::step: walkers whose type navigates by A* follow a plan
// shared through the PlanCache (advancing within their own waypoint radius), flow-field
// walkers follow their goal's field, and a walker that makes no progress re-plans around
// the blockage or side-steps. Plans are made serially in agent order, targets in parallel
// from each agent's own state, so the result does not depend on the thread count.
#include "simcore/world/World.h"

#include "simcore/world/Sense.h"

#include "simcore/nav/NavDefaults.h"
#include "simcore/traffic/LightPhase.h"
#include "simcore/base/Rng.h"
#include "simcore/world/detail/StepGeometry.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace throng::sim {

using namespace detail;

namespace {

// From a blocked cell c: of its eight neighbours that are walkable, reach the goal and
// are in sight (no wall between), the one nearest the goal along the field; with none,
// the nearest walkable cell.
template <typename InSight>
NavCell onwardOrNearestWalkable(const FlowField& field, NavCell c, InSight&& inSight)
{
    const NavGrid& grid = field.grid();
    NavCell best = c;
    float bestM = INFINITY;
    for (int dz = -1; dz <= 1; ++dz)
        for (int dx = -1; dx <= 1; ++dx) {
            const NavCell n{c.x + dx, c.z + dz};
            if ((dx == 0 && dz == 0) || !grid.walkable(n) || !field.reachable(n) || !inSight(grid.centre(n)))
                continue;
            if (const float m = field.distanceM(n); m < bestM) {
                bestM = m;
                best = n;
            }
        }
    return bestM < INFINITY ? best : grid.nearestWalkable(c);
}

enum NavStream : std::uint64_t { kWaypointRadius = 201, kSideStepSign };

constexpr float kWaypointRadiusBaseM = 1.0f;  // a walker advances within 0.5..1.5 m of a corner
constexpr float kWaypointSpread = 0.5f;
constexpr float kAvoidRadiusM = 1.0f;         // a stalled walker's detour avoids this disk ahead of it
constexpr float kSideStepDurationS = 1.5f;
constexpr float kQueueGapM = 0.5f;           // m: a walker this close behind a waiting one queues
constexpr float kCornerReachedM = 0.35f;      // this close to a corner, a walker turns even without a clear view
constexpr std::uint8_t kMaxQueueDepth = 24;   // walkers in one queue; past it a "queue" with no head is none
constexpr float kDensityRadiusM = 1.2f;       // m: the half disk ahead a walker reads the density in
constexpr float kMinCrowdSpeedFraction = 0.1f;// a jammed walker still edges on
constexpr std::uint8_t kLostSteps = 12;       // steps with the waypoint out of sight before planning afresh

}  // namespace

void World::buildNav(const Scene& scene)
{
    const std::size_t n = m_agents.pos.size();
    m_agents.out.assign(n, 0);
    float inflate = 0.0f, smallest = INFINITY;
    std::vector<Navigation> mode(n, Navigation::Direct);
    for (std::size_t i = 0; i < n; ++i) {
        const AgentType& t = scene.agentTypes[m_agents.info[i].typeIndex];
        if (t.kind != AgentKind::Pedestrian || m_traffic.isDriven(i) || t.navigation == Navigation::Direct)
            continue;
        mode[i] = t.navigation;
        inflate = std::max(inflate, t.radiusM + kNavClearanceM);
        smallest = std::min(smallest, t.radiusM);
    }
    m_nav.active = inflate > 0.0f;
    if (!m_nav.active && scene.flowStrokes.empty())
        return;
    // The set as walkers meet it: walls, obstacles and the kerbs along lanes (m_set.walls holds
    // all three), so a plan never leads onto a lane except over a crosswalk.
    NavShapes shapes = navShapes(scene);
    shapes.walls = m_set.walls.segments();
    m_nav.grid.build(shapes, scene.settings.boundsMin, scene.settings.boundsMax,
                     NavGridParams{scene.settings.navCellM, m_nav.active ? inflate : kNavDefaultRadiusM + kNavClearanceM});
    // Flow strokes become a sketched field (Jin et al. 2008) that flow_field_following
    // reads; should the solve fail, the World keeps the plain lookup along the strokes.
    if (!scene.flowStrokes.empty()) {
        SketchField sketch;
        if (sketch.build(scene, m_nav.grid))
            m_nav.sketch = std::move(sketch);
    }
    if (!m_nav.active)
        return;
    m_nav.reachShapes = std::move(shapes);
    m_nav.reachRadiusM = smallest;

    m_nav.hasField.assign(m_set.goals.size(), 0);
    m_nav.fields.resize(m_set.goals.size());
    for (std::size_t i = 0; i < n; ++i)
        if (mode[i] == Navigation::FlowField && m_agents.goal[i] >= 0)
            m_nav.hasField[std::size_t(m_agents.goal[i])] = 1;
    for (std::size_t g = 0; g < m_set.goals.size(); ++g)
        if (m_nav.hasField[g]) {
            const FlowGoal goal{m_set.goals[g].position, m_set.goals[g].radiusM};
            m_nav.fields[g].build(m_nav.grid, std::span<const FlowGoal>(&goal, 1));
        }

    m_nav.mode = std::move(mode);
    m_nav.plan.assign(n, nullptr);
    m_nav.planGoal.assign(n, -1);
    m_nav.waypoint.assign(n, 0);
    m_nav.waypointRadiusM.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        m_nav.waypointRadiusM[i] = waypointRadiusM(kWaypointRadiusBaseM, rngUniform(m_seed, m_agents.info[i].id, 0, kWaypointRadius),
                                                   kWaypointSpread);
    m_nav.stall.assign(n, StallWatch{});
    m_nav.replan.assign(n, 0);
    m_nav.sideStepS.assign(n, 0.0f);
    m_nav.sideDir.assign(n, glm::vec2(0.0f));
    m_nav.target.assign(n, glm::vec2(0.0f));
    m_nav.hasTarget.assign(n, 0);
    m_nav.waiting.assign(n, 0);
    m_nav.waitingNext.assign(n, 0);
    m_nav.lostSteps.assign(n, 0);
    m_nav.noWay.assign(n, 0);
    // Plans at load, in agent order: a group starting in one cell shares one plan.
    for (std::size_t i = 0; i < n; ++i)
        if (m_nav.mode[i] == Navigation::AStar && m_agents.goal[i] >= 0 && m_agents.path[i] < 0)
            planNav(i);
    // Flow-field walkers where the field does not reach: is there a way at all?
    for (std::size_t i = 0; i < n; ++i)
        if (m_nav.mode[i] == Navigation::FlowField && m_agents.goal[i] >= 0 && m_agents.path[i] < 0) {
            const FlowField& field = m_nav.fields[std::size_t(m_agents.goal[i])];
            const NavCell c = field.grid().nearestWalkable(field.grid().cellOf(navStart(i)));
            if (!field.grid().walkable(c) || !field.reachable(c))
                m_nav.noWay[i] = noWayToGoal(i) ? 1 : 0;
        }
}

glm::vec2 World::navStart(std::size_t i) const
{
    // One that started inside a wall or obstacle walks out first (WorldEscape.cpp).
    return m_agents.escaping[i] ? m_agents.escapeTo[i] : xz(m_agents.pos[i]);
}

bool World::noWayToGoal(std::size_t i)
{
    if (!m_nav.reach.built()) {
        const NavGrid& g = m_nav.grid;
        const glm::vec2 lo = g.origin(), hi = lo + glm::vec2(float(g.cols()), float(g.rows())) * g.cellM();
        m_nav.reach.build(m_nav.reachShapes, lo, hi, m_nav.reachRadiusM,
                          NavReach::cellFor(lo, hi, std::min(0.5f * g.cellM(), 0.1f)));
    }
    // Only a walker found in a region that does not meet the goal waits; one pushed where
    // the grid cannot place it (deep in a wall's margin) goes on as before.
    const Goal& g = m_set.goals[std::size_t(m_agents.goal[i])];
    return m_nav.reach.regionAt(navStart(i)) >= 0 && !m_nav.reach.reaches(navStart(i), g.position, g.radiusM);
}

void World::planNav(std::size_t i)
{
    const Goal& g = m_set.goals[std::size_t(m_agents.goal[i])];
    m_nav.plan[i] = planBetween(m_nav.cache, m_nav.grid, navStart(i), g.position, m_nav.astar);
    m_nav.planGoal[i] = m_agents.goal[i];
    m_nav.noWay[i] = m_nav.plan[i] && m_nav.plan[i]->found() ? 0 : noWayToGoal(i) ? 1 : 0;
    m_nav.waypoint[i] = 0;
    m_nav.stall[i] = StallWatch{};
}

void World::navBeforeStep()
{
    if (!m_nav.active)
        return;
    const std::size_t n = m_agents.pos.size();
    // Plan: serially and in agent order, so what the cache holds never depends on threads.
    for (std::size_t i = 0; i < n; ++i) {
        if (m_nav.mode[i] != Navigation::AStar || m_agents.stopped[i] || m_agents.goal[i] < 0 || m_agents.path[i] >= 0)
            continue;
        const NavPlan* plan = m_nav.plan[i].get();
        if (!plan || m_nav.planGoal[i] != m_agents.goal[i]) {
            planNav(i);
        } else if (PlanCache::stale(*plan, m_nav.grid)) {
            ++m_nav.counters.stalePlans;
            planNav(i);
        } else if (m_nav.lostSteps[i] >= kLostSteps) {
            // Pushed off its way (the crowd at a crossing, a side-step) until a wall or a
            // kerb stands between the walker and its corner: plan again from where it is.
            m_nav.lostSteps[i] = 0;
            m_nav.replan[i] = 0;
            ++m_nav.counters.lostPlans;
            planNav(i);
        } else if (m_nav.replan[i]) {
            // Stalled: plan around the spot just ahead (the jam or what it keeps pushing
            // against); with no way round, step aside for a moment instead.
            m_nav.replan[i] = 0;
            const glm::vec2 p = xz(m_agents.pos[i]);
            glm::vec2 way = m_nav.hasTarget[i] ? m_nav.target[i] - p : m_agents.goalSpot[i] - p;
            way = glm::dot(way, way) > 1e-8f ? glm::normalize(way) : xz(m_agents.fwd[i]);
            const NavGrid& grid = m_nav.grid;
            const NavCell start = grid.nearestWalkable(grid.cellOf(p));
            const NavCell goal = grid.nearestWalkable(grid.cellOf(m_set.goals[std::size_t(m_agents.goal[i])].position));
            NavPlan detour = planAround(m_nav.astar, grid, start, goal, p + way * (m_agents.radius[i] + kAvoidRadiusM),
                                        kAvoidRadiusM);
            // Progress is measured along the new way from here on (a detour is longer).
            m_nav.stall[i] = StallWatch{};
            if (detour.found()) {
                m_nav.plan[i] = std::make_shared<const NavPlan>(std::move(detour));
                m_nav.waypoint[i] = 0;
                ++m_nav.counters.replans;
            } else {
                const float sign = rngUniform(m_seed, m_agents.info[i].id, m_clock.step, kSideStepSign) < 0.5f ? -1.0f : 1.0f;
                m_nav.sideDir[i] = glm::vec2(-way.y, way.x) * sign;
                m_nav.sideStepS[i] = kSideStepDurationS;
                ++m_nav.counters.sideSteps;
            }
        }
    }
    // Target: each walker from its own state.
    m_team.forEach(n, 256, [&](std::size_t i) {
        m_nav.waitingNext[i] = queueDepth(i);
        updateNavTarget(i);
    });
    m_nav.waiting.swap(m_nav.waitingNext);
}

std::uint8_t World::queueDepth(std::size_t i) const
{
    if (m_agents.stopped[i] || m_traffic.signal.empty() || m_types.params[m_agents.info[i].typeIndex].kind != AgentKind::Pedestrian)
        return 0;
    const PedestrianSignal& sig = m_traffic.signal[i];
    if (sig.crosswalk >= 0 && !sig.onCrosswalk && (sig.mustStop || sig.phase != LightPhase::Green))
        return 1;
    // Right behind a waiting walker, in the way it wants to go: the queue waits too, one
    // place further back. Neighbours and depths are the last step's, so the order agents
    // are visited in does not matter. Two walkers facing each other would otherwise keep
    // each other "waiting" for ever (and never re-plan): without a head held at a light,
    // such a ring's depth grows by one a step until it passes the cap and dissolves.
    const glm::vec2 p = xz(m_agents.pos[i]), way = wantedHeading(view(), i);
    const std::uint32_t* near = &m_agents.nearIndex[i * kMaxNeighbours];
    std::uint8_t ahead = kMaxQueueDepth;
    for (std::size_t k = 0; k < m_agents.nearCount[i]; ++k) {
        const std::uint32_t j = near[k];
        const glm::vec2 d = xz(m_agents.pos[j]) - p;
        if (m_nav.waiting[j] && glm::length(d) < m_agents.radius[i] + m_agents.radius[j] + kQueueGapM && glm::dot(d, way) > 0.0f)
            ahead = std::min(ahead, m_nav.waiting[j]);
    }
    return ahead < kMaxQueueDepth ? std::uint8_t(ahead + 1) : 0;
}

void World::updateNavTarget(std::size_t i)
{
    m_nav.hasTarget[i] = 0;
    const Navigation mode = m_nav.mode[i];
    if (mode == Navigation::Direct || m_agents.stopped[i] || m_agents.goal[i] < 0 || m_agents.path[i] >= 0)
        return;
    const glm::vec2 p = xz(m_agents.pos[i]);
    // The target lies beyond the arrival's slowing distance, so a walker keeps its pace
    // through corners and down the field and slows only for its own spot in the goal.
    const float carrot = m_types.steering[m_agents.info[i].typeIndex].arrival.slowingDistanceM + 0.5f;
    auto aim = [&](glm::vec2 dir, float distance) {
        m_nav.target[i] = p + dir * std::max(distance, carrot);
        m_nav.hasTarget[i] = 1;
    };
    if (m_nav.sideStepS[i] > 0.0f) {
        m_nav.sideStepS[i] -= m_clock.dt;
        aim(m_nav.sideDir[i], 0.0f);
        return;
    }
    const std::size_t goal = std::size_t(m_agents.goal[i]);
    float remainingM = glm::distance(p, m_agents.goalSpot[i]);
    // No way to the goal (walls close it off, or its door is narrower than the body): the
    // walker waits where it stands. Heading straight at the goal instead, it pressed against
    // the set, stalled, side-stepped and tried again for the whole shot (issue 23). A plan
    // made on a changed grid is stale and made again, so a door that opens lets it go.
    auto wait = [&] {
        m_nav.target[i] = p;
        m_nav.hasTarget[i] = 1;
        m_nav.stall[i] = StallWatch{};
    };
    if (mode == Navigation::AStar) {
        const NavPlan* plan = m_nav.plan[i].get();
        if (m_nav.noWay[i] && m_nav.planGoal[i] == m_agents.goal[i])
            return wait();
        if (plan && plan->found() && m_nav.planGoal[i] == m_agents.goal[i]) {
            const std::vector<glm::vec2>& w = plan->waypoints;
            // Within its own radius of a corner the walker turns for the next one, but only
            // once it can see it: cutting a corner short must not lead into a wall's end.
            std::size_t k = m_nav.waypoint[i];
            while (k + 1 < w.size()) {
                const std::size_t next = advanceWaypoint(w, k, p, m_nav.waypointRadiusM[i]);
                if (next == k || (glm::distance(p, w[k]) > kCornerReachedM && !lineOfSight(m_nav.grid, p, w[k + 1])))
                    break;
                ++k;
            }
            m_nav.waypoint[i] = std::uint32_t(k);
            // Seen from the nearest walkable cell: a walker brushing a wall stands in its
            // inflated margin, from where nothing is in sight.
            const NavGrid& grid = m_nav.grid;
            const NavCell at = grid.cellOf(p);
            const glm::vec2 eye = grid.walkable(at) ? p : grid.centre(grid.nearestWalkable(at));
            const bool inSight = glm::distance(p, w[k]) <= kCornerReachedM || lineOfSight(grid, eye, w[k]);
            m_nav.lostSteps[i] = inSight ? 0 : std::uint8_t(std::min<int>(m_nav.lostSteps[i] + 1, kLostSteps));
            // The last waypoint is the goal cell's centre: from there on the walker heads
            // for its own spot, as a direct walker does.
            if (k + 1 < w.size()) {
                const glm::vec2 d = w[k] - p;
                const float len = glm::length(d);
                remainingM = len + glm::distance(w.back(), m_agents.goalSpot[i]);
                for (std::size_t j = k; j + 1 < w.size(); ++j)
                    remainingM += glm::distance(w[j], w[j + 1]);
                if (len > 1e-4f)
                    aim(d / len, len);
            }
        }
    } else if (goal < m_nav.hasField.size() && m_nav.hasField[goal]) {
        const FlowField& field = m_nav.fields[goal];
        const NavGrid& grid = field.grid();
        const NavCell c = grid.cellOf(p);
        if (field.reachable(c)) {
            remainingM = field.distanceM(c);
            const glm::vec2 dir = field.sample(p);
            if (glm::dot(dir, dir) > 0.0f) {
                // The fundamental diagram: in a crowd a walker goes no faster than the
                // density ahead allows, so a door's queue packs no tighter than people do.
                // Arrival sets the speed from the target's distance, so the target comes
                // as close as that speed asks.
                const float slowing = m_types.steering[m_agents.info[i].typeIndex].arrival.slowingDistanceM;
                const float fraction = crowdSpeedFraction(i, dir);
                if (fraction < 1.0f && slowing > 0.0f) {
                    m_nav.target[i] = p + dir * (slowing * fraction);
                    m_nav.hasTarget[i] = 1;
                } else {
                    aim(dir, 0.0f);
                }
            }
        } else if (const NavCell free = onwardOrNearestWalkable(field, c, [&](glm::vec2 q) {
                       bool crossed = false;
                       m_set.walls.forEachNear((p + q) * 0.5f, 0.5f * glm::distance(p, q) + 0.01f, [&](std::uint32_t k) {
                           const Segment& w = m_set.walls.segment(k);
                           crossed = crossed || segmentsCross(p, q, w.a, w.b);
                       });
                       return !crossed;
                   });
                   grid.walkable(free) && field.reachable(free)) {
            // Squeezed into a wall's margin (a blocked cell has no direction): into the
            // walkable cell next to it that is nearest the goal, where the field takes over
            // again. (Back into the nearest walkable cell instead, a walker that cut the
            // corner of a pillar's margin on the field's diagonal was sent back where it
            // came from, and stood on that cell's edge for good: the last of 20,000 in the
            // evacuation demo, issue 23.)
            const glm::vec2 d = grid.centre(free) - p;
            const float len = glm::length(d);
            remainingM = field.distanceM(free) + len;
            if (len > 1e-4f)
                aim(d / len, 0.0f);
        } else if (m_nav.noWay[i]) {
            return wait();
        }
    }
    // Stall watch: waiting at a light is not being stuck. A flow-field walker in a queue
    // is not stuck either (the field already leads round the set), so only A* walkers act.
    if (m_nav.waitingNext[i])
        m_nav.stall[i] = StallWatch{};
    else if (updateStall(m_nav.stall[i], remainingM, m_clock.dt) && mode == Navigation::AStar)
        m_nav.replan[i] = 1;
}

float World::crowdSpeedFraction(std::size_t i, glm::vec2 way) const
{
    // Weidmann (1993): v(rho) = v0 (1 - exp(-1.913 (1/rho - 1/5.4))), rho in persons/m^2,
    // from the walkers in the half disk ahead (last step's neighbours: thread-independent).
    const glm::vec2 p = xz(m_agents.pos[i]);
    const std::uint32_t* near = &m_agents.nearIndex[i * kMaxNeighbours];
    int ahead = 0;
    for (std::size_t k = 0; k < m_agents.nearCount[i]; ++k) {
        const glm::vec2 d = xz(m_agents.pos[near[k]]) - p;
        ahead += glm::dot(d, d) < kDensityRadiusM * kDensityRadiusM && glm::dot(d, way) > 0.0f ? 1 : 0;
    }
    const float rho = float(ahead) / (0.5f * 3.14159265f * kDensityRadiusM * kDensityRadiusM);
    if (rho <= 0.0f)
        return 1.0f;
    const float fraction = 1.0f - std::exp(-1.913f * (1.0f / rho - 1.0f / 5.4f));
    return std::clamp(fraction, kMinCrowdSpeedFraction, 1.0f);
}

bool WorldNav::sketchedFlow(glm::vec3 p, glm::vec3& direction) const
{
    if (!sketch)
        return false;
    const SketchField& field = *sketch;
    const NavCell c = field.grid().cellOf(xz(p));
    const glm::vec2 d = field.grid().inside(c) && field.strength(c) >= kSketchMinStrength ? field.sample(xz(p)) : glm::vec2(0.0f);
    direction = {d.x, 0.0f, d.y};
    return true;
}

}  // namespace throng::sim
