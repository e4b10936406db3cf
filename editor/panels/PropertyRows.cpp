#include "editor/panels/PropertyRows.h"

#include "editor/commands/NameReferences.h"
#include "editor/panels/BehaviourTable.h"
#include "editor/panels/PointTable.h"
#include "editor/panels/StopLineTable.h"
#include "editor/panels/PropertyForm.h"
#include "editor/SpawnPolygonCheck.h"
#include "simcore/scene/Clip.h"
#include "simcore/scene/GroundPolygon.h"
#include "simcore/scene/SpawnArea.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <set>

namespace throng::editor {

namespace {

QString tr(const char* text)
{
    return PropertyForm::tr(text);
}

PropertyForm::Options namesOfKind(ItemKind kind)
{
    return [kind](const sim::Scene& s) {
        QStringList out;
        for (const std::string& name : namesOf(s, kind))
            out << QString::fromStdString(name);
        return out;
    };
}

// The agents' groups (Agent::group): free names, listed as the scene uses them.
QStringList agentGroups(const sim::Scene& s)
{
    std::set<std::string> names;
    for (const sim::Agent& a : s.agents)
        if (!a.group.empty())
            names.insert(a.group);
    QStringList out;
    for (const std::string& name : names)
        out << QString::fromStdString(name);
    return out;
}

// sim::CarFollowing's values, in its order.
QStringList carFollowingNames()
{
    return {tr("Inherit"), tr("IDM"), tr("Gap time"), tr("Fuzzy rules")};
}

// The actions an action point may play: every clip but idle, walk and run.
QStringList actionPointActions()
{
    QStringList out;
    for (int c = int(sim::Clip::Wait); c < sim::kClipCount; ++c)
        out << QString::fromUtf8(sim::toString(sim::Clip(c)));
    return out;
}

void addPoints(PropertyForm& form, PropertyForm::Locate<PointTable::Points> locate)
{
    auto* table = new PointTable(form, std::move(locate), form.owner());
    form.addRow(tr("Points"), table, [table] { table->refresh(); });
}

sim::SpawnGroup withAreaShape(const sim::SpawnGroup& now, sim::AreaShape shape)
{
    sim::SpawnGroup next = now;
    next.shape = shape;
    if (next.shape == now.shape)
        return next;
    const sim::GroundBounds box = sim::spawnAreaBounds(now);
    const glm::vec2 middle = 0.5f * (box.min + box.max), extent = box.max - box.min;
    next.points.clear();
    if (shape == sim::AreaShape::Circle) {
        next.center = middle;
        next.radiusM = std::max(0.5f, 0.5f * std::min(extent.x, extent.y));
    } else if (shape == sim::AreaShape::Rect) {
        next.min = box.min;
        next.max = box.max;
    } else if (now.shape == sim::AreaShape::Circle) {
        constexpr int kSides = 12;
        for (int k = 0; k < kSides; ++k) {
            const float a = 6.28318531f * float(k) / float(kSides);
            next.points.push_back(now.center + now.radiusM * glm::vec2(std::cos(a), std::sin(a)));
        }
    } else {
        next.points = {now.min, {now.max.x, now.min.y}, now.max, {now.min.x, now.max.y}};
    }
    return next;
}

}  // namespace

#define THRONG_AT(list, member) [](sim::Scene& s, std::size_t i) -> auto& { return s.list[i].member; }

namespace {

// A measurement's kind and size, and its points: a line's two ends, or an area's corners
// (kept a simple polygon). Lines and areas selected together show neither table.
void addMeasurementRows(PropertyForm& form)
{
    form.addInfo("measures", tr("Measures"), [](const sim::Scene& s, std::size_t i) {
        const sim::Measurement& m = s.measurements[i];
        if (m.shape == sim::MeasurementShape::Line)
            return tr("Walkers crossing it (flow), %1 m long")
                .arg(double(glm::length(m.points[1] - m.points[0])), 0, 'f', 2);
        return tr("Density and speed inside, %1 m²").arg(sim::polygonArea(m.points), 0, 'f', 2);
    });
    auto allOf = [&form](sim::MeasurementShape shape) {
        const std::vector<std::size_t> items = form.indices();
        return std::all_of(items.begin(), items.end(),
                           [&](std::size_t i) { return form.scene().measurements[i].shape == shape; });
    };
    auto* ends = new PointTable(form, THRONG_AT(measurements, points), form.owner());
    ends->setMinPoints(2);
    ends->setMaxPoints(2);
    ends->setCheck([](const PointTable::Points& points) {
        return points.size() == 2 && points[0] == points[1] ? tr("A measurement line's ends must differ.") : QString();
    });
    form.addRow(tr("Ends"), ends, [&form, ends, allOf] {
        form.setRowShown(ends, allOf(sim::MeasurementShape::Line));
        ends->refresh();
    });
    auto* corners = new PointTable(form, THRONG_AT(measurements, points), form.owner());
    corners->setMinPoints(3);
    corners->setCheck([](const PointTable::Points& points) {
        return sim::polygonSelfCrossing(points)
                   ? tr("That would make the area's outline cross itself; it stays as it is.")
                   : QString();
    });
    form.addRow(tr("Corners"), corners, [&form, corners, allOf] {
        form.setRowShown(corners, allOf(sim::MeasurementShape::Area));
        corners->refresh();
    });
}

}  // namespace

void addPropertyRows(PropertyForm& form)
{
    switch (form.kind()) {
    case ItemKind::Agent: addAgentRows(form); break;
    case ItemKind::AgentType: addAgentTypeRows(form); break;
    case ItemKind::Group: addGroupRows(form); break;
    case ItemKind::Crosswalk: addCrosswalkRows(form); break;
    case ItemKind::Source: addSourceRows(form); break;
    case ItemKind::Vehicle: addVehicleRows(form); break;
    case ItemKind::LayoutOp: addLayoutOpRows(form); break;
    default: addSetRows(form); break;
    }
}

void addAgentRows(PropertyForm& form)
{
    form.addInfo("id", tr("Id"), [](const sim::Scene& s, std::size_t i) { return QString::number(s.agents[i].id); });
    form.addChoice("type", tr("Type"), namesOfKind(ItemKind::AgentType), THRONG_AT(agents, type), false);
    form.addChoice("brain", tr("Brain"), namesOfKind(ItemKind::Brain), THRONG_AT(agents, brain), true);
    form.addChoice("group", tr("Group"), agentGroups, THRONG_AT(agents, group), true, true);
    form.addChoice("goal", tr("Goal"), namesOfKind(ItemKind::Goal), THRONG_AT(agents, goal), true);
    form.addChoice("path", tr("Path"), namesOfKind(ItemKind::Path), THRONG_AT(agents, path), true);
    addLeaderRow(form, THRONG_AT(agents, leader), true);
    form.addNumberFields();
    addAgentVariationRows(form);
}

void addAgentTypeRows(PropertyForm& form)
{
    form.addName();
    form.addEnum<sim::AgentKind>("kind", tr("Kind"), {tr("Pedestrian"), tr("Vehicle"), tr("Flier")},
                                 THRONG_AT(agentTypes, kind));
    form.addChoice("brain", tr("Brain"), namesOfKind(ItemKind::Brain), THRONG_AT(agentTypes, brain), true);
    form.addEnum<sim::Navigation>("navigation", tr("Navigation"), {tr("Direct"), tr("A* plan"), tr("Flow field")},
                                  THRONG_AT(agentTypes, navigation));
    form.addCheck("priorityCombination", tr("Prioritised behaviours"), THRONG_AT(agentTypes, priorityCombination));
    form.addEnum<sim::CarFollowing>("carFollowing", tr("Car following"), carFollowingNames(),
                                    THRONG_AT(agentTypes, carFollowing), [](const sim::Scene& s, std::size_t i) {
                                        return s.agentTypes[i].kind == sim::AgentKind::Vehicle;
                                    });
    form.addNumberFields();
    addAgentTypeLookRows(form);
    addAgentTypeAgeRow(form);
    addAgentTypeCollisionRows(form);
    auto* table = new BehaviourTable(form, form.owner());
    form.addRow(tr("Behaviours"), table, [table] { table->refresh(); });
}

void addGroupRows(PropertyForm& form)
{
    form.addName();
    form.addChoice("type", tr("Type"), namesOfKind(ItemKind::AgentType), THRONG_AT(groups, type), false);
    form.addInteger<std::uint32_t>("count", tr("Count"), 0, 1000000, THRONG_AT(groups, count));
    form.addChoice("goal", tr("Goal"), namesOfKind(ItemKind::Goal), THRONG_AT(groups, goal), true);
    form.addChoice("path", tr("Path"), namesOfKind(ItemKind::Path), THRONG_AT(groups, path), true);
    addLeaderRow(form, THRONG_AT(groups, leader), false);
    // A group chooses its exit or has a goal, path or leader: exits clear those.
    addExitsRow(form, THRONG_AT(groups, exits), [&form](const std::vector<std::string>& names) {
        form.applyEach<sim::SpawnGroup>("exits", tr("Exits"), [](sim::Scene& s, std::size_t i) -> auto& {
            return s.groups[i];
        }, [names](const sim::SpawnGroup& now) {
            sim::SpawnGroup out = now;
            out.exits = names;
            if (!names.empty()) {
                // Walkers that choose their exit go on their own: no route, and no keeping together.
                out.goal.clear();
                out.path.clear();
                out.leader = 0;
                out.formation.shape = sim::FormationShape::None;
                out.companions = glm::uvec2(0u);
            }
            return out;
        });
    }, {"goal", "path", "leader"});
    // The area's shape; a switch carries the area over (the circle round the rectangle's
    // middle, the rectangle round the circle, the polygon on the rectangle's corners or
    // round the circle) so that the group stays valid and in place.
    const PropertyForm::Locate<sim::SpawnGroup> group = [](sim::Scene& s, std::size_t i) -> auto& { return s.groups[i]; };
    form.addIndexChoice("shape", tr("Area"), [] { return QStringList{tr("Rectangle"), tr("Circle"), tr("Polygon")}; }, [&form] {
        const auto shape = form.common<sim::AreaShape>(THRONG_AT(groups, shape));
        return shape ? std::optional<int>(int(*shape)) : std::nullopt;
    }, [&form, group](int index) {
        form.applyEach<sim::SpawnGroup>("shape", tr("Area"), group, [index](const sim::SpawnGroup& now) {
            return withAreaShape(now, sim::AreaShape(index));
        });
    });
    form.addNumberFields();
    addKeepTogetherRows(form);
    // A polygon's corners, kept a valid spawn area: an edit that would make it cross
    // itself is refused.
    auto* corners = new PointTable(form, THRONG_AT(groups, points), form.owner());
    corners->setMinPoints(3);
    corners->setCheck([](const PointTable::Points& points) { return spawnPolygonProblem(points); });
    form.addRow(tr("Corners"), corners, [&form, corners] {
        const std::vector<std::size_t> items = form.indices();
        form.setRowShown(corners, std::any_of(items.begin(), items.end(), [&](std::size_t i) {
            return form.scene().groups[i].shape == sim::AreaShape::Polygon;
        }));
        corners->refresh();
    });
}

void addSetRows(PropertyForm& form)
{
    const ItemKind kind = form.kind();
    if (hasName(kind) && kind != ItemKind::Brain)
        form.addName();
    switch (kind) {
    case ItemKind::Settings:
        form.addInteger<std::uint64_t>("seed", tr("Seed"), 0, 2147483647,
                                       [](sim::Scene& s, std::size_t) -> auto& { return s.settings.seed; });
        // The scene's default; "Inherit" is not one (a lane or a vehicle type inherits it).
        form.addIndexChoice("carFollowing", tr("Car following"), [] { return carFollowingNames().mid(1); }, [&form] {
            const sim::CarFollowing m = form.scene().traffic.carFollowing;
            return std::optional<int>(m == sim::CarFollowing::Inherit ? 0 : int(m) - 1);
        }, [&form](int index) {
            form.apply<sim::CarFollowing>("carFollowing", tr("Car following"),
                                          [](sim::Scene& s, std::size_t) -> auto& { return s.traffic.carFollowing; },
                                          sim::CarFollowing(index + 1));
        });
        break;
    case ItemKind::Path:
        form.addCheck("closed", tr("Closed loop"), THRONG_AT(paths, closed));
        form.addCheck("planned", tr("Planned (A*)"), THRONG_AT(paths, planned));
        addPoints(form, THRONG_AT(paths, points));
        break;
    case ItemKind::Goal: form.addCheck("exit", tr("Exit"), THRONG_AT(goals, exit)); break;
    case ItemKind::ActionPoint:
        form.addChoice("action", tr("Action"), [](const sim::Scene&) { return actionPointActions(); },
                       THRONG_AT(actionPoints, action), false);
        form.addCheck("faces", tr("Turns to facing"), THRONG_AT(actionPoints, faces));
        form.addInfo("types", tr("Types"), [](const sim::Scene& s, std::size_t i) {
            const std::vector<std::string>& types = s.actionPoints[i].types;
            QStringList names;
            for (const std::string& t : types)
                names << QString::fromStdString(t);
            return types.empty() ? tr("every walker") : names.join(", ");
        });
        break;
    case ItemKind::Lane:
        form.addCheck("loop", tr("Loop"), THRONG_AT(lanes, loop));
        form.addEnum<sim::CarFollowing>("carFollowing", tr("Car following"), carFollowingNames(),
                                        THRONG_AT(lanes, carFollowing));
        addPoints(form, THRONG_AT(lanes, points));
        break;
    case ItemKind::Obstacle:
        form.addEnum<sim::ObstacleShape>("shape", tr("Shape"), {tr("Circle"), tr("Box")}, THRONG_AT(obstacles, shape));
        break;
    case ItemKind::TrafficLight: {
        auto* table = new StopLineTable(form, form.owner());
        form.addRow(tr("Stop lines"), table, [table] { table->refresh(); });
        break;
    }
    case ItemKind::Hero:
        form.addChoice("type", tr("Type"), namesOfKind(ItemKind::AgentType), THRONG_AT(heroes, type), false);
        form.addInfo("keyframes", tr("Keyframes"), [](const sim::Scene& s, std::size_t i) {
            const sim::Hero& h = s.heroes[i];
            const QString count = QString::number(h.keyframes.size());
            return h.keyframesFile.empty() ? count
                                           : tr("%1 from %2").arg(count, QString::fromStdString(h.keyframesFile));
        });
        break;
    case ItemKind::Measurement: addMeasurementRows(form); break;
    case ItemKind::Wall:
        addPoints(form, THRONG_AT(walls, points));
        break;
    case ItemKind::Brain:
        form.addInfo("name", tr("Name"),
                     [](const sim::Scene& s, std::size_t i) { return QString::fromStdString(s.brains[i].name); });
        break;
    default: break;
    }
    form.addNumberFields();
}

#undef THRONG_AT

}  // namespace throng::editor
