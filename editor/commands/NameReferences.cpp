#include "editor/commands/NameReferences.h"

#include <QCoreApplication>

namespace throng::editor {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("NameReferences", text);
}

using FieldOf = std::string& (*)(sim::Scene&, std::size_t);

// How a message names the item that refers: "group nw_walkers", "Agent 4 (walker)".
QString userName(const sim::Scene& scene, SceneItem user)
{
    const QString label = itemLabel(scene, user);
    switch (user.kind) {
    case ItemKind::Group: return tr("group %1").arg(label);
    case ItemKind::Hero: return tr("hero %1").arg(label);
    case ItemKind::AgentType: return tr("agent type %1").arg(label);
    case ItemKind::Source: return tr("source %1").arg(label);
    default: return label;
    }
}

// Adds a use for every index of a list of `count` items whose field is `name`.
void collect(std::vector<NameUse>& out, const sim::Scene& scene, std::size_t count, const std::string& name,
             ItemKind userKind, FieldOf field)
{
    auto& readable = const_cast<sim::Scene&>(scene);  // read only: nothing is written here
    for (std::size_t i = 0; i < count; ++i) {
        if (field(readable, i) != name)
            continue;
        const SceneItem user{userKind, i};
        out.push_back({[field, i](sim::Scene& s) -> std::string& { return field(s, i); }, user,
                       userName(scene, user)});
    }
}

// The stop lines whose `field` (lane or crosswalk) is `name`.
void collectStopLines(std::vector<NameUse>& out, const sim::Scene& scene, const std::string& name,
                      std::string sim::StopLine::*field)
{
    for (std::size_t l = 0; l < scene.trafficLights.size(); ++l)
        for (std::size_t k = 0; k < scene.trafficLights[l].stopLines.size(); ++k)
            if (scene.trafficLights[l].stopLines[k].*field == name)
                out.push_back({[l, k, field](sim::Scene& s) -> std::string& { return s.trafficLights[l].stopLines[k].*field; },
                               SceneItem{ItemKind::TrafficLight, l},
                               tr("the stop line of traffic light %1").arg(itemLabel(scene, {ItemKind::TrafficLight, l}))});
}

void collectVehicles(std::vector<NameUse>& out, const sim::Scene& scene, const std::string& name, FieldOf field)
{
    auto& readable = const_cast<sim::Scene&>(scene);
    for (std::size_t i = 0; i < scene.vehicles.size(); ++i)
        if (field(readable, i) == name)
            out.push_back({[field, i](sim::Scene& s) -> std::string& { return field(s, i); },
                           SceneItem{ItemKind::Vehicle, i}, tr("vehicle %1").arg(i + 1)});
}

// The action points whose `types` list holds `name`.
void collectActionPointTypes(std::vector<NameUse>& out, const sim::Scene& scene, const std::string& name)
{
    for (std::size_t p = 0; p < scene.actionPoints.size(); ++p)
        for (std::size_t k = 0; k < scene.actionPoints[p].types.size(); ++k)
            if (scene.actionPoints[p].types[k] == name)
                out.push_back({[p, k](sim::Scene& s) -> std::string& { return s.actionPoints[p].types[k]; },
                               SceneItem{ItemKind::ActionPoint, p},
                               tr("action point %1").arg(itemLabel(scene, {ItemKind::ActionPoint, p}))});
}

// The sources whose mix of types holds `name`.
void collectSourceTypes(std::vector<NameUse>& out, const sim::Scene& scene, const std::string& name)
{
    for (std::size_t p = 0; p < scene.sources.size(); ++p)
        for (std::size_t k = 0; k < scene.sources[p].types.size(); ++k)
            if (scene.sources[p].types[k].type == name)
                out.push_back({[p, k](sim::Scene& s) -> std::string& { return s.sources[p].types[k].type; },
                               SceneItem{ItemKind::Source, p}, userName(scene, {ItemKind::Source, p})});
}

// The layout operations whose selector names `name` among its groups or types (`list`).
void collectLayoutNames(std::vector<NameUse>& out, const sim::Scene& scene, const std::string& name,
                        std::vector<std::string> sim::AgentSelector::*list)
{
    for (std::size_t o = 0; o < scene.layout.ops.size(); ++o) {
        const std::vector<std::string>& names = scene.layout.ops[o].agents.*list;
        for (std::size_t k = 0; k < names.size(); ++k)
            if (names[k] == name)
                out.push_back({[o, k, list](sim::Scene& s) -> std::string& { return (s.layout.ops[o].agents.*list)[k]; },
                               SceneItem{ItemKind::LayoutOp, o},
                               tr("layout operation %1").arg(itemLabel(scene, {ItemKind::LayoutOp, o}))});
    }
}

}  // namespace

bool hasName(ItemKind kind)
{
    return kind != ItemKind::Settings && kind != ItemKind::Agent && kind != ItemKind::FlowStroke &&
           kind != ItemKind::Vehicle;
}

std::function<std::string&(sim::Scene&)> nameLocate(SceneItem item)
{
    const std::size_t i = item.index;
    switch (item.kind) {
    case ItemKind::AgentType: return [i](sim::Scene& s) -> std::string& { return s.agentTypes[i].name; };
    case ItemKind::Group: return [i](sim::Scene& s) -> std::string& { return s.groups[i].name; };
    case ItemKind::Path: return [i](sim::Scene& s) -> std::string& { return s.paths[i].name; };
    case ItemKind::Wall: return [i](sim::Scene& s) -> std::string& { return s.walls[i].name; };
    case ItemKind::Obstacle: return [i](sim::Scene& s) -> std::string& { return s.obstacles[i].name; };
    case ItemKind::Goal: return [i](sim::Scene& s) -> std::string& { return s.goals[i].name; };
    case ItemKind::TrafficLight: return [i](sim::Scene& s) -> std::string& { return s.trafficLights[i].name; };
    case ItemKind::Lane: return [i](sim::Scene& s) -> std::string& { return s.lanes[i].name; };
    case ItemKind::Hero: return [i](sim::Scene& s) -> std::string& { return s.heroes[i].name; };
    case ItemKind::Brain: return [i](sim::Scene& s) -> std::string& { return s.brains[i].name; };
    case ItemKind::Crosswalk: return [i](sim::Scene& s) -> std::string& { return s.crosswalks[i].name; };
    case ItemKind::ActionPoint: return [i](sim::Scene& s) -> std::string& { return s.actionPoints[i].name; };
    case ItemKind::Source: return [i](sim::Scene& s) -> std::string& { return s.sources[i].name; };
    case ItemKind::Measurement: return [i](sim::Scene& s) -> std::string& { return s.measurements[i].name; };
    case ItemKind::LayoutOp: return [i](sim::Scene& s) -> std::string& { return s.layout.ops[i].name; };
    default: return {};
    }
}

std::string nameOf(const sim::Scene& scene, SceneItem item)
{
    const auto locate = nameLocate(item);
    return locate ? locate(const_cast<sim::Scene&>(scene)) : std::string();
}

std::vector<std::string> namesOf(const sim::Scene& scene, ItemKind kind)
{
    std::vector<std::string> names;
    if (!hasName(kind))
        return names;
    for (std::size_t i = 0; i < itemCount(scene, kind); ++i)
        names.push_back(nameOf(scene, {kind, i}));
    return names;
}

std::vector<NameUse> nameUses(const sim::Scene& scene, ItemKind kind, const std::string& name)
{
    std::vector<NameUse> out;
    if (name.empty())
        return out;
    switch (kind) {
    case ItemKind::AgentType:
        collect(out, scene, scene.agents.size(), name, ItemKind::Agent,
                [](sim::Scene& s, std::size_t i) -> std::string& { return s.agents[i].type; });
        collect(out, scene, scene.groups.size(), name, ItemKind::Group,
                [](sim::Scene& s, std::size_t i) -> std::string& { return s.groups[i].type; });
        collect(out, scene, scene.heroes.size(), name, ItemKind::Hero,
                [](sim::Scene& s, std::size_t i) -> std::string& { return s.heroes[i].type; });
        collectVehicles(out, scene, name, [](sim::Scene& s, std::size_t i) -> std::string& { return s.vehicles[i].type; });
        collectActionPointTypes(out, scene, name);
        collectSourceTypes(out, scene, name);
        collectLayoutNames(out, scene, name, &sim::AgentSelector::types);
        break;
    case ItemKind::Group: collectLayoutNames(out, scene, name, &sim::AgentSelector::groups); break;
    case ItemKind::Brain:
        collect(out, scene, scene.agentTypes.size(), name, ItemKind::AgentType,
                [](sim::Scene& s, std::size_t i) -> std::string& { return s.agentTypes[i].brain; });
        collect(out, scene, scene.agents.size(), name, ItemKind::Agent,
                [](sim::Scene& s, std::size_t i) -> std::string& { return s.agents[i].brain; });
        break;
    case ItemKind::Path:
        collect(out, scene, scene.groups.size(), name, ItemKind::Group,
                [](sim::Scene& s, std::size_t i) -> std::string& { return s.groups[i].path; });
        collect(out, scene, scene.agents.size(), name, ItemKind::Agent,
                [](sim::Scene& s, std::size_t i) -> std::string& { return s.agents[i].path; });
        collect(out, scene, scene.sources.size(), name, ItemKind::Source,
                [](sim::Scene& s, std::size_t i) -> std::string& { return s.sources[i].path; });
        break;
    case ItemKind::Goal:
        collect(out, scene, scene.groups.size(), name, ItemKind::Group,
                [](sim::Scene& s, std::size_t i) -> std::string& { return s.groups[i].goal; });
        collect(out, scene, scene.agents.size(), name, ItemKind::Agent,
                [](sim::Scene& s, std::size_t i) -> std::string& { return s.agents[i].goal; });
        collect(out, scene, scene.sources.size(), name, ItemKind::Source,
                [](sim::Scene& s, std::size_t i) -> std::string& { return s.sources[i].goal; });
        break;
    case ItemKind::Lane:
        collectVehicles(out, scene, name, [](sim::Scene& s, std::size_t i) -> std::string& { return s.vehicles[i].lane; });
        collectStopLines(out, scene, name, &sim::StopLine::lane);
        break;
    case ItemKind::Crosswalk: collectStopLines(out, scene, name, &sim::StopLine::crosswalk); break;
    default:
        break;
    }
    return out;
}

SceneChange renameChange(SceneItem item, const std::vector<NameUse>& uses)
{
    const SceneField reference = item.kind == ItemKind::AgentType ? SceneField::Type
                                 : item.kind == ItemKind::Brain   ? SceneField::Brain
                                                                  : SceneField::Route;
    SceneChange change = SceneChange::of(item, SceneField::Name);
    for (const NameUse& use : uses) {
        if (use.user) {
            change |= SceneChange::of(*use.user, reference);
        } else {
            // A reference held by nothing listed: say only that the simulation reads it.
            change.fields |= fieldBit(reference);
            change.simulationReads = true;
        }
    }
    return change;
}

std::vector<LeaderUse> leaderUses(const sim::Scene& scene, std::uint32_t id)
{
    std::vector<LeaderUse> out;
    if (id == 0)
        return out;
    for (std::size_t i = 0; i < scene.agents.size(); ++i)
        if (scene.agents[i].leader == id)
            out.push_back({[i](sim::Scene& s) -> std::uint32_t& { return s.agents[i].leader; }, {ItemKind::Agent, i}});
    for (std::size_t i = 0; i < scene.groups.size(); ++i)
        if (scene.groups[i].leader == id)
            out.push_back({[i](sim::Scene& s) -> std::uint32_t& { return s.groups[i].leader; }, {ItemKind::Group, i}});
    return out;
}

}  // namespace throng::editor
