// Checkpoints of a World: saving, restoring into a World of the same scene, and adopting
// into a World of an edited scene (the rule is in WorldState.h). Kept out of the step
// files; the lists below are the one place that names the World's state arrays, so a
// renamed or new array is added here.
#include "simcore/world/WorldState.h"

#include "simcore/hero/HeroTrack.h"
#include "simcore/world/World.h"
#include "simcore/world/detail/WorldBrains.h"
#include "simcore/world/detail/WorldStateColumns.h"

#include <algorithm>
#include <map>
#include <stdexcept>

namespace throng::sim {

std::size_t WorldState::memoryBytes() const
{
    std::size_t bytes = sizeof(WorldState) + agents.size() * sizeof(AgentInfo) + grid.memoryBytes();
#define THRONG_BYTES(name) bytes += name.size() * sizeof(name[0]);
    THRONG_AGENT_COLUMNS(THRONG_BYTES)
#undef THRONG_BYTES
#define THRONG_BYTES(world, name) bytes += name.size() * sizeof(name[0]);
    THRONG_NAV_COLUMNS(THRONG_BYTES)
#undef THRONG_BYTES
    bytes += signal.size() * sizeof(PedestrianSignal) +
             (pedestriansBefore.size() + pedestriansAfter.size()) * sizeof(PedestrianView);
    if (trafficSystem)
        bytes += trafficSystem->vehicleCount() * 128;
    for (const auto& type : brainState)
        for (const auto& column : type)
            bytes += column.size() * sizeof(float);
    for (const auto& column : tagValues)
        bytes += column.size() * sizeof(float);
    return bytes + brainBatch.size() * sizeof(std::int32_t) + (brainLocal.size() + brainAction.size()) * 6 +
           vehicleSpeed.size() * sizeof(float);
}

bool sameTrafficSet(const Scene& a, const Scene& b)
{
    if (!(a.settings == b.settings && a.lanes == b.lanes && a.crosswalks == b.crosswalks &&
          a.vehicles == b.vehicles && a.trafficLights.size() == b.trafficLights.size()))
        return false;
    // Lights may change their phases and timing (the signal keeps its clock), not where
    // they stand or what they control.
    for (std::size_t k = 0; k < a.trafficLights.size(); ++k) {
        const TrafficLight &x = a.trafficLights[k], &y = b.trafficLights[k];
        if (x.name != y.name || x.position != y.position || !(x.stopLines == y.stopLines))
            return false;
    }
    std::map<std::string, const AgentType*> vehicleTypes;
    for (const AgentType& t : a.agentTypes)
        if (t.kind == AgentKind::Vehicle)
            vehicleTypes[t.name] = &t;
    std::size_t seen = 0;
    for (const AgentType& t : b.agentTypes) {
        if (t.kind != AgentKind::Vehicle)
            continue;
        const auto it = vehicleTypes.find(t.name);
        if (it == vehicleTypes.end() || !(*it->second == t))
            return false;
        ++seen;
    }
    return seen == vehicleTypes.size();
}

namespace {

bool sameCells(const NavGrid& a, const NavGrid& b)
{
    if (a.cellCount() != b.cellCount() || a.cellM() != b.cellM())
        return false;
    if (a.cellCount() == 0)
        return true;
    if (a.centre(a.cellAt(0)) != b.centre(b.cellAt(0)) || a.cols() != b.cols())
        return false;
    for (int i = 0; i < a.cellCount(); ++i)
        if (a.walkableIndex(i) != b.walkableIndex(i))
            return false;
    return true;
}

}  // namespace

WorldState World::saveState() const
{
    WorldState s;
    s.seed = m_seed;
    s.agents = m_agents.info;
#define THRONG_SAVE(member, name, rule) s.name = member;
    THRONG_WHOLE_MEMBERS(THRONG_SAVE)
#undef THRONG_SAVE
#define THRONG_SAVE(name) s.name = m_agents.name;
    THRONG_AGENT_COLUMNS(THRONG_SAVE)
#undef THRONG_SAVE
#define THRONG_SAVE(world, name) s.name = m_nav.world;
    THRONG_NAV_COLUMNS(THRONG_SAVE)
#undef THRONG_SAVE
    if (const detail::WorldBrains* brains = m_brains.runtime()) {
        const detail::WorldBrains& wb = *brains;
        s.hasBrains = true;
        for (const detail::TypeBrain& tb : wb.types)
            s.brainState.push_back(tb.evaluator ? tb.evaluator->stateColumns() : std::vector<std::vector<float>>{});
#define THRONG_SAVE(member, name) s.name = wb.member;
        THRONG_BRAIN_MEMBERS(THRONG_SAVE)
#undef THRONG_SAVE
    }
    return s;
}

void World::restoreState(const WorldState& state)
{
    // Ids may differ: an agent kept through an edit (adoptState) keeps its old id, which
    // a World built from the edited scene gives another member; the checkpoint's count.
    bool same = state.agents.size() == m_agents.info.size() && state.seed == m_seed;
    for (std::size_t i = 0; same && i < m_agents.info.size(); ++i)
        same = state.agents[i].typeIndex == m_agents.info[i].typeIndex;
    if (!same)
        throw std::invalid_argument("restoreState: the checkpoint is of a World with other agents or seed");
    m_agents.info = state.agents;
    restoreDynamicState(state, {});
}

// Everything of the checkpoint, whatever the scene: adoptState puts the edited scene's
// parameters back afterwards.
void World::restoreDynamicState(const WorldState& s, const std::vector<std::uint8_t>& keepBrain)
{
#define THRONG_RESTORE_Plain(member, name) member = s.name;
#define THRONG_RESTORE_Kept(member, name)
#define THRONG_RESTORE(member, name, rule) THRONG_RESTORE_##rule(member, name)
    THRONG_WHOLE_MEMBERS(THRONG_RESTORE)
#undef THRONG_RESTORE
#undef THRONG_RESTORE_Kept
#undef THRONG_RESTORE_Plain
#define THRONG_RESTORE(name) m_agents.name = s.name;
    THRONG_AGENT_COLUMNS(THRONG_RESTORE)
#undef THRONG_RESTORE
    m_sources.rewind();  // agents let in after the checkpoint are off stage again
    m_starts.rewind();   // walkers let go after the checkpoint stand again
    // Kept: the traffic system only into a World that has one (an edit that took every
    // lane and vehicle away leaves none).
    if (m_traffic.system && s.trafficSystem)
        m_traffic.system = s.trafficSystem;
    // Navigation columns exist only in a World with A* or flow-field walkers: when an edit
    // gave or took the last of them, the World keeps its own (fresh legs, plans anew).
    if (s.navMode.size() == m_nav.mode.size()) {
#define THRONG_RESTORE(world, name) m_nav.world = s.name;
        THRONG_NAV_COLUMNS(THRONG_RESTORE)
#undef THRONG_RESTORE
    }
    // Plans are stamped with their grid's generation: on the same cells take the saved grid
    // (and so its generation) with them; on other cells every A* walker plans again.
    if (sameCells(s.navGrid, m_nav.grid)) {
        m_nav.grid = s.navGrid;
        m_nav.cache = s.planCache;
    } else {
        for (std::size_t i = 0; i < m_nav.plan.size(); ++i) {
            m_nav.plan[i] = nullptr;
            m_nav.planGoal[i] = -1;
            m_nav.waypoint[i] = 0;
        }
    }
    // A grid of other cells (an edit changed a perception radius) is rebuilt by the next step.
    const bool sameCells =
        s.grid.fineCellM() == m_grid.fineCellM() && s.grid.sortedByHeight() == m_grid.sortedByHeight();
    if (sameCells)
        m_grid = s.grid;
    m_gridCurrent = sameCells && s.gridCurrent;
    if (!m_brains.active() || !s.hasBrains)
        return;
    detail::WorldBrains& wb = *m_brains.runtime();
    // Brain memory, agent by agent, where the agent's old and new type run programs with
    // the same state columns (adoptState has checked that they are the same brain).
    std::vector<std::vector<std::vector<float>>> columns(wb.types.size());
    for (std::size_t t = 0; t < wb.types.size(); ++t)
        if (wb.types[t].evaluator)
            columns[t] = wb.types[t].evaluator->stateColumns();
    for (std::size_t i = 0; i < m_agents.info.size() && i < s.brainLocal.size() && i < s.brainBatch.size(); ++i) {
        if (s.brainBatch[i] < 0 || wb.batch[i] < 0)
            continue;
        const auto t0 = std::size_t(s.brainBatch[i]), t1 = std::size_t(wb.batch[i]);
        const std::int32_t l0 = s.brainLocal[i], l1 = wb.local[i];
        if ((!keepBrain.empty() && !keepBrain[i]) || l0 < 0 || l1 < 0 || t0 >= s.brainState.size() ||
            s.brainState[t0].size() != columns[t1].size())
            continue;
        for (std::size_t c = 0; c < columns[t1].size(); ++c)
            columns[t1][c][std::size_t(l1)] = s.brainState[t0][c][std::size_t(l0)];
        wb.action[i] = s.brainAction[i];
    }
    for (std::size_t t = 0; t < wb.types.size(); ++t)
        if (wb.types[t].evaluator)
            wb.types[t].evaluator->setStateColumns(columns[t]);
    for (std::size_t k = 0; k < wb.tags.size(); ++k)
        for (std::size_t j = 0; j < s.tags.size(); ++j)
            if (s.tags[j] == wb.tags[k] && s.tagValues[j].size() == wb.tagValues[k].size())
                wb.tagValues[k] = s.tagValues[j];
    if (s.vehicleSpeed.size() == wb.vehicleSpeed.size())
        wb.vehicleSpeed = s.vehicleSpeed;
}

namespace {

struct Declared {
    std::string goal, path;
};

// Each agent's goal and path as its scene declares them, in the World's dense order:
// placed agents, then every group's members, then every source's (vehicles and heroes,
// after them, have none).
std::vector<Declared> declaredLegs(const Scene& scene, std::uint64_t seed)
{
    std::vector<Declared> out;
    for (const Agent& a : scene.agents)
        out.push_back({a.goal, a.path});
    for (const SpawnGroup& g : scene.groups)
        out.insert(out.end(), g.count, Declared{g.goal, g.path});
    const std::vector<std::uint32_t> counts = sourceCounts(scene, seed);
    for (std::size_t s = 0; s < scene.sources.size(); ++s)
        out.insert(out.end(), counts[s], Declared{scene.sources[s].goal, scene.sources[s].path});
    return out;
}

template <typename T>
std::int32_t remapByName(std::int32_t index, const std::vector<T>& from, const std::vector<T>& to)
{
    if (index < 0 || std::size_t(index) >= from.size())
        return -1;
    for (std::size_t k = 0; k < to.size(); ++k)
        if (to[k].name == from[std::size_t(index)].name)
            return std::int32_t(k);
    return -1;
}

// The brain agent i runs: a placed agent's own brain, else its type's.
const BrainGraph* brainOf(const Scene& scene, std::size_t i, std::size_t type)
{
    if (i < scene.agents.size() && !scene.agents[i].brain.empty())
        return scene.findBrain(scene.agents[i].brain);
    const std::string& name = scene.agentTypes[type].brain;
    return name.empty() ? nullptr : scene.findBrain(name);
}

}  // namespace

bool World::adoptState(const WorldState& stateIn, const Scene& stateScene, const Scene& thisScene,
                       std::vector<std::int32_t>* previousOut)
{
    if (stateIn.seed != m_seed || !(stateScene.settings == thisScene.settings))
        return false;
    // Agents by key, not by dense index: an added or removed agent moves the others.
    const std::vector<std::int32_t> previous =
        matchAgents(stateIn.agents, stateScene, m_agents.info, thisScene, m_seed);
    if (previousOut)
        *previousOut = previous;
    bool identity = previous.size() == stateIn.agents.size();
    for (std::size_t i = 0; identity && i < previous.size(); ++i)
        identity = previous[i] == std::int32_t(i);
    // With another agent set, the checkpoint is first laid out in this World's order
    // (new agents as this World built them); from there on the rule is the same.
    WorldState remapped;
    if (!identity)
        remapped = remapState(stateIn, saveState(), previous);
    const WorldState& s = identity ? stateIn : remapped;
    const auto before = [&](std::size_t i) { return identity ? std::int32_t(i) : previous[i]; };
    if (thisScene.trafficLights != stateScene.trafficLights && m_traffic.system && s.trafficSystem &&
        sameTrafficSet(stateScene, thisScene)) {
        // A light's phases or timing changed: the vehicles keep their state and the
        // signal its clock (the step), with the edited timing.
        WorldState retimed = s;
        retimed.trafficSystem->retime(thisScene.trafficLights);
        return adoptMatched(retimed, stateScene, thisScene, before);
    }
    return adoptMatched(s, stateScene, thisScene, before);
}

void World::placeEditedHeroes(const Scene& stateScene, const Scene& thisScene,
                              const std::function<std::int32_t(std::size_t)>& previous)
{
    // A hero the edit added, or whose keyframes it changed, stands where its track puts
    // it now, as the traffic phase leaves every hero after a step (WorldTraffic::drive);
    // a hero kept as it was is where its checkpoint says, which is the same place.
    const double now = double(m_clock.step) * double(m_clock.dt);
    std::size_t k = 0;
    for (const Hero& h : thisScene.heroes) {
        if (h.keyframes.empty())
            continue;  // as built: only heroes with keyframes are agents
        const HeroTrack& track = m_traffic.heroes[k];
        const std::size_t i = m_traffic.heroAgent[k++];
        const auto was = std::find_if(stateScene.heroes.begin(), stateScene.heroes.end(),
                                      [&](const Hero& o) { return o.id == h.id; });
        if (previous(i) >= 0 && was != stateScene.heroes.end() && was->keyframes == h.keyframes)
            continue;
        const glm::vec2 f = track.forwardAt(now);
        m_agents.pos[i] = m_agents.nextPos[i] = m_agents.resolvedPos[i] = track.positionAt(now);
        m_agents.vel[i] = track.velocityAt(now);
        m_agents.fwd[i] = glm::vec3(f.x, 0.0f, f.y);
        m_agents.side[i] = glm::vec3(-f.y, 0.0f, f.x);
    }
}

bool World::adoptMatched(const WorldState& s, const Scene& stateScene, const Scene& thisScene,
                         const std::function<std::int32_t(std::size_t)>& previous)
{
    const std::size_t n = m_agents.info.size();
    std::vector<std::uint8_t> keepBrain(n, 1);
    for (std::size_t i = 0; i < n; ++i) {
        const std::int32_t b = previous(i);
        const BrainGraph* before = b < 0 ? nullptr : brainOf(stateScene, std::size_t(b), s.agents[i].typeIndex);
        const BrainGraph* after = brainOf(thisScene, i, m_agents.info[i].typeIndex);
        keepBrain[i] = before && after && *before == *after ? 1 : 0;
    }
    // The edited scene's parameters and fresh legs, as this World was built.
    const auto radius = m_agents.radius, maxSpeed = m_agents.maxSpeed, stride = m_agents.stride,
               arrivalTime = m_agents.arrivalTime;
    const auto leader = m_agents.leader, goal = m_agents.goal, path = m_agents.path;
    const auto goalSpot = m_agents.goalSpot;
    const auto mode = m_nav.mode;
    const auto waypointRadiusM = m_nav.waypointRadiusM;
    // An edit of the lanes, crosswalks, stop lines, vehicles or vehicle types: the traffic
    // system of the edited scene, with the clock and the kept vehicles' state of the old.
    const bool network = !sameTrafficSet(stateScene, thisScene);
    std::optional<TrafficSystem> edited = network ? m_traffic.system : std::nullopt;
    const std::vector<PedestrianSignal> signal = m_traffic.signal;
    restoreDynamicState(s, keepBrain);
    if (network) {
        m_traffic.system = std::move(edited);
        if (m_traffic.system && s.trafficSystem)
            m_traffic.system->adoptFrom(*s.trafficSystem);
        else if (m_traffic.system)
            m_traffic.system->startAt(m_clock.step);
        // Walkers keep the answer they steered by while the crosswalks stay; else they ask anew.
        if (stateScene.crosswalks != thisScene.crosswalks || m_traffic.signal.size() != signal.size())
            m_traffic.signal = signal;
        // Vehicles stand where their (re-projected or new) lane state puts them, as a step
        // leaves them (WorldTraffic::drive).
        for (std::size_t v = 0; m_traffic.system && v < m_traffic.vehicleAgent.size(); ++v) {
            const TrafficSystem& ts = *m_traffic.system;
            const std::size_t i = m_traffic.vehicleAgent[v];
            const glm::vec2 p = ts.position(v), f = ts.forward(v);
            m_agents.pos[i] = glm::vec3(p.x, m_set.groundHeight(p.x, p.y), p.y);
            m_agents.vel[i] = glm::vec3(f.x, 0.0f, f.y) * (ts.active(v) ? ts.speed(v) : 0.0f);
            m_agents.fwd[i] = glm::vec3(f.x, 0.0f, f.y);
            m_agents.side[i] = glm::vec3(-f.y, 0.0f, f.x);
        }
    }
    placeEditedHeroes(stateScene, thisScene, previous);
    m_agents.radius = radius;
    m_agents.maxSpeed = maxSpeed;
    m_agents.stride = stride;
    m_agents.leader = leader;
    m_nav.waypointRadiusM = waypointRadiusM;
    // A kept agent keeps its id, and with an unchanged type what was drawn by it.
    for (std::size_t i = 0; i < n; ++i) {
        if (previous(i) < 0 || s.agents[i].id == m_agents.info[i].id)
            continue;
        m_agents.info[i].id = s.agents[i].id;
        const std::size_t t0 = s.agents[i].typeIndex, t1 = m_agents.info[i].typeIndex;
        if (t0 < stateScene.agentTypes.size() && t1 < thisScene.agentTypes.size() &&
            stateScene.agentTypes[t0] == thisScene.agentTypes[t1]) {
            m_agents.maxSpeed[i] = s.maxSpeed[i];
            m_agents.stride[i] = s.stride[i];
            if (i < m_nav.waypointRadiusM.size() && i < s.waypointRadiusM.size())
                m_nav.waypointRadiusM[i] = s.waypointRadiusM[i];
        }
    }

    scheduleReactions(thisScene, false);  // by the kept ids; who still stands is the checkpoint's

    const std::vector<Declared> legsBefore = declaredLegs(stateScene, m_seed);
    const std::vector<Declared> legsAfter = declaredLegs(thisScene, m_seed);
    for (std::size_t i = 0; i < n; ++i) {
        const std::int32_t g = remapByName(s.goal[i], stateScene.goals, thisScene.goals);
        const std::int32_t p = remapByName(s.path[i], stateScene.paths, thisScene.paths);
        // A new agent (no previous index) starts as this World built it.
        const std::int32_t b = previous(i);
        const std::size_t j = std::size_t(std::max<std::int32_t>(b, 0));
        const bool declaredSame = j >= legsBefore.size() || i >= legsAfter.size() ||
                                  (legsBefore[j].goal == legsAfter[i].goal && legsBefore[j].path == legsAfter[i].path);
        const bool legKept = b >= 0 && declaredSame && (s.goal[i] < 0) == (g < 0) && (s.path[i] < 0) == (p < 0);
        if (legKept) {
            m_agents.goal[i] = g;
            m_agents.path[i] = p;
        } else {
            m_agents.goal[i] = goal[i];
            m_agents.path[i] = path[i];
            m_agents.goalSpot[i] = goalSpot[i];
            m_agents.arrivalTime[i] = arrivalTime[i];
            m_agents.arrived[i] = m_agents.stopped[i] = m_agents.stoppedBefore[i] = 0;
        }
        // Action points by name: one at a point that the edit removed, or whose leg changed,
        // goes on at once; one at a kept point plays out the time it had left.
        const std::int32_t at =
            legKept ? remapByName(s.pointAt[i], stateScene.actionPoints, thisScene.actionPoints) : -1;
        if (m_agents.pointAt[i] >= 0 && at < 0) {
            m_agents.stopped[i] = m_agents.stoppedBefore[i] = 0;
            m_agents.pointLeftS[i] = 0.0f;
        }
        m_agents.pointAt[i] = at;
        // One still standing out its reaction time goes on standing, whatever its leg; so
        // does a vehicle or hero, new ones too: they are driven, never steered (as built).
        if (m_agents.unstarted[i] || m_traffic.isDriven(i))
            m_agents.stopped[i] = m_agents.stoppedBefore[i] = 1;
        m_agents.pointLast[i] = remapByName(s.pointLast[i], stateScene.actionPoints, thisScene.actionPoints);
        if (i >= mode.size() || i >= m_nav.mode.size() || i >= m_nav.plan.size())
            continue;  // no navigation in this scene (its arrays are empty)
        const bool replans = !legKept || mode[i] != m_nav.mode[i] || !(stateScene.goals == thisScene.goals);
        m_nav.mode[i] = mode[i];
        if (replans) {
            m_nav.plan[i] = nullptr;
            m_nav.planGoal[i] = -1;
            m_nav.waypoint[i] = 0;
        }
    }
    return true;
}

}  // namespace throng::sim
