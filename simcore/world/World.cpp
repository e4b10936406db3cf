#include "simcore/world/World.h"

#include "simcore/world/WorldBuilds.h"

#include "simcore/world/Constraints.h"

#include "simcore/nav/PathPlanning.h"
#include "simcore/steering/PathFollowing.h"

#include "simcore/scene/SceneOrigin.h"
#include "simcore/scene/SpawnArea.h"
#include "simcore/scene/StepRate.h"
#include "simcore/scene/TerrainHeight.h"
#include "simcore/scene/WalkingAge.h"
#include "simcore/world/PolygonSampler.h"
#include "simcore/world/RepeatedStatics.h"
#include "simcore/world/SpawnSpread.h"
#include "simcore/base/Rng.h"
#include "simcore/world/detail/AgentStreams.h"
#include "simcore/world/detail/NameIndex.h"
#include "simcore/world/detail/StepGeometry.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>

namespace throng::sim {

namespace {

using enum detail::AgentStream;
using detail::NameIndex;

constexpr std::uint64_t kSpawnTries = 16;  // draws of a spawned walker's place before it is walked out
// A spawned group's walkers part until no pair overlaps by more than this, or the rounds
// run out (a group denser than its bodies can pack: the collide pass goes on parting them).
constexpr float kSpreadToleranceM = 0.002f;
constexpr int kSpreadRounds = 200;

// The share of max force a type's walkers keep right with (KeepRight.h); 0: they do not.
// A type that also runs unaligned collision avoidance, which dodges sideways itself, keeps
// right with a quarter of separation's keep_right: the whole of it slowed two streams
// passing each other between pillars by half (TestWalkKernel's walled crowd: 39 of 100
// through in 60 s, 84 without keeping right), a quarter sped them (97) and still parted
// 120 walkers crossing a ring, who had jammed in its middle (all across in 120 s, 14
// without).
constexpr float kKeepRightWithUnaligned = 0.25f;

float keepRightShare(AgentKind kind, const TypeSteering& s)
{
    using B = Behaviour;
    if (kind != AgentKind::Pedestrian || !s.on(B::Separation) || s.on(B::ReciprocalAvoidance))
        return 0.0f;
    return s.separation.keepRight * (s.on(B::UnalignedCollisionAvoidance) ? kKeepRightWithUnaligned : 1.0f);
}

thread_local std::uint64_t t_worldsBuilt = 0;

}  // namespace

std::uint64_t worldsBuiltOnThisThread() { return t_worldsBuilt; }

World::World(const Scene& scene, const WorldOptions& options)
    : m_team(options.threads), m_origin(simulationOrigin(scene))
{
    // A set at map coordinates runs relative to its centre: at 1e6 m a float's spacing
    // is 6 cm, and a walker's step of 6 cm rounded to nothing (issue 23).
    if (m_origin == glm::dvec2(0.0))
        build(scene, options);
    else
        build(shiftedScene(scene, m_origin), options);
    ++t_worldsBuilt;
}

void World::build(const Scene& scene, const WorldOptions& options)
{
    m_seed = options.overrideSeed ? options.seed : scene.settings.seed;
    m_clock.frameDt = 1.0f / scene.settings.fps;
    m_clock.subSteps = subStepsPerFrame(scene.settings.fps);
    m_clock.dt = physicsStepS(scene.settings.fps);
    m_neighbourSweep = options.neighbourSweep;

    // Cells of half the perception radius on the ground: a nearest-first query then
    // stops a little beyond the k-th neighbour. Fliers get cells as large as the radius,
    // as each cell costs a search by height (fewer instructions per step, measured).
    bool fliers = false;
    for (const AgentType& t : scene.agentTypes)
        fliers = fliers || t.kind == AgentKind::Flier;
    const float cellPerRadius = fliers ? 1.0f : 0.5f;
    float cell = 0.0f;
    for (const AgentType& t : scene.agentTypes) {
        const float halfView = glm::radians(std::min(t.viewAngleDeg, 360.0f)) * 0.5f;
        m_types.steering.push_back(compileTypeSteering(t));
        m_types.collision.push_back(TypeCollision::of(t));
        const TypeSteering& steering = m_types.steering.back();
        m_types.keepRight.push_back(keepRightShare(t.kind, steering));
        m_types.ageYears.push_back(t.kind == AgentKind::Pedestrian ? t.variation.ageYears : glm::vec2(0.0f));
        m_types.timeGapS.push_back(t.kind == AgentKind::Pedestrian ? t.timeGapS : 0.0f);
        // Reciprocal avoidance needs both sides of a pair to see each other: such a type
        // perceives all round, whatever its view angle.
        const bool allRound = t.viewAngleDeg >= 360.0f || m_types.steering.back().on(Behaviour::ReciprocalAvoidance);
        m_types.params.push_back({t.radiusM, t.maxSpeed, t.maxForce, t.mass, t.perceptionM,
                           allRound ? -1.0f : std::cos(halfView), t.kind});
        cell = std::max(cell, cellPerRadius * t.perceptionM);
    }
    cell = std::clamp(cell, 0.5f, 4.0f);
    for (const TypeCollision& c : m_types.collision)
        m_types.makingWay = m_types.makingWay || c.priority != m_types.collision[0].priority ||
                            c.layerBit != m_types.collision[0].layerBit ||
                            c.collidesWith != m_types.collision[0].collidesWith;
    m_traffic.build(scene, m_seed, m_team.size());
    buildStatics(scene);
    buildAgents(scene);
    addTrafficAgents(scene);
    m_ties.build(m_agents.info);  // every agent is in: placed, spawned, sources', vehicles, heroes
    m_brains.build(scene, view());
    findEscapes();  // before the plans: one that starts inside an obstacle plans from outside it
    m_agents.out.assign(m_agents.size(), 0);  // nobody has left yet
    // The sources' agents wait off stage until the source phase lets them in.
    m_agents.offstage.assign(m_agents.size(), 0);
    m_sources.sendOffstage(m_agents);
    m_agents.unstarted.assign(m_agents.size(), 0);
    scheduleReactions(scene, true);
    m_formations.build(scene, m_agents, m_seed);
    m_nav.build(scene, view());
    if (m_exits.active()) {
        for (const std::int32_t g : m_exits.goals())
            m_nav.ensureField(view(), std::size_t(g));
        takeExits(m_exits.first(view()));
    }
    for (const TypeParams& t : m_types.params) {
        m_hasFliers = m_hasFliers || t.kind == AgentKind::Flier;
        m_allFliers = m_allFliers && t.kind == AgentKind::Flier;
        m_maxRadius = std::max(m_maxRadius, t.radius);
    }
    // On the ground, cells up to four times as wide while the crowd is spread out
    // (NeighbourGrid.h); fliers keep theirs (the boids' sweep is tuned to them).
    m_grid.configure(scene.settings.boundsMin, scene.settings.boundsMax, cell, m_hasFliers ? 0.0f : 4.0f * cell,
                     options.gridCells);
    m_grid.rebuild(m_agents.pos, m_hasFliers, m_agents.out, &m_team);
    // Layers or priorities change whom an agent perceives and avoids, and signals hold
    // agents back: those worlds keep the general path. Brains change weights, turns and
    // speeds per agent: the walker kernel takes them up, the boids kernel does not.
    const bool open = !m_types.makingWay && m_traffic.signal.empty();
    m_move.build(m_types, m_set, m_clock.dt, m_agents.size(), {!m_brains.active() && open, open},
                 {options.boidKernel, options.walkKernel, options.collideShortcut, options.steerEight});
    m_contactRounds.shortcut = options.contactShortcut;
}

void World::buildStatics(const Scene& scene)
{
    std::vector<Segment> walls, obstacleBoxes;
    for (const Wall& w : scene.walls)
        for (std::size_t k = 0; k + 1 < w.points.size(); ++k)
            walls.push_back({w.points[k], w.points[k + 1]});
    // Exact repeats (a paste gone wrong; `check` warns) would be met once each per query:
    // 50,000 copies of one wall made 24 frames take minutes. One of each is the same set.
    const std::vector<Obstacle> obstacles = uniqueObstacles(scene.obstacles);
    for (const Obstacle& o : obstacles)
        if (o.shape == ObstacleShape::Circle) {
            m_set.circles.push_back({glm::vec3(o.center.x, 0.0f, o.center.y), o.radiusM});
            obstacleBoxes.push_back({o.center - glm::vec2(o.radiusM), o.center + glm::vec2(o.radiusM)});
        }
    for (const Obstacle& o : obstacles) {
        if (o.shape != ObstacleShape::Box)
            continue;
        // Scene angles turn counter-clockwise seen from above (+y up, z south).
        const float a = glm::radians(o.angleDeg);
        const glm::vec2 ax(std::cos(a), -std::sin(a)), az(std::sin(a), std::cos(a));
        const glm::vec2 h = o.size * 0.5f;
        const glm::vec2 c[4] = {o.center - ax * h.x - az * h.y, o.center + ax * h.x - az * h.y,
                                o.center + ax * h.x + az * h.y, o.center - ax * h.x + az * h.y};
        for (int k = 0; k < 4; ++k)
            walls.push_back({c[k], c[(k + 1) % 4]});
        m_set.boxes.push_back({glm::vec3(o.center.x, 0.0f, o.center.y), glm::vec3(ax.x, 0.0f, ax.y), h});
        const float reach = glm::length(h);
        obstacleBoxes.push_back({o.center - glm::vec2(reach), o.center + glm::vec2(reach)});
    }
    m_traffic.appendKerbs(walls);
    removeRepeatedSegments(walls);
    // The wall grid's cells fit a walker's feelers; obstacle boxes are found by their bounds.
    // Both grids cover the bounds and a margin only: one wall point at -1e30 m would
    // otherwise stretch each cell over the whole set (every query seeing every wall).
    const glm::vec2 margin(kStaticGridMarginM);
    m_set.walls.build(walls, 4.0f, scene.settings.boundsMin - margin, scene.settings.boundsMax + margin);
    m_set.obstacleGrid.build(obstacleBoxes, 4.0f, scene.settings.boundsMin - margin, scene.settings.boundsMax + margin);

    m_set.goals = scene.goals;
    // Paths marked `plan: astar` become their planned way round the set (PathPlanning).
    m_set.paths = plannedPaths(scene);
    for (const Path& p : m_set.paths) {
        std::vector<glm::vec3> points;
        for (glm::vec2 q : p.points)
            points.push_back({q.x, 0.0f, q.y});
        m_set.pathPoints.push_back(std::move(points));
    }
    m_set.lights = scene.trafficLights;
    for (const Crosswalk& c : scene.crosswalks) {
        int light = -1;
        for (std::size_t l = 0; l < scene.trafficLights.size(); ++l)
            for (const StopLine& s : scene.trafficLights[l].stopLines)
                if (s.crosswalk == c.name)
                    light = int(l);
        m_set.crosswalks.push_back({c.from, c.to, c.widthM * 0.5f, light});
    }
    for (const FlowStroke& s : scene.flowStrokes)
        for (std::size_t k = 0; k + 1 < s.points.size(); ++k)
            m_set.flow.push_back({s.points[k], s.points[k + 1], s.widthM * 0.5f});
    m_set.terrain = scene.terrain;
    m_set.actionPoints = actionPlaces(scene);
    const glm::vec2 lo = scene.settings.boundsMin, hi = scene.settings.boundsMax;
    // Containment keeps fliers above the ground plane too (terrain is enforced per step).
    m_set.bounds = {glm::vec3(lo.x, 0.0f, lo.y), glm::vec3(hi.x, 1e4f, hi.y)};
}

void World::buildAgents(const Scene& scene)
{
    std::size_t total = scene.agents.size();
    for (const SpawnGroup& g : scene.groups)
        total += g.count;
    m_agents.info.reserve(total);

    const NameIndex types(scene.agentTypes), goals(scene.goals), paths(scene.paths);
    for (const Agent& a : scene.agents)
        addAgent(scene, a.id, std::uint16_t(std::max(0, types(a.type))), a.position, glm::radians(a.headingDeg),
                 goals(a.goal), paths(a.path), a.leader);
    AgentId next = firstSpawnedId(scene);
    // A group or source that chooses among exits (ExitChoice.h) starts bound for the first;
    // the choice is made once the World's flow fields exist (a source's agents: as they enter).
    std::vector<std::int32_t> choosesFrom(scene.agents.size(), -1);
    std::vector<std::vector<std::int32_t>> exitSets;
    for (std::size_t g = 0; g < scene.groups.size(); ++g) {
        const SpawnGroup& group = scene.groups[g];
        spawnGroup(scene, group, g, std::uint16_t(std::max(0, types(group.type))),
                   group.exits.empty() ? goals(group.goal) : goals(group.exits[0]), paths(group.path), next);
        std::int32_t set = -1;
        if (!group.exits.empty() && !scene.brainPicksGoals(group.type)) {
            set = std::int32_t(exitSets.size());
            exitSets.emplace_back();
            for (const std::string& e : group.exits)
                exitSets.back().push_back(goals(e));
        }
        choosesFrom.resize(m_agents.info.size(), set);
    }
    addSourceAgents(scene, next, choosesFrom, exitSets);
    m_exits.build(std::move(choosesFrom), std::move(exitSets));

    // Leaders were given as ids; the step reads dense indices.
    std::map<AgentId, std::int32_t> denseOf;
    for (std::size_t i = 0; i < m_agents.info.size(); ++i)
        denseOf[m_agents.info[i].id] = std::int32_t(i);
    for (std::int32_t& l : m_agents.leader) {
        auto it = denseOf.find(AgentId(l));
        l = l > 0 && it != denseOf.end() ? it->second : -1;
    }
}

namespace {

// Interleaves the low 16 bits of x and z (a Morton code): agents near each other in
// space get near codes, so sorting by it keeps neighbours near in memory.
std::uint32_t mortonCode(std::uint32_t x, std::uint32_t z)
{
    auto spread = [](std::uint32_t v) {
        v &= 0xffffu;
        v = (v | (v << 8)) & 0x00ff00ffu;
        v = (v | (v << 4)) & 0x0f0f0f0fu;
        v = (v | (v << 2)) & 0x33333333u;
        return (v | (v << 1)) & 0x55555555u;
    };
    return spread(x) | (spread(z) << 1);
}

}  // namespace

void World::spawnGroup(const Scene& scene, const SpawnGroup& group, std::size_t groupIndex, std::uint16_t type,
                       int goal, int path, AgentId& nextId)
{
    // Keys are (group, member), not the running id, so editing one group never moves
    // the members of another.
    struct Spawn { glm::vec3 position; float heading; std::uint32_t order; };
    std::vector<Spawn> spawns(group.count);
    const bool walker = scene.agentTypes[type].kind == AgentKind::Pedestrian;
    const float bodyR = scene.agentTypes[type].radiusM;
    std::vector<glm::vec2> places(group.count);
    std::vector<std::uint8_t> clearOfStatics(group.count, 1);
    const PolygonSampler polygon(group.shape == AreaShape::Polygon ? std::span<const glm::vec2>(group.points)
                                                                   : std::span<const glm::vec2>());
    for (std::uint32_t k = 0; k < group.count; ++k) {
        const std::uint64_t key = (std::uint64_t(groupIndex + 1) << 32) | k;
        // A walker drawn where its body does not fit (a group's area over a pillar or
        // across a wall) is drawn again, up to kSpawnTries times (draw k keyed by step k,
        // so the first draw is the one every earlier release made); one that never fits
        // is walked out by findEscapes (Constraints.h).
        glm::vec2& p = places[k];
        for (std::uint64_t draw = 0; draw < kSpawnTries; ++draw) {
            const float u = rngUniform(m_seed, key, draw, kSpawnX), v = rngUniform(m_seed, key, draw, kSpawnZ);
            if (group.shape == AreaShape::Rect) {
                p = group.min + (group.max - group.min) * glm::vec2(u, v);
            } else if (group.shape == AreaShape::Polygon) {
                p = polygon.at(rngUniform(m_seed, key, draw, kSpawnPick), u, v);
            } else {
                const float r = group.radiusM * std::sqrt(u), a = 6.28318531f * v;
                p = group.center + r * glm::vec2(std::cos(a), std::sin(a));
            }
            glm::vec2 clear;
            clearOfStatics[k] = !walker || !escapeTarget(m_set, p, bodyR, clear);
            if (clearOfStatics[k])
                break;
        }
    }
    if (walker)
        spreadMembers(group, type, groupIndex, places, clearOfStatics);
    for (std::uint32_t k = 0; k < group.count; ++k) {
        const std::uint64_t key = (std::uint64_t(groupIndex + 1) << 32) | k;
        const glm::vec2 p = places[k];
        float heading = 6.28318531f * rngUniform(m_seed, key, 0, kSpawnHeading);
        // Fliers spawn at a height drawn from the group's altitude range.
        const float y =
            group.altitudeM.x + (group.altitudeM.y - group.altitudeM.x) * rngUniform(m_seed, key, 0, kSpawnY);
        if (goal >= 0) {
            const glm::vec2 d = scene.goals[std::size_t(goal)].position - p;
            if (glm::dot(d, d) > 1e-6f)
                heading = std::atan2(-d.y, d.x);
        }
        // Members are added in the order of 2 m cells along a Morton curve: a random
        // spawn order would scatter each agent's neighbours over the whole of memory,
        // and every neighbour read of a large crowd would miss the cache.
        const glm::vec2 cell = glm::clamp((p - scene.settings.boundsMin) * 0.5f, glm::vec2(0.0f), glm::vec2(65535.0f));
        spawns[k] = {glm::vec3(p.x, y, p.y), heading, mortonCode(std::uint32_t(cell.x), std::uint32_t(cell.y))};
    }
    std::vector<std::uint32_t> byPlace(group.count);
    for (std::uint32_t k = 0; k < group.count; ++k)
        byPlace[k] = k;
    std::stable_sort(byPlace.begin(), byPlace.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return spawns[a].order < spawns[b].order; });
    for (std::uint32_t k : byPlace)
        addAgent(scene, nextId++, type, spawns[k].position, spawns[k].heading, goal, path, group.leader);
}

void World::spreadMembers(const SpawnGroup& group, std::uint16_t type, std::size_t groupIndex,
                          std::vector<glm::vec2>& places, const std::vector<std::uint8_t>& clearOfStatics) const
{
    // A group's walkers drawn over each other part before the first frame (SpawnSpread.h),
    // against each other and the ground agents placed before them that their type collides
    // with, their centres kept in the group's area and their bodies clear of the statics;
    // one drawn inside a wall or obstacle is walked out by findEscapes instead.
    if (places.empty())
        return;
    const float r = m_types.params[type].radius;
    glm::vec2 lo = places[0], hi = places[0];
    for (const glm::vec2& p : places) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    std::vector<SpreadBody> bodies;
    bodies.reserve(places.size());
    float largest = r;  // the largest body of any type (the types, not every agent placed so far)
    for (const TypeParams& t : m_types.params)
        largest = std::max(largest, t.radius);
    const float reach = 8.0f * largest;  // members part by a few radii at most
    for (std::size_t i = 0; i < m_agents.pos.size(); ++i) {
        const glm::vec2 q = detail::xz(m_agents.pos[i]);
        if (m_types.params[m_agents.info[i].typeIndex].kind == AgentKind::Flier ||
            !collide(m_types.collision[type], collision(i)) || q.x < lo.x - reach || q.y < lo.y - reach ||
            q.x > hi.x + reach || q.y > hi.y + reach)
            continue;
        bodies.push_back({q, m_agents.radius[i], false, m_agents.info[i].id});
    }
    const std::size_t first = bodies.size();
    for (std::size_t k = 0; k < places.size(); ++k)
        bodies.push_back({places[k], r, clearOfStatics[k] != 0, (std::uint64_t(groupIndex + 1) << 32) | k});
    const bool hasStatics = m_set.hasStatics();
    auto settle = [&](glm::vec2 q, float radius, glm::vec2& out) {
        q = clampToSpawnArea(group, q);
        if (!hasStatics) {
            out = q;
            return true;
        }
        return !escapeTarget(m_set, q, radius, out);  // not into a wall or obstacle; clear of their edges
    };
    spreadBodies(bodies, settle, kSpreadToleranceM, kSpreadRounds);
    for (std::size_t k = 0; k < places.size(); ++k)
        places[k] = bodies[first + k].p;
}

void World::addAgent(const Scene& scene, AgentId id, std::uint16_t type, glm::vec3 pos, float headingRad, int goal,
                     int path, AgentId leader)
{
    const AgentType& t = scene.agentTypes[type];
    const bool flier = t.kind == AgentKind::Flier;
    if (!flier)
        pos.y = m_set.groundHeight(pos.x, pos.z);
    // Heading is counter-clockwise seen from above (+y up, z south): forward = (cos, 0, -sin).
    const glm::vec3 fwd(std::cos(headingRad), 0.0f, -std::sin(headingRad));
    const float speedFactor =
        rngRange(m_seed, id, 0, kSpeedFactor, t.variation.speedFactor.x, t.variation.speedFactor.y);
    m_agents.info.push_back({id, type});
    m_agents.pos.push_back(pos);
    // Fliers start at their stall speed so they never fall out of the sky on frame 1.
    const float maxSpeed = t.maxSpeed * speedFactor * ageSpeedFactor(m_types.ageYears[type], m_seed, id);
    m_agents.vel.push_back(flier ? fwd * std::min(maxSpeed, std::max(t.minSpeed, 0.5f * maxSpeed)) : glm::vec3(0.0f));
    m_agents.fwd.push_back(fwd);
    m_agents.side.push_back(glm::normalize(glm::cross(fwd, glm::vec3(0.0f, 1.0f, 0.0f))));
    m_agents.up.push_back(glm::vec3(0.0f, 1.0f, 0.0f));
    m_agents.radius.push_back(t.radiusM);
    m_agents.maxSpeed.push_back(maxSpeed);
    m_agents.phase.push_back(
        rngRange(m_seed, id, 0, kPhaseOffset, t.variation.phaseOffset.x, t.variation.phaseOffset.y));
    // Stride length scales with body size; 1.4 m is an adult's walking stride.
    m_agents.stride.push_back(t.kind == AgentKind::Pedestrian
                           ? 1.4f * std::max(0.5f, t.radiusM / 0.3f) * rngRange(m_seed, id, 0, kStride, 0.95f, 1.05f)
                           : 2.0f * t.radiusM * 3.14159265f);
    const float wa = 6.28318531f * rngUniform(m_seed, id, 0, kWanderStart);
    m_agents.wander.push_back({glm::vec3(std::sin(wa), 0.0f, std::cos(wa))});
    m_agents.arrivalTime.push_back(-1.0f);
    m_agents.goal.push_back(goal);
    m_agents.path.push_back(path);
    m_agents.leader.push_back(std::int32_t(leader));
    // A crowd sharing a goal spreads over it instead of converging on one point, so the
    // first arrivals do not wall off the rest.
    glm::vec2 spot(0.0f);
    if (goal >= 0) {
        const Goal& g = scene.goals[std::size_t(goal)];
        spot = detail::goalSpot(g.position, g.radiusM, g.exit, t.radiusM, rngUniform(m_seed, id, 0, kSpotR),
                                rngUniform(m_seed, id, 0, kSpotA));
    }
    m_agents.goalSpot.push_back(spot);
    m_agents.pathAlong.push_back(path >= 0 ? startPathProgress(SteeringPath{m_set.pathPoints[std::size_t(path)],
                                                                            m_set.paths[std::size_t(path)].radiusM,
                                                                            m_set.paths[std::size_t(path)].closed},
                                                               pos)
                                           : 0.0f);
    m_agents.arrived.push_back(0);
    m_agents.stopped.push_back(0);
    m_agents.stoppedBefore.push_back(0);
    m_agents.onCrosswalk.push_back(0);
    m_agents.nextPos.push_back(pos);
    m_agents.nextVel.push_back(m_agents.vel.back());
    m_agents.nextFwd.push_back(fwd);
    m_agents.nextSide.push_back(m_agents.side.back());
    m_agents.nextUp.push_back(m_agents.up.back());
    m_agents.nextWander.push_back(m_agents.wander.back());
    m_agents.heldForce.push_back(glm::vec3(0.0f));
    m_agents.nearIndex.resize(m_agents.nearIndex.size() + kMaxNeighbours);
    m_agents.nearCount.push_back(0);
    m_move.addAgent();
    m_agents.resolvedPos.push_back(pos);
    m_agents.pointAt.push_back(-1);
    m_agents.pointLast.push_back(-1);
    m_agents.pointLeftS.push_back(0.0f);
}

std::size_t World::agentsInScene() const
{
    std::size_t n = 0;
    for (std::size_t i = 0; i < m_agents.size(); ++i)
        n += m_agents.out[i] ? 0 : 1;
    return n;
}

// Agents that start inside a wall or obstacle walk out of it first (Constraints.h).
void World::findEscapes()
{
    const std::size_t n = m_agents.pos.size();
    m_agents.escaping.assign(n, 0);
    m_agents.escapeTo.assign(n, glm::vec2(0.0f));
    if (m_set.walls.segments().empty() && m_set.circles.empty())
        return;
    for (std::size_t i = 0; i < n; ++i) {
        if (m_types.params[m_agents.info[i].typeIndex].kind != AgentKind::Pedestrian || m_traffic.isDriven(i))
            continue;
        glm::vec2 to;
        if (escapeTarget(m_set, detail::xz(m_agents.pos[i]), m_agents.radius[i], to)) {
            m_agents.escaping[i] = 1;
            m_agents.escapeTo[i] = to;
        }
    }
}

std::size_t World::agentsWithGoal() const
{
    std::size_t count = 0;
    for (std::size_t i = 0; i < m_agents.pos.size(); ++i)
        if (!m_agents.offstage[i] && ((m_agents.path[i] >= 0 && !m_set.paths[std::size_t(m_agents.path[i])].closed) ||
                                      (m_agents.path[i] < 0 && m_agents.goal[i] >= 0)))
            ++count;
    return count;
}

int World::lightState(std::size_t light) const
{
    return view().lightState(light);
}


void World::snapshot(std::vector<AgentFrame>& out) const
{
    out.resize(m_agents.pos.size());
    for (std::size_t i = 0; i < m_agents.pos.size(); ++i) {
        const float speed = glm::length(m_agents.vel[i]);
        AgentFrame& f = out[i];
        f.position = m_agents.pos[i];
        f.headingRad = std::atan2(-m_agents.fwd[i].z, m_agents.fwd[i].x);
        f.speed = speed;
        f.phase = m_agents.phase[i];
        // Clip thresholds relative to a walker: below 0.1 m/s stand, above 2.5 m/s run.
        f.clip = actionPointClip(m_set.actionPoints, m_agents, i,
                                 m_brains.clip(i, speed < 0.1f ? Clip::Idle : (speed < 2.5f ? Clip::Walk : Clip::Run)));
        f.out = m_agents.out[i] != 0 && m_agents.offstage[i] == 0;
        f.present = m_agents.offstage[i] == 0;
        f.arrived = m_agents.arrived[i] != 0;
    }
}

void World::startRecording(FrameCache& cache) const
{
    cache.reset(m_agents.info, 1.0f / m_clock.frameDt, origin());
    std::vector<AgentFrame> frame;
    snapshot(frame);
    cache.append(frame);
}

std::size_t World::memoryBytes() const
{
    const std::size_t n = m_agents.pos.capacity();
    return n * (sizeof(AgentInfo) + 11 * sizeof(glm::vec3) + 2 * sizeof(WanderState) + 6 * sizeof(float) +
                5 * sizeof(std::int32_t) + 2 * sizeof(glm::vec2) + 6 + kMaxNeighbours * sizeof(std::uint32_t)) +
           m_grid.memoryBytes();
}

// The traffic's vehicles and heroes, as agents after the scene's own.
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
            addAgent(scene, ts.id(v), typeOf(typeById[ts.id(v)]), glm::vec3(p.x, 0.0f, p.y), std::atan2(-f.y, f.x), -1,
                     -1, 0);
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
    m_traffic.markAgents(m_agents, m_types, walkers);
    // A driven agent counts as standing for the step's phases: it is never steered, and a
    // walker that overlaps it takes the whole correction.
    for (std::size_t i = walkers; i < m_agents.pos.size(); ++i)
        m_agents.stopped[i] = m_agents.stoppedBefore[i] = 1;
}

// The brains' facade (BrainPhase.h).
int World::brainAction(std::size_t i) const { return m_brains.action(i); }
std::string World::brainActionName(std::size_t i) const { return m_brains.actionName(i); }
const std::vector<std::string>& World::brainErrors() const { return m_brains.errors(); }
const BrainEvaluator* World::brainEvaluator(std::size_t typeIndex) const { return m_brains.evaluator(typeIndex); }
const BrainEvaluator* World::agentBrainEvaluator(std::size_t i) const { return m_brains.agentEvaluator(i); }
void World::pickBrainAgent(std::ptrdiff_t i) { m_brains.pickAgent(i, m_agents.pos.size()); }

}  // namespace throng::sim
