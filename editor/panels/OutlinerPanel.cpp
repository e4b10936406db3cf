#include "editor/panels/OutlinerPanel.h"

#include "editor/SceneDocument.h"

#include <QHeaderView>
#include <QSignalBlocker>

#include <algorithm>
#include <map>

namespace throng::editor {

namespace {
constexpr int kKindRole = Qt::UserRole;
constexpr int kIndexRole = Qt::UserRole + 1;
constexpr int kGroupRole = Qt::UserRole + 2;  // agent-group rows: the group's name
constexpr int kAgentGroups = -100;            // kKindRole of the agent-group heading and rows
// What the rows show of an item: the lists themselves, names, an agent's id and type, a
// vehicle's type and lane, a flow stroke's width, the agents' groups. A move, a look or a
// brain edit leaves every row as it was.
constexpr std::uint32_t kShownFields = fieldBit(SceneField::Items) | fieldBit(SceneField::Name) |
                                       fieldBit(SceneField::Type) | fieldBit(SceneField::Group) |
                                       fieldBit(SceneField::Route) | fieldBit(SceneField::Shape);
constexpr ItemKind kListed[] = {ItemKind::Settings,    ItemKind::AgentType, ItemKind::Group,        ItemKind::Agent,
                                ItemKind::Path,        ItemKind::Wall,      ItemKind::Obstacle,     ItemKind::Goal,
                                ItemKind::ActionPoint, ItemKind::Source,    ItemKind::TrafficLight, ItemKind::Lane,
                                ItemKind::Crosswalk,   ItemKind::Vehicle,   ItemKind::FlowStroke,   ItemKind::Hero,
                                ItemKind::Brain,       ItemKind::Measurement};
}  // namespace

OutlinerPanel::OutlinerPanel(SceneDocument& document, QWidget* parent) : QTreeWidget(parent), m_document(document)
{
    setObjectName("outliner");
    setHeaderHidden(true);
    setSelectionMode(QAbstractItemView::ExtendedSelection);
    setToolTip(tr("Everything in the scene; select rows to edit them in Properties"));
    connect(&m_document, &SceneDocument::sceneReset, this, &OutlinerPanel::rebuild);
    connect(&m_document, &SceneDocument::sceneChanged, this, [this](const SceneChange& change) {
        if (change.hasAny(kShownFields))
            rebuild();
    });
    connect(&m_document, &SceneDocument::selectionChanged, this, &OutlinerPanel::showSelection);
    connect(this, &QTreeWidget::itemSelectionChanged, this, &OutlinerPanel::takeSelection);
    rebuild();
}

QTreeWidgetItem* OutlinerPanel::kindRow(ItemKind kind) const
{
    for (int i = 0; i < topLevelItemCount(); ++i)
        if (topLevelItem(i)->data(0, kKindRole).toInt() == int(kind))
            return topLevelItem(i);
    return nullptr;
}

void OutlinerPanel::rebuild()
{
    const QSignalBlocker block(this);
    m_updating = true;
    QSet<int> expanded;
    for (int i = 0; i < topLevelItemCount(); ++i)
        if (topLevelItem(i)->isExpanded())
            expanded.insert(topLevelItem(i)->data(0, kKindRole).toInt());
    clear();
    const sim::Scene& scene = m_document.scene();
    for (ItemKind kind : kListed) {
        const std::size_t count = itemCount(scene, kind);
        if (kind == ItemKind::Settings) {
            auto* row = new QTreeWidgetItem(this, {itemLabel(scene, {kind, 0})});
            row->setData(0, kKindRole, int(kind));
            row->setData(0, kIndexRole, 0);
            continue;
        }
        auto* heading = new QTreeWidgetItem(this, {QStringLiteral("%1 (%2)").arg(kindTitle(kind)).arg(count)});
        heading->setData(0, kKindRole, int(kind));
        heading->setData(0, kIndexRole, -1);
        heading->setFlags(heading->flags() & ~Qt::ItemIsSelectable);
        if (kind == ItemKind::Agent && count > kMaxListedAgents)
            continue;
        for (std::size_t i = 0; i < count; ++i) {
            auto* row = new QTreeWidgetItem(heading, {itemLabel(scene, {kind, i})});
            row->setData(0, kKindRole, int(kind));
            row->setData(0, kIndexRole, qlonglong(i));
        }
        heading->setExpanded(expanded.contains(int(kind)));
        if (kind == ItemKind::Agent)
            addAgentGroups(expanded.contains(kAgentGroups));
    }
    m_updating = false;
    showSelection();
}

// The agents' groups (Agent::group), each row selecting its agents as a set.
void OutlinerPanel::addAgentGroups(bool expand)
{
    std::map<std::string, std::size_t> groups;
    for (const sim::Agent& a : m_document.scene().agents)
        if (!a.group.empty())
            ++groups[a.group];
    auto* heading = new QTreeWidgetItem(this, {tr("Agent Groups (%1)").arg(groups.size())});
    heading->setData(0, kKindRole, kAgentGroups);
    heading->setData(0, kIndexRole, -1);
    heading->setFlags(heading->flags() & ~Qt::ItemIsSelectable);
    for (const auto& [name, count] : groups) {
        const QString label = tr("%1 (%n agent(s))", nullptr, int(count)).arg(QString::fromStdString(name));
        auto* row = new QTreeWidgetItem(heading, {label});
        row->setData(0, kKindRole, kAgentGroups);
        row->setData(0, kIndexRole, -1);
        row->setData(0, kGroupRole, QString::fromStdString(name));
    }
    heading->setExpanded(expand);
}

QTreeWidgetItem* OutlinerPanel::agentGroupRow(const QString& name) const
{
    for (int i = 0; i < topLevelItemCount(); ++i) {
        QTreeWidgetItem* heading = topLevelItem(i);
        if (heading->data(0, kKindRole).toInt() != kAgentGroups)
            continue;
        for (int k = 0; k < heading->childCount(); ++k)
            if (heading->child(k)->data(0, kGroupRole).toString() == name)
                return heading->child(k);
    }
    return nullptr;
}

void OutlinerPanel::showSelection()
{
    const QSignalBlocker block(this);
    clearSelection();
    for (const SceneItem& item : m_document.selection()) {
        QTreeWidgetItem* heading = kindRow(item.kind);
        if (item.kind == ItemKind::Settings && heading) {
            heading->setSelected(true);
            continue;
        }
        if (heading && int(item.index) < heading->childCount()) {
            heading->child(int(item.index))->setSelected(true);
            heading->setExpanded(true);
        }
    }
}

void OutlinerPanel::takeSelection()
{
    if (m_updating)
        return;
    Selection selection;
    const std::vector<sim::Agent>& agents = m_document.scene().agents;
    for (QTreeWidgetItem* row : selectedItems()) {
        if (row->data(0, kKindRole).toInt() == kAgentGroups) {
            const std::string group = row->data(0, kGroupRole).toString().toStdString();
            for (std::size_t i = 0; i < agents.size(); ++i)
                if (agents[i].group == group && std::find(selection.begin(), selection.end(),
                                                          SceneItem{ItemKind::Agent, i}) == selection.end())
                    selection.push_back({ItemKind::Agent, i});
            continue;
        }
        const qlonglong index = row->data(0, kIndexRole).toLongLong();
        if (index >= 0)
            selection.push_back({ItemKind(row->data(0, kKindRole).toInt()), std::size_t(index)});
    }
    m_document.setSelection(selection);
}

}  // namespace throng::editor
