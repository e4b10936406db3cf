// The navigation phase of World::step (WorldNav): walkers whose type navigates by A*
// follow a plan shared through the PlanCache (advancing within their own waypoint
// radius), flow-field walkers follow their goal's field, and a walker that makes no
// progress re-plans around the blockage or side-steps. Plans are made serially in agent order, targets in parallel
// from each agent's own state, so the result does not depend on the thread count.
#include "simcore/world/WorldNav.h"

#include "simcore/world/Sense.h"
#include "simcore/world/StepView.h"

#include "simcore/nav/NavDefaults.h"
#include "simcore/nav/NavPassages.h"
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

void WorldNav::build(const Scene& scene, const StepView& v)
{
    const std::size_t n = v.agents.pos.size();
    float inflate = 0.0f, smallest = INFINITY;
    std::vector<Navigation> modes(n, Navigation::Direct);
    for (std::size_t i = 0; i < n; ++i) {
        const AgentType& t = scene.agentTypes[v.agents.info[i].typeIndex];
        if (t.kind != AgentKind::Pedestrian || v.traffic.isDriven(i) || t.navigation == Navigation::Direct)
            continue;
        modes[i] = t.navigation;
        inflate = std::max(inflate, t.radiusM + kNavClearanceM);
        smallest = std::min(smallest, t.radiusM);
    }
    active = inflate > 0.0f;
    if (!active && scene.flowStrokes.empty())
        return;
    // The set as walkers meet it: walls, obstacles and the kerbs along lanes (v.set.walls holds
    // all three), so a plan never leads onto a lane except over a crosswalk.
    NavShapes shapes = navShapes(scene);
    shapes.walls = v.set.walls.segments();
    const float inflateM = active ? inflate : kNavDefaultRadiusM + kNavClearanceM;
    grid.build(shapes, scene.settings.boundsMin, scene.settings.boundsMax,
               NavGridParams{scene.settings.navCellM, inflateM});
    // A passage the largest body fits through stays open, though narrower than the clearance asks.
    openNarrowPassages(grid, shapes, inflateM - kNavClearanceM, inflateM);
    // Flow strokes become a sketched field (Jin et al. 2008) that flow_field_following
    // reads; should the solve fail, the World keeps the plain lookup along the strokes.
    if (!scene.flowStrokes.empty()) {
        SketchField solved;
        if (solved.build(scene, grid))
            sketch = std::move(solved);
    }
    if (!active)
        return;
    reachShapes = std::move(shapes);
    reachRadiusM = smallest;

    hasField.assign(v.set.goals.size(), 0);
    fields.resize(v.set.goals.size());
    for (std::size_t i = 0; i < n; ++i)
        if (modes[i] == Navigation::FlowField && v.agents.goal[i] >= 0)
            hasField[std::size_t(v.agents.goal[i])] = 1;
    for (std::size_t g = 0; g < v.set.goals.size(); ++g)
        if (hasField[g]) {
            const FlowGoal goal{v.set.goals[g].position, v.set.goals[g].radiusM};
            fields[g].build(grid, std::span<const FlowGoal>(&goal, 1));
        }

    mode = std::move(modes);
    plan.assign(n, nullptr);
    planGoal.assign(n, -1);
    waypoint.assign(n, 0);
    waypointRadiusM.resize(n);
    for (std::size_t i = 0; i < n; ++i)
        waypointRadiusM[i] = sim::waypointRadiusM(
            kWaypointRadiusBaseM, rngUniform(v.seed, v.agents.info[i].id, 0, kWaypointRadius), kWaypointSpread);
    stall.assign(n, StallWatch{});
    replan.assign(n, 0);
    sideStepS.assign(n, 0.0f);
    sideDir.assign(n, glm::vec2(0.0f));
    target.assign(n, glm::vec2(0.0f));
    hasTarget.assign(n, 0);
    waiting.assign(n, 0);
    waitingNext.assign(n, 0);
    lostSteps.assign(n, 0);
    noWay.assign(n, 0);
    // Plans at load, in agent order: a group starting in one cell shares one plan.
    for (std::size_t i = 0; i < n; ++i)
        if (mode[i] == Navigation::AStar && v.agents.goal[i] >= 0 && v.agents.path[i] < 0)
            planFor(v, i);
    // Flow-field walkers where the field does not reach: is there a way at all?
    for (std::size_t i = 0; i < n; ++i)
        if (mode[i] == Navigation::FlowField && v.agents.goal[i] >= 0 && v.agents.path[i] < 0) {
            const FlowField& field = fields[std::size_t(v.agents.goal[i])];
            const NavCell c = field.grid().nearestWalkable(field.grid().cellOf(startOf(v, i)));
            if (!field.grid().walkable(c) || !field.reachable(c))
                noWay[i] = noWayToGoal(v, i) ? 1 : 0;
        }
}

void WorldNav::ensureField(const StepView& v, std::size_t g)
{
    if (!active || g >= hasField.size() || hasField[g])
        return;
    const FlowGoal goal{v.set.goals[g].position, v.set.goals[g].radiusM};
    fields[g].build(grid, std::span<const FlowGoal>(&goal, 1));
    hasField[g] = 1;
}

glm::vec2 WorldNav::startOf(const StepView& v, std::size_t i) const
{
    // One that started inside a wall or obstacle walks out first (Constraints.h).
    return v.agents.escaping[i] ? v.agents.escapeTo[i] : xz(v.agents.pos[i]);
}

bool WorldNav::noWayToGoal(const StepView& v, std::size_t i)
{
    if (!reach.built()) {
        const NavGrid& g = grid;
        const glm::vec2 lo = g.origin(), hi = lo + glm::vec2(float(g.cols()), float(g.rows())) * g.cellM();
        reach.build(reachShapes, lo, hi, reachRadiusM,
                          NavReach::cellFor(lo, hi, std::min(0.5f * g.cellM(), 0.1f)));
    }
    // Only a walker found in a region that does not meet the goal waits; one pushed where
    // the grid cannot place it (deep in a wall's margin) goes on as before.
    const Goal& g = v.set.goals[std::size_t(v.agents.goal[i])];
    return reach.regionAt(startOf(v, i)) >= 0 && !reach.reaches(startOf(v, i), g.position, g.radiusM);
}

void WorldNav::planFor(const StepView& v, std::size_t i)
{
    const Goal& g = v.set.goals[std::size_t(v.agents.goal[i])];
    plan[i] = planBetween(cache, grid, startOf(v, i), g.position, astar);
    planGoal[i] = v.agents.goal[i];
    noWay[i] = plan[i] && plan[i]->found() ? 0 : noWayToGoal(v, i) ? 1 : 0;
    waypoint[i] = 0;
    stall[i] = StallWatch{};
}

void WorldNav::beforeStep(const StepView& v)
{
    if (!active)
        return;
    const std::size_t n = v.agents.pos.size();
    // Plan: serially and in agent order, so what the cache holds never depends on threads.
    for (std::size_t i = 0; i < n; ++i) {
        if (mode[i] != Navigation::AStar || v.agents.stopped[i] || v.agents.goal[i] < 0 || v.agents.path[i] >= 0)
            continue;
        const NavPlan* current = plan[i].get();
        if (!current || planGoal[i] != v.agents.goal[i]) {
            planFor(v, i);
        } else if (PlanCache::stale(*current, grid)) {
            ++counters.stalePlans;
            planFor(v, i);
        } else if (lostSteps[i] >= kLostSteps) {
            // Pushed off its way (the crowd at a crossing, a side-step) until a wall or a
            // kerb stands between the walker and its corner: current again from where it is.
            lostSteps[i] = 0;
            replan[i] = 0;
            ++counters.lostPlans;
            planFor(v, i);
        } else if (replan[i]) {
            // Stalled: current around the spot just ahead (the jam or what it keeps pushing
            // against); with no way round, step aside for a moment instead.
            replan[i] = 0;
            const glm::vec2 p = xz(v.agents.pos[i]);
            glm::vec2 way = hasTarget[i] ? target[i] - p : v.agents.goalSpot[i] - p;
            way = glm::dot(way, way) > 1e-8f ? glm::normalize(way) : xz(v.agents.fwd[i]);
            const NavGrid& cells = grid;
            const NavCell from = cells.nearestWalkable(cells.cellOf(p));
            const NavCell to = cells.nearestWalkable(cells.cellOf(v.set.goals[std::size_t(v.agents.goal[i])].position));
            NavPlan detour = planAround(astar, cells, from, to, p + way * (v.agents.radius[i] + kAvoidRadiusM),
                                        kAvoidRadiusM);
            // Progress is measured along the new way from here on (a detour is longer).
            stall[i] = StallWatch{};
            if (detour.found()) {
                plan[i] = std::make_shared<const NavPlan>(std::move(detour));
                waypoint[i] = 0;
                ++counters.replans;
            } else {
                const float sign =
                    rngUniform(v.seed, v.agents.info[i].id, v.clock.step, kSideStepSign) < 0.5f ? -1.0f : 1.0f;
                sideDir[i] = glm::vec2(-way.y, way.x) * sign;
                sideStepS[i] = kSideStepDurationS;
                ++counters.sideSteps;
            }
        }
    }
    // Target: each walker from its own state.
    v.team.forEach(n, 256, [&](std::size_t i) {
        waitingNext[i] = queueDepth(v, i);
        updateTarget(v, i);
    });
    waiting.swap(waitingNext);
}

std::uint8_t WorldNav::queueDepth(const StepView& v, std::size_t i) const
{
    if (v.agents.stopped[i] || v.traffic.signal.empty() ||
        v.types.params[v.agents.info[i].typeIndex].kind != AgentKind::Pedestrian)
        return 0;
    const PedestrianSignal& sig = v.traffic.signal[i];
    if (sig.crosswalk >= 0 && !sig.onCrosswalk && (sig.mustStop || sig.phase != LightPhase::Green))
        return 1;
    // Right behind a waiting walker, in the way it wants to go: the queue waits too, one
    // place further back. Neighbours and depths are the last step's, so the order agents
    // are visited in does not matter. Two walkers facing each other would otherwise keep
    // each other "waiting" for ever (and never re-plan): without a head held at a light,
    // such a ring's depth grows by one a step until it passes the cap and dissolves.
    const glm::vec2 p = xz(v.agents.pos[i]), way = wantedHeading(v, i);
    const std::uint32_t* near = &v.agents.nearIndex[i * kMaxNeighbours];
    std::uint8_t ahead = kMaxQueueDepth;
    for (std::size_t k = 0; k < v.agents.nearCount[i]; ++k) {
        const std::uint32_t j = near[k];
        const glm::vec2 d = xz(v.agents.pos[j]) - p;
        if (waiting[j] && glm::length(d) < v.agents.radius[i] + v.agents.radius[j] + kQueueGapM &&
            glm::dot(d, way) > 0.0f)
            ahead = std::min(ahead, waiting[j]);
    }
    return ahead < kMaxQueueDepth ? std::uint8_t(ahead + 1) : 0;
}

void WorldNav::updateTarget(const StepView& v, std::size_t i)
{
    hasTarget[i] = 0;
    const Navigation how = mode[i];
    if (how == Navigation::Direct || v.agents.stopped[i] || v.agents.goal[i] < 0 || v.agents.path[i] >= 0)
        return;
    const glm::vec2 p = xz(v.agents.pos[i]);
    // The target lies beyond the arrival's slowing distance, so a walker keeps its pace
    // through corners and down the field and slows only for its own spot in the goal.
    const float carrot = v.types.steering[v.agents.info[i].typeIndex].arrival.slowingDistanceM + 0.5f;
    auto aim = [&](glm::vec2 dir, float distance) {
        target[i] = p + dir * std::max(distance, carrot);
        hasTarget[i] = 1;
    };
    if (sideStepS[i] > 0.0f) {
        sideStepS[i] -= v.clock.dt;
        aim(sideDir[i], 0.0f);
        return;
    }
    const std::size_t goal = std::size_t(v.agents.goal[i]);
    float remainingM = glm::distance(p, v.agents.goalSpot[i]);
    // No way to the goal (walls close it off, or its door is narrower than the body): the
    // walker waits where it stands. Heading straight at the goal instead, it pressed against
    // the set, stalled, side-stepped and tried again for the whole shot (issue 23). A current
    // made on a changed grid is stale and made again, so a door that opens lets it go.
    auto wait = [&] {
        target[i] = p;
        hasTarget[i] = 1;
        stall[i] = StallWatch{};
    };
    if (how == Navigation::AStar) {
        const NavPlan* current = plan[i].get();
        if (noWay[i] && planGoal[i] == v.agents.goal[i])
            return wait();
        if (current && current->found() && planGoal[i] == v.agents.goal[i]) {
            const std::vector<glm::vec2>& w = current->waypoints;
            // Within its own radius of a corner the walker turns for the next one, but only
            // once it can see it: cutting a corner short must not lead into a wall's end.
            std::size_t k = waypoint[i];
            while (k + 1 < w.size()) {
                const std::size_t next = advanceWaypoint(w, k, p, waypointRadiusM[i]);
                if (next == k || (glm::distance(p, w[k]) > kCornerReachedM && !lineOfSight(grid, p, w[k + 1])))
                    break;
                ++k;
            }
            waypoint[i] = std::uint32_t(k);
            // Seen from the nearest walkable cell: a walker brushing a wall stands in its
            // inflated margin, from where nothing is in sight.
            const NavGrid& cells = grid;
            const NavCell at = cells.cellOf(p);
            const glm::vec2 eye = cells.walkable(at) ? p : cells.centre(cells.nearestWalkable(at));
            const bool inSight = glm::distance(p, w[k]) <= kCornerReachedM || lineOfSight(cells, eye, w[k]);
            lostSteps[i] = inSight ? 0 : std::uint8_t(std::min<int>(lostSteps[i] + 1, kLostSteps));
            // The last waypoint is the goal cell's centre: from there on the walker heads
            // for its own spot, as a direct walker does.
            if (k + 1 < w.size()) {
                const glm::vec2 d = w[k] - p;
                const float len = glm::length(d);
                remainingM = len + glm::distance(w.back(), v.agents.goalSpot[i]);
                for (std::size_t j = k; j + 1 < w.size(); ++j)
                    remainingM += glm::distance(w[j], w[j + 1]);
                if (len > 1e-4f)
                    aim(d / len, len);
            }
        }
    } else if (goal < hasField.size() && hasField[goal]) {
        const FlowField& field = fields[goal];
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
                const float slowing = v.types.steering[v.agents.info[i].typeIndex].arrival.slowingDistanceM;
                const float fraction = crowdSpeedFraction(v, i, dir);
                if (fraction < 1.0f && slowing > 0.0f) {
                    target[i] = p + dir * (slowing * fraction);
                    hasTarget[i] = 1;
                } else {
                    aim(dir, 0.0f);
                }
            }
        } else if (const NavCell free = onwardOrNearestWalkable(field, c, [&](glm::vec2 q) {
                       bool crossed = false;
                       v.set.walls.forEachNear((p + q) * 0.5f, 0.5f * glm::distance(p, q) + 0.01f,
                                               [&](std::uint32_t k) {
                                                   const Segment& w = v.set.walls.segment(k);
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
        } else if (noWay[i]) {
            return wait();
        }
    }
    // Stall watch: waiting at a light is not being stuck. A flow-field walker in a queue
    // is not stuck either (the field already leads round the set), so only A* walkers act.
    if (waitingNext[i])
        stall[i] = StallWatch{};
    else if (updateStall(stall[i], remainingM, v.clock.dt) && how == Navigation::AStar)
        replan[i] = 1;
}

float WorldNav::crowdSpeedFraction(const StepView& v, std::size_t i, glm::vec2 way) const
{
    // Weidmann (1993): v(rho) = v0 (1 - exp(-1.913 (1/rho - 1/5.4))), rho in persons/m^2,
    // from the walkers in the half disk ahead (last step's neighbours: thread-independent).
    const glm::vec2 p = xz(v.agents.pos[i]);
    const std::uint32_t* near = &v.agents.nearIndex[i * kMaxNeighbours];
    const std::size_t count = v.agents.nearCount[i];
    // The half disk is 1.2 m round; in a dense crowd the walker's k nearest all stand
    // closer than that, and those beyond them are not in its list: then the half disk
    // shrinks to the farthest of them, within which the list holds everyone (a k-nearest
    // density estimate). Counting only the listed within 1.2 m capped the density a walker
    // saw at about 2 persons/m², so packed crowds walked on at 0.7 m/s.
    float radius2 = kDensityRadiusM * kDensityRadiusM;
    if (count == kMaxNeighbours) {
        float farthest2 = 0.0f;
        for (std::size_t k = 0; k < count; ++k) {
            const glm::vec2 d = xz(v.agents.pos[near[k]]) - p;
            farthest2 = std::max(farthest2, glm::dot(d, d));
        }
        radius2 = std::min(radius2, std::max(farthest2, 1e-4f));
    }
    int ahead = 0;
    for (std::size_t k = 0; k < count; ++k) {
        const glm::vec2 d = xz(v.agents.pos[near[k]]) - p;
        ahead += glm::dot(d, d) <= radius2 && glm::dot(d, way) > 0.0f ? 1 : 0;
    }
    const float rho = float(ahead) / (0.5f * 3.14159265f * radius2);
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
    const glm::vec2 d =
        field.grid().inside(c) && field.strength(c) >= kSketchMinStrength ? field.sample(xz(p)) : glm::vec2(0.0f);
    direction = {d.x, 0.0f, d.y};
    return true;
}

}  // namespace throng::sim
