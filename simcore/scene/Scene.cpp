#include "simcore/scene/Scene.h"

#include "simcore/scene/BehaviourTable.h"

#include <algorithm>

namespace throng::sim {

namespace {
template <typename T>
const T* findByName(const std::vector<T>& items, const std::string& name)
{
    auto it = std::find_if(items.begin(), items.end(), [&](const T& t) { return t.name == name; });
    return it == items.end() ? nullptr : &*it;
}
}  // namespace

const AgentType* Scene::findAgentType(const std::string& name) const { return findByName(agentTypes, name); }
const Goal* Scene::findGoal(const std::string& name) const { return findByName(goals, name); }
const Path* Scene::findPath(const std::string& name) const { return findByName(paths, name); }
const Lane* Scene::findLane(const std::string& name) const { return findByName(lanes, name); }
const Crosswalk* Scene::findCrosswalk(const std::string& name) const { return findByName(crosswalks, name); }
const BrainGraph* Scene::findBrain(const std::string& name) const { return findByName(brains, name); }

namespace {

bool picksGoals(const Scene& scene, const BrainGraph* brain, int depth)
{
    if (!brain || depth > 16)  // a macro that uses itself is the compiler's error, not a loop here
        return false;
    for (const BrainNode& n : brain->nodes) {
        if (n.type == "output.goal")
            return true;
        if (n.type == "macro")
            for (const BrainParam& p : n.params)
                if (p.key == "brain" && picksGoals(scene, scene.findBrain(p.text), depth + 1))
                    return true;
    }
    return false;
}

}  // namespace

bool Scene::brainPicksGoals(const std::string& type) const
{
    const AgentType* t = findAgentType(type);
    return t && !t->brain.empty() && picksGoals(*this, findBrain(t->brain), 0);
}

const BrainNode* BrainGraph::findNode(NodeId id) const
{
    auto it = std::find_if(nodes.begin(), nodes.end(), [&](const BrainNode& n) { return n.id == id; });
    return it == nodes.end() ? nullptr : &*it;
}

const std::vector<std::string>& behaviourNames()
{
    // In priority order: the most urgent first (BehaviourTable.h).
    static const std::vector<std::string> names = [] {
        std::vector<std::string> v;
        for (const BehaviourEntry& e : kBehaviourTable)
            v.emplace_back(e.name);
        return v;
    }();
    return names;
}

const std::vector<std::string>& builtinCharacters()
{
    static const std::vector<std::string> names{"man", "woman", "tall_man", "child", "elderly", "horse", "car", "bird"};
    return names;
}

const char* toString(AgentKind kind)
{
    switch (kind) {
    case AgentKind::Pedestrian: return "pedestrian";
    case AgentKind::Vehicle: return "vehicle";
    case AgentKind::Flier: return "flier";
    }
    return "pedestrian";
}

const char* toString(Navigation navigation)
{
    switch (navigation) {
    case Navigation::Direct: return "direct";
    case Navigation::AStar: return "astar";
    case Navigation::FlowField: return "flow_field";
    }
    return "direct";
}

std::uint32_t firstSpawnedId(const Scene& scene)
{
    std::uint32_t next = 1;
    for (const Agent& a : scene.agents)
        next = std::max(next, a.id + 1);
    for (const Vehicle& v : scene.vehicles)
        next = std::max(next, v.id + 1);
    for (const Hero& h : scene.heroes)
        next = std::max(next, h.id + 1);
    return next;
}

const char* toString(Arrivals arrivals)
{
    return arrivals == Arrivals::Poisson ? "poisson" : "steady";
}

const char* toString(FormationShape shape)
{
    switch (shape) {
    case FormationShape::Line: return "line";
    case FormationShape::Column: return "column";
    case FormationShape::Wedge: return "wedge";
    case FormationShape::None: break;
    }
    return "none";
}

const char* toString(MeasurementShape shape)
{
    return shape == MeasurementShape::Area ? "area" : "line";
}

const char* toString(AreaShape shape)
{
    switch (shape) {
    case AreaShape::Circle: return "circle";
    case AreaShape::Polygon: return "polygon";
    case AreaShape::Rect: break;
    }
    return "rect";
}
const char* toString(ObstacleShape shape) { return shape == ObstacleShape::Box ? "box" : "circle"; }

const char* toString(CarFollowing model)
{
    switch (model) {
    case CarFollowing::Inherit: return "inherit";
    case CarFollowing::Idm: return "idm";
    case CarFollowing::GapTime: return "gap_time";
    case CarFollowing::Fuzzy: return "fuzzy";
    }
    return "inherit";
}

CarFollowing carFollowingOf(const Scene& scene, const Lane* lane, const AgentType* type)
{
    if (lane && lane->carFollowing != CarFollowing::Inherit)
        return lane->carFollowing;
    if (type && type->carFollowing != CarFollowing::Inherit)
        return type->carFollowing;
    return scene.traffic.carFollowing == CarFollowing::Inherit ? CarFollowing::Idm : scene.traffic.carFollowing;
}

}  // namespace throng::sim
