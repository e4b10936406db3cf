#include "editor/SceneItem.h"

#include <QCoreApplication>

namespace throng::editor {

namespace {

QString tr(const char* text)
{
    return QCoreApplication::translate("SceneItem", text);
}

template <class T>
QString named(const std::vector<T>& list, std::size_t i, const QString& kind)
{
    if (i < list.size() && !list[i].name.empty())
        return QString::fromStdString(list[i].name);
    return QStringLiteral("%1 %2").arg(kind).arg(i + 1);
}

}  // namespace

QString layoutKindTitle(sim::LayoutKind kind)
{
    switch (kind) {
    case sim::LayoutKind::Translate: return tr("Translate");
    case sim::LayoutKind::Rotate: return tr("Rotate");
    case sim::LayoutKind::TimeOffset: return tr("Time offset");
    case sim::LayoutKind::Mirror: return tr("Mirror");
    case sim::LayoutKind::Delete: return tr("Delete");
    case sim::LayoutKind::Expand: return tr("Expand");
    case sim::LayoutKind::Duplicate: return tr("Duplicate");
    case sim::LayoutKind::Swap: return tr("Swap");
    case sim::LayoutKind::ReplaceClip: return tr("Replace clip");
    case sim::LayoutKind::Resolve: return tr("Resolve");
    }
    return {};
}

std::size_t itemCount(const sim::Scene& s, ItemKind kind)
{
    switch (kind) {
    case ItemKind::Settings: return 1;
    case ItemKind::AgentType: return s.agentTypes.size();
    case ItemKind::Group: return s.groups.size();
    case ItemKind::Agent: return s.agents.size();
    case ItemKind::Path: return s.paths.size();
    case ItemKind::Wall: return s.walls.size();
    case ItemKind::Obstacle: return s.obstacles.size();
    case ItemKind::Goal: return s.goals.size();
    case ItemKind::TrafficLight: return s.trafficLights.size();
    case ItemKind::Lane: return s.lanes.size();
    case ItemKind::FlowStroke: return s.flowStrokes.size();
    case ItemKind::Hero: return s.heroes.size();
    case ItemKind::Brain: return s.brains.size();
    case ItemKind::Crosswalk: return s.crosswalks.size();
    case ItemKind::Vehicle: return s.vehicles.size();
    case ItemKind::ActionPoint: return s.actionPoints.size();
    case ItemKind::Source: return s.sources.size();
    case ItemKind::Measurement: return s.measurements.size();
    case ItemKind::LayoutOp: return s.layout.ops.size();
    }
    return 0;
}

QString kindTitle(ItemKind kind)
{
    switch (kind) {
    case ItemKind::Settings: return tr("Settings");
    case ItemKind::AgentType: return tr("Agent Types");
    case ItemKind::Group: return tr("Groups");
    case ItemKind::Agent: return tr("Agents");
    case ItemKind::Path: return tr("Paths");
    case ItemKind::Wall: return tr("Walls");
    case ItemKind::Obstacle: return tr("Obstacles");
    case ItemKind::Goal: return tr("Goals");
    case ItemKind::TrafficLight: return tr("Traffic Lights");
    case ItemKind::Lane: return tr("Lanes");
    case ItemKind::FlowStroke: return tr("Flow Strokes");
    case ItemKind::Hero: return tr("Heroes");
    case ItemKind::Brain: return tr("Brains");
    case ItemKind::Crosswalk: return tr("Crosswalks");
    case ItemKind::Vehicle: return tr("Vehicles");
    case ItemKind::ActionPoint: return tr("Action Points");
    case ItemKind::Source: return tr("Sources");
    case ItemKind::Measurement: return tr("Measurements");
    case ItemKind::LayoutOp: return tr("Layout");
    }
    return {};
}

QString itemLabel(const sim::Scene& s, SceneItem item)
{
    const std::size_t i = item.index;
    switch (item.kind) {
    case ItemKind::Settings: return tr("Simulation Settings");
    case ItemKind::AgentType: return named(s.agentTypes, i, tr("Type"));
    case ItemKind::Group: return named(s.groups, i, tr("Group"));
    case ItemKind::Agent:
        return i < s.agents.size() ? tr("Agent %1 (%2)").arg(s.agents[i].id).arg(QString::fromStdString(s.agents[i].type))
                                   : QString();
    case ItemKind::Path: return named(s.paths, i, tr("Path"));
    case ItemKind::Wall: return named(s.walls, i, tr("Wall"));
    case ItemKind::Obstacle: return named(s.obstacles, i, tr("Obstacle"));
    case ItemKind::Goal: return named(s.goals, i, tr("Goal"));
    case ItemKind::TrafficLight: return named(s.trafficLights, i, tr("Light"));
    case ItemKind::Lane: return named(s.lanes, i, tr("Lane"));
    case ItemKind::FlowStroke:
        return i < s.flowStrokes.size() ? tr("Flow stroke %1 (%2 m wide)").arg(i + 1).arg(double(s.flowStrokes[i].widthM))
                                        : QString();
    case ItemKind::Hero: return named(s.heroes, i, tr("Hero"));
    case ItemKind::Brain: return named(s.brains, i, tr("Brain"));
    case ItemKind::Crosswalk: return named(s.crosswalks, i, tr("Crosswalk"));
    case ItemKind::Vehicle:
        if (i >= s.vehicles.size())
            return QString();
        // Vehicles carry no name: the number, type and lane tell them apart.
        return tr("Vehicle %1 (%2 on %3)")
            .arg(i + 1)
            .arg(QString::fromStdString(s.vehicles[i].type), QString::fromStdString(s.vehicles[i].lane));
    case ItemKind::ActionPoint: return named(s.actionPoints, i, tr("Action point"));
    case ItemKind::Source: return named(s.sources, i, tr("Source"));
    case ItemKind::Measurement: return named(s.measurements, i, tr("Measurement"));
    case ItemKind::LayoutOp:
        // An unnamed operation by what it does and where it stands in the layer: "Translate 2".
        return i < s.layout.ops.size() ? named(s.layout.ops, i, layoutKindTitle(s.layout.ops[i].kind)) : QString();
    }
    return {};
}

std::optional<SceneItem> itemForKey(const std::string& key)
{
    static const std::pair<const char*, ItemKind> kLists[] = {
        {"agent_types", ItemKind::AgentType}, {"groups", ItemKind::Group},   {"agents", ItemKind::Agent},
        {"paths", ItemKind::Path},             {"walls", ItemKind::Wall},     {"obstacles", ItemKind::Obstacle},
        {"goals", ItemKind::Goal},             {"traffic_lights", ItemKind::TrafficLight},
        {"lanes", ItemKind::Lane},             {"heroes", ItemKind::Hero},    {"brains", ItemKind::Brain},
        {"flow_strokes", ItemKind::FlowStroke}, {"crosswalks", ItemKind::Crosswalk},
        {"vehicles", ItemKind::Vehicle},       {"action_points", ItemKind::ActionPoint},
        {"sources", ItemKind::Source},         {"measurements", ItemKind::Measurement},
        {"layout", ItemKind::LayoutOp}};
    if (key.rfind("settings", 0) == 0)
        return SceneItem{ItemKind::Settings, 0};
    const std::size_t open = key.find('['), close = key.find(']');
    if (open == std::string::npos || close == std::string::npos || close <= open + 1)
        return std::nullopt;
    const std::string list = key.substr(0, open), digits = key.substr(open + 1, close - open - 1);
    if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9)
        return std::nullopt;
    for (const auto& [name, kind] : kLists)
        if (list == name)
            return SceneItem{kind, std::size_t(std::stoul(digits))};
    return std::nullopt;
}

}  // namespace throng::editor
