#include "simcore/world/GeometryCheck.h"

#include "simcore/nav/NavReach.h"
#include "simcore/scene/SceneOrigin.h"
#include "simcore/world/World.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <map>
#include <utility>

namespace throng::sim {

namespace {

// A scene file's float is held this finely at most before check warns (m).
constexpr double kFineSpacingM = 0.01;
// Agents listed by id in one warning, at most.
constexpr std::size_t kNamedAgents = 6;

std::string metres(double v)
{
    char buf[48];
    if (std::fabs(v) < 1.0 && v != 0.0) {
        std::snprintf(buf, sizeof buf, "%.3g", v);
        return buf;
    }
    std::snprintf(buf, sizeof buf, "%.2f", v);
    std::string out = buf;
    while (out.back() == '0')
        out.pop_back();
    if (out.back() == '.')
        out.pop_back();
    return out;
}

std::string point(glm::vec2 p, glm::dvec2 origin)
{
    std::string out = "(";
    out += metres(double(p.x) + origin.x);
    out += ", ";
    out += metres(double(p.y) + origin.y);
    out += ')';
    return out;
}

// Where each World agent came from: a placed agent (its index in scene.agents) or a member
// of a spawned group; vehicles and heroes are neither (-1, -1). Ids as World gives them.
struct Origins {
    std::map<AgentId, std::size_t> placed;
    std::vector<std::pair<AgentId, AgentId>> groupIds;  // per group, [first, last)
    std::ptrdiff_t groupOf(AgentId id) const
    {
        for (std::size_t g = 0; g < groupIds.size(); ++g)
            if (id >= groupIds[g].first && id < groupIds[g].second)
                return std::ptrdiff_t(g);
        return -1;
    }
};

Origins originsOf(const Scene& scene)
{
    Origins o;
    for (std::size_t k = 0; k < scene.agents.size(); ++k)
        o.placed[scene.agents[k].id] = k;
    // Spawned agents take ids after every id the scene uses (World::buildAgents).
    AgentId next = 1;
    for (const Agent& a : scene.agents) next = std::max(next, a.id + 1);
    for (const Vehicle& v : scene.vehicles) next = std::max(next, v.id + 1);
    for (const Hero& h : scene.heroes) next = std::max(next, h.id + 1);
    for (const SpawnGroup& g : scene.groups) {
        o.groupIds.emplace_back(next, next + g.count);
        next += g.count;
    }
    return o;
}

void precision(const Scene& scene, const std::string& file, std::vector<Diagnostic>& out)
{
    const double spacing = coordinateSpacingM(scene);
    const glm::dvec2 origin = simulationOrigin(scene);
    if (spacing > kFineSpacingM)
        out.push_back({Severity::Warning, file, 0, 0, "settings.bounds",
                       "coordinates this far from (0, 0) are held in the scene file only to " + metres(spacing) +
                           " m (32-bit floats): walls, obstacles, goals, paths and placed agents snap to that "
                           "spacing; the run itself is simulated relative to the scene's centre " +
                           point(glm::vec2(0.0f), origin) + " and loses nothing more"});
    // Relative to that centre, the set's far corners: agents out there move in rounded steps.
    const glm::vec2 lo = scene.settings.boundsMin, hi = scene.settings.boundsMax;
    const double reach = std::max({std::fabs(double(lo.x) - origin.x), std::fabs(double(hi.x) - origin.x),
                                   std::fabs(double(lo.y) - origin.y), std::fabs(double(hi.y) - origin.y)});
    if (reach > kFarSceneM) {
        const float r = float(reach);
        const double step = double(std::nextafter(r, INFINITY) - r);
        out.push_back({Severity::Warning, file, 0, 0, "settings.bounds",
                       "the bounds reach " + metres(reach) + " m from their centre; agents farther than " +
                           metres(kFarSceneM) + " m from it move in steps rounded to up to " + metres(step) +
                           " m (split a set this large into scenes of its parts)"});
    }
}

void startsInside(const Scene& scene, const World& world, const Origins& origins, const std::string& file,
                  std::vector<Diagnostic>& out)
{
    const glm::dvec2 origin(world.origin().x, world.origin().z);
    std::vector<std::size_t> groupInside(scene.groups.size(), 0), groupFirst(scene.groups.size(), 0);
    for (std::size_t i = 0; i < world.agentCount(); ++i) {
        if (!world.isEscaping(i))
            continue;
        const glm::vec2 p(world.positions()[i].x, world.positions()[i].z), to = world.escapeTo(i);
        if (const auto it = origins.placed.find(world.id(i)); it != origins.placed.end()) {
            out.push_back({Severity::Warning, file, 0, 0, "agents[" + std::to_string(it->second) + "]",
                           "agent " + std::to_string(world.id(i)) + " starts inside a wall or obstacle at " +
                               point(p, origin) + "; the run walks it " + metres(glm::distance(p, to)) +
                               " m out to " + point(to, origin) + " at its own pace before it moves on"});
        } else if (const std::ptrdiff_t g = origins.groupOf(world.id(i)); g >= 0) {
            if (groupInside[std::size_t(g)]++ == 0)
                groupFirst[std::size_t(g)] = i;
        }
    }
    for (std::size_t g = 0; g < scene.groups.size(); ++g) {
        if (groupInside[g] == 0)
            continue;
        const glm::vec3 p = world.positions()[groupFirst[g]];
        out.push_back({Severity::Warning, file, 0, 0, "groups[" + std::to_string(g) + "]",
                       std::to_string(groupInside[g]) + " of " + std::to_string(scene.groups[g].count) +
                           " members of group '" + scene.groups[g].name +
                           "' spawn inside walls or obstacles (the first at " + point({p.x, p.z}, origin) +
                           "); the run walks each out along the shortest way at its own pace"});
    }
}

void reachability(const Scene& scene, const World& world, const Origins& origins, const std::string& file,
                  std::vector<Diagnostic>& out)
{
    const Scene local =
        world.origin() == glm::dvec3(0.0) ? Scene{} : shiftedScene(scene, {world.origin().x, world.origin().z});
    const Scene& s = world.origin() == glm::dvec3(0.0) ? scene : local;
    // One grid per body radius that has somewhere to go; walkers only (fliers fly over the
    // set, vehicles keep to lanes).
    std::map<float, NavReach> grids;
    std::map<std::pair<std::int32_t, std::uint16_t>, std::vector<std::size_t>> stranded;  // (goal, type) -> agents
    const NavShapes shapes = navShapes(s);
    const glm::vec2 lo = s.settings.boundsMin, hi = s.settings.boundsMax;
    auto gridFor = [&](float radius) -> const NavReach& {
        auto it = grids.find(radius);
        if (it == grids.end()) {
            it = grids.emplace(radius, NavReach{}).first;
            it->second.build(shapes, lo, hi, radius, NavReach::cellFor(lo, hi, std::min(0.1f, 0.5f * radius)));
        }
        return it->second;
    };
    std::vector<std::uint8_t> warnedGoal(s.goals.size(), 0);
    for (std::size_t i = 0; i < world.agentCount(); ++i) {
        const std::int32_t g = world.goalIndex(i);
        const AgentInfo& info = world.agentInfo()[i];
        const AgentType& type = s.agentTypes[info.typeIndex];
        if (g < 0 || type.kind != AgentKind::Pedestrian || world.isDriven(i))
            continue;
        // Followers of a path or a leader go where those lead, not to their goal.
        const AgentId id = world.id(i);
        if (const auto it = origins.placed.find(id); it != origins.placed.end()) {
            const Agent& a = s.agents[it->second];
            if (!a.path.empty() || a.leader != 0)
                continue;
        } else if (const std::ptrdiff_t grp = origins.groupOf(id); grp >= 0) {
            const SpawnGroup& sg = s.groups[std::size_t(grp)];
            if (!sg.path.empty() || sg.leader != 0)
                continue;
        }
        const Goal& goal = s.goals[std::size_t(g)];
        const NavReach& reach = gridFor(type.radiusM);
        if (!reach.enterable(goal.position, goal.radiusM)) {
            if (!warnedGoal[std::size_t(g)]) {
                warnedGoal[std::size_t(g)] = 1;
                out.push_back({Severity::Warning, file, 0, 0, "goals[" + std::to_string(g) + "]",
                               std::string(goal.exit ? "exit '" : "goal '") + goal.name +
                                   "' cannot be reached by a body of radius " + metres(type.radiusM) +
                                   " m (type '" + type.name + "'): no place within its radius is that clear of "
                                   "walls and obstacles" + (goal.exit ? " (is its door narrower than " +
                                   metres(2.0 * type.radiusM) + " m?)" : std::string()) +
                                   "; its agents will not get there"});
            }
            continue;
        }
        const glm::vec2 from =
            world.isEscaping(i) ? world.escapeTo(i) : glm::vec2(world.positions()[i].x, world.positions()[i].z);
        if (!reach.reaches(from, goal.position, goal.radiusM))
            stranded[{g, info.typeIndex}].push_back(i);
    }
    for (const auto& [key, agents] : stranded) {
        const Goal& goal = s.goals[std::size_t(key.first)];
        const AgentType& type = s.agentTypes[key.second];
        std::string who;
        std::vector<std::size_t> perGroup(s.groups.size(), 0);
        std::size_t named = 0;
        for (std::size_t i : agents) {
            const AgentId id = world.id(i);
            if (origins.placed.count(id)) {
                if (named++ < kNamedAgents)
                    who += (who.empty() ? "agent " : ", ") + std::to_string(id);
            } else if (const std::ptrdiff_t grp = origins.groupOf(id); grp >= 0) {
                ++perGroup[std::size_t(grp)];
            }
        }
        if (named > kNamedAgents)
            who += " and " + std::to_string(named - kNamedAgents) + " more placed agents";
        for (std::size_t grp = 0; grp < perGroup.size(); ++grp)
            if (perGroup[grp] > 0)
                who += (who.empty() ? "" : "; ") + std::to_string(perGroup[grp]) + " of group '" + s.groups[grp].name +
                       "'";
        const std::string how = type.navigation == Navigation::AStar       ? "A* walkers wait where they stand"
                                : type.navigation == Navigation::FlowField ? "flow-field walkers wait where they stand"
                                                                           : "they walk at it and stay short of it";
        out.push_back({Severity::Warning, file, 0, 0, "goals[" + std::to_string(key.first) + "]",
                       std::string(goal.exit ? "exit '" : "goal '") + goal.name + "' cannot be reached by " +
                           std::to_string(agents.size()) + " agents of type '" + type.name + "' (" + who +
                           "): walls or obstacles close it off from where they start; " + how});
    }
}

}  // namespace

std::vector<Diagnostic> checkSceneGeometry(const Scene& scene, const std::string& file)
{
    std::vector<Diagnostic> out;
    precision(scene, file, out);
    WorldOptions options;
    options.threads = 1;
    try {
        const World world(scene, options);
        const Origins origins = originsOf(scene);
        startsInside(scene, world, origins, file, out);
        reachability(scene, world, origins, file, out);
    } catch (const std::exception& e) {
        // The run would fail the same way; `run` reports it. The checks above still hold.
        out.push_back(
            {Severity::Warning, file, 0, 0, "", std::string("cannot build the run's initial state: ") + e.what()});
    }
    return out;
}

}  // namespace throng::sim
