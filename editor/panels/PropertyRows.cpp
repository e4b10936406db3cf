#include "editor/panels/PropertyRows.h"

#include "editor/commands/NameReferences.h"
#include "editor/panels/BehaviourTable.h"
#include "editor/panels/PropertyForm.h"

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

void addNumbers(PropertyForm& form)
{
    for (const PropertyField& field : propertyFields(form.kind()))
        form.addNumber(field);
}

}  // namespace

#define THRONG_AT(list, member) [](sim::Scene& s, std::size_t i) -> auto& { return s.list[i].member; }

void addPropertyRows(PropertyForm& form)
{
    switch (form.kind()) {
    case ItemKind::Agent: addAgentRows(form); break;
    case ItemKind::AgentType: addAgentTypeRows(form); break;
    case ItemKind::Group: addGroupRows(form); break;
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
    addNumbers(form);
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
    addNumbers(form);
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
    form.addInfo("shape", tr("Area"), [](const sim::Scene& s, std::size_t i) {
        const sim::SpawnGroup& g = s.groups[i];
        return g.shape == sim::AreaShape::Circle
                   ? tr("circle at (%1, %2)").arg(g.center.x).arg(g.center.y)
                   : tr("rectangle (%1, %2) to (%3, %4)").arg(g.min.x).arg(g.min.y).arg(g.max.x).arg(g.max.y);
    });
    addNumbers(form);
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
        break;
    case ItemKind::Path:
        form.addCheck("closed", tr("Closed loop"), THRONG_AT(paths, closed));
        form.addCheck("planned", tr("Planned (A*)"), THRONG_AT(paths, planned));
        form.addInfo("points", tr("Points"),
                     [](const sim::Scene& s, std::size_t i) { return QString::number(s.paths[i].points.size()); });
        break;
    case ItemKind::Goal: form.addCheck("exit", tr("Exit"), THRONG_AT(goals, exit)); break;
    case ItemKind::Lane: form.addCheck("loop", tr("Loop"), THRONG_AT(lanes, loop)); break;
    case ItemKind::TrafficLight:
        form.addInfo("stopLines", tr("Stop lines"), [](const sim::Scene& s, std::size_t i) {
            QStringList lines;
            for (const sim::StopLine& line : s.trafficLights[i].stopLines)
                lines << (line.lane.empty() ? tr("crosswalk %1").arg(QString::fromStdString(line.crosswalk))
                                            : tr("lane %1 at %2 m").arg(QString::fromStdString(line.lane)).arg(line.atM));
            return lines.isEmpty() ? tr("none") : lines.join("\n");
        });
        break;
    case ItemKind::Hero:
        form.addChoice("type", tr("Type"), namesOfKind(ItemKind::AgentType), THRONG_AT(heroes, type), false);
        form.addInfo("keyframes", tr("Keyframes"), [](const sim::Scene& s, std::size_t i) {
            const sim::Hero& h = s.heroes[i];
            const QString count = QString::number(h.keyframes.size());
            return h.keyframesFile.empty() ? count
                                           : tr("%1 from %2").arg(count, QString::fromStdString(h.keyframesFile));
        });
        break;
    case ItemKind::Wall:
        form.addInfo("points", tr("Points"),
                     [](const sim::Scene& s, std::size_t i) { return QString::number(s.walls[i].points.size()); });
        break;
    case ItemKind::Brain:
        form.addInfo("name", tr("Name"),
                     [](const sim::Scene& s, std::size_t i) { return QString::fromStdString(s.brains[i].name); });
        break;
    default: break;
    }
    addNumbers(form);
}

#undef THRONG_AT

}  // namespace throng::editor
