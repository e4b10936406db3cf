#include "editor/commands/DeleteItemsCommand.h"

#include "editor/commands/NameReferences.h"

#include <QCoreApplication>
#include <QStringList>

#include <algorithm>
#include <set>

namespace throng::editor {

namespace {

QString tr(const char* text, int n = -1)
{
    return QCoreApplication::translate("DeleteItemsCommand", text, nullptr, n);
}

template <class Item>
void take(const std::vector<Item>& list, std::size_t index, std::vector<std::pair<std::size_t, Item>>& out)
{
    if (index < list.size() && std::none_of(out.begin(), out.end(), [&](const auto& e) { return e.first == index; }))
        out.emplace_back(index, list[index]);
}

// Removes from the back, so the recorded indices stay valid while removing.
template <class Item>
void removeAll(std::vector<Item>& list, const std::vector<std::pair<std::size_t, Item>>& removed)
{
    for (auto it = removed.rbegin(); it != removed.rend(); ++it)
        list.erase(list.begin() + std::ptrdiff_t(it->first));
}

// Inserts from the front: each index is where the item stood with the earlier ones back.
template <class Item>
void restoreAll(std::vector<Item>& list, const std::vector<std::pair<std::size_t, Item>>& removed)
{
    for (const auto& [index, item] : removed)
        list.insert(list.begin() + std::ptrdiff_t(index), item);
}

}  // namespace

bool DeleteItemsCommand::deletable(ItemKind kind)
{
    return kind != ItemKind::Settings;
}

template <class Scene, class F>
void DeleteItemsCommand::forEachList(Scene& s, F f)
{
    f(s.agents, m_agents, ItemKind::Agent);
    f(s.agentTypes, m_types, ItemKind::AgentType);
    f(s.groups, m_groups, ItemKind::Group);
    f(s.paths, m_paths, ItemKind::Path);
    f(s.walls, m_walls, ItemKind::Wall);
    f(s.obstacles, m_obstacles, ItemKind::Obstacle);
    f(s.goals, m_goals, ItemKind::Goal);
    f(s.trafficLights, m_lights, ItemKind::TrafficLight);
    f(s.lanes, m_lanes, ItemKind::Lane);
    f(s.flowStrokes, m_strokes, ItemKind::FlowStroke);
    f(s.heroes, m_heroes, ItemKind::Hero);
    f(s.crosswalks, m_crosswalks, ItemKind::Crosswalk);
    f(s.vehicles, m_vehicles, ItemKind::Vehicle);
    f(s.brains, m_brains, ItemKind::Brain);
    f(s.actionPoints, m_actionPoints, ItemKind::ActionPoint);
    f(s.sources, m_sources, ItemKind::Source);
    f(s.measurements, m_measurements, ItemKind::Measurement);
    f(s.layout.ops, m_layoutOps, ItemKind::LayoutOp);
}

DeleteItemsCommand::DeleteItemsCommand(SceneDocument& document, const Selection& items) : m_document(document)
{
    const sim::Scene& scene = document.scene();
    forEachList(scene, [&](const auto& list, auto& removed, ItemKind kind) {
        for (const SceneItem& item : items)
            if (item.kind == kind)
                take(list, item.index, removed);
        std::sort(removed.begin(), removed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
        m_count += removed.size();
    });
    checkReferences(scene, items);
    const auto first = std::find_if(items.begin(), items.end(), [](SceneItem i) { return deletable(i.kind); });
    setText(m_count == 1 ? tr("Delete %1").arg(itemLabel(scene, *first)) : tr("Delete %n item(s)", int(m_count)));
}

// The rules, item by item, for what others refer to:
// - A path, goal, lane, crosswalk, brain or agent type still named by an item that stays (a group following
//   the path, agents or a source sending walkers to the goal, vehicles or a stop line on the lane,
//   anything of the type) is refused, naming who uses it: clearing the reference would silently change
//   what a whole group does far from the selection, and a vehicle or hero cannot live
//   without its lane or type. Deleting the users in the same selection is fine.
// - A deleted placed agent or hero that others follow (`leader`) is deleted, and the
//   followers' leader is cleared in the same command: following nobody is valid, and
//   it is what a user who removes the leader expects.
void DeleteItemsCommand::checkReferences(const sim::Scene& scene, const Selection& items)
{
    const std::set<std::pair<int, std::size_t>> deleted = [&] {
        std::set<std::pair<int, std::size_t>> d;
        for (const SceneItem& i : items)
            d.insert({int(i.kind), i.index});
        return d;
    }();
    QStringList problems;
    for (const SceneItem& item : items) {
        if (item.kind != ItemKind::Path && item.kind != ItemKind::Goal && item.kind != ItemKind::Lane &&
            item.kind != ItemKind::AgentType && item.kind != ItemKind::Crosswalk && item.kind != ItemKind::Brain)
            continue;
        if (item.index >= itemCount(scene, item.kind))
            continue;
        QStringList users;
        std::size_t count = 0;
        for (const NameUse& use : nameUses(scene, item.kind, nameOf(scene, item))) {
            if (use.user && deleted.count({int(use.user->kind), use.user->index}))
                continue;
            if (++count <= 3)
                users << use.who;
        }
        if (count == 0)
            continue;
        if (count > 3)
            users << tr("%n more", int(count - 3));
        problems << tr("%1 is still used by %2").arg(itemLabel(scene, item), users.join(", "));
    }
    if (!problems.isEmpty())
        m_refusal = tr("Nothing deleted: %1. Delete or change those first.").arg(problems.join("; "));

    std::vector<std::uint32_t> ids;
    for (const auto& [index, agent] : m_agents)
        ids.push_back(agent.id);
    for (const auto& [index, hero] : m_heroes)
        ids.push_back(hero.id);
    for (const auto& [index, vehicle] : m_vehicles)
        ids.push_back(vehicle.id);
    for (std::uint32_t id : ids)
        for (const LeaderUse& use : leaderUses(scene, id)) {
            m_clearedLeaders.emplace_back(use.locate, id);
            m_leaderUsers.push_back(use.user);
        }
}

SceneChange DeleteItemsCommand::change()
{
    // Every list deleted from: the indices after a deleted item shift.
    SceneChange change;
    forEachList(m_document.scene(), [&change](const auto&, const auto& removed, ItemKind kind) {
        if (!removed.empty())
            change |= SceneChange::ofAll(kind, SceneField::Items);
    });
    for (const SceneItem& user : m_leaderUsers)
        change |= SceneChange::of(user, SceneField::Route);
    return change;
}

void DeleteItemsCommand::redo()
{
    m_document.modify(change(), [this](sim::Scene& s) {
        for (const auto& [locate, id] : m_clearedLeaders)
            locate(s) = 0;
        forEachList(s, [](auto& list, const auto& removed, ItemKind) { removeAll(list, removed); });
    });
}

void DeleteItemsCommand::undo()
{
    m_document.modify(change(), [this](sim::Scene& s) {
        forEachList(s, [](auto& list, const auto& removed, ItemKind) { restoreAll(list, removed); });
        for (const auto& [locate, id] : m_clearedLeaders)
            locate(s) = id;
    });
}

}  // namespace throng::editor
