#include "editor/SceneChange.h"

#include <QStringList>

#include <algorithm>
#include <array>

namespace throng::editor {

namespace {

bool before(SceneItem a, SceneItem b)
{
    return a.kind != b.kind ? int(a.kind) < int(b.kind) : a.index < b.index;
}

// Sorts, drops repeats, and lets an all-of-kind entry stand for its kind's single items.
void normalise(std::vector<SceneItem>& items)
{
    std::sort(items.begin(), items.end(), before);
    items.erase(std::unique(items.begin(), items.end()), items.end());
    std::array<bool, kItemKindCount> all{};
    for (const SceneItem& item : items)
        if (item.index == SceneChange::kAllOfKind)
            all[std::size_t(item.kind)] = true;
    std::erase_if(items, [&](SceneItem item) {
        return all[std::size_t(item.kind)] && item.index != SceneChange::kAllOfKind;
    });
}

const char* fieldName(SceneField field)
{
    switch (field) {
    case SceneField::Items: return "items";
    case SceneField::Position: return "position";
    case SceneField::Heading: return "heading";
    case SceneField::Shape: return "shape";
    case SceneField::Type: return "type";
    case SceneField::Look: return "look";
    case SceneField::Name: return "name";
    case SceneField::Group: return "group";
    case SceneField::Route: return "route";
    case SceneField::Brain: return "brain";
    case SceneField::BrainLayout: return "brain layout";
    case SceneField::Parameters: return "parameters";
    case SceneField::Settings: return "settings";
    }
    return "?";
}

}  // namespace

bool simulationReads(ItemKind kind, SceneField field)
{
    // Measurements are read by the analysis of the recorded frames, never by a World; the
    // layout layer edits the recorded frames after the simulation.
    if (kind == ItemKind::Measurement || kind == ItemKind::LayoutOp)
        return false;
    switch (field) {
    case SceneField::Look:
    case SceneField::Group:
    case SceneField::BrainLayout: return false;
    case SceneField::Name:
        // The World looks these up by nothing (a path by the name its users give, and
        // those are items of their own); every other name is looked up: by groups when a
        // run resumes, by brains (goals, brains), by the traffic set (lights, lanes,
        // crosswalks, vehicle types).
        return kind != ItemKind::Wall && kind != ItemKind::Obstacle && kind != ItemKind::Hero && kind != ItemKind::Path;
    default: return true;
    }
}

SceneChange SceneChange::of(ItemKind kind, std::vector<std::size_t> indices, SceneField field)
{
    SceneChange change;
    change.items.reserve(indices.size());
    for (std::size_t i : indices)
        change.items.push_back({kind, i});
    normalise(change.items);
    change.fields = fieldBit(field);
    change.simulationReads = !change.items.empty() && editor::simulationReads(kind, field);
    return change;
}

SceneChange SceneChange::of(SceneItem item, SceneField field)
{
    return of(item.kind, {item.index}, field);
}

SceneChange SceneChange::ofAll(ItemKind kind, SceneField field)
{
    return of(kind, {kAllOfKind}, field);
}

SceneChange& SceneChange::operator|=(const SceneChange& other)
{
    items.insert(items.end(), other.items.begin(), other.items.end());
    normalise(items);
    fields |= other.fields;
    simulationReads = simulationReads || other.simulationReads;
    return *this;
}

bool SceneChange::touches(ItemKind kind) const
{
    return std::any_of(items.begin(), items.end(), [kind](SceneItem item) { return item.kind == kind; });
}

bool SceneChange::touches(SceneItem item) const
{
    return std::binary_search(items.begin(), items.end(), item, before) ||
           std::binary_search(items.begin(), items.end(), SceneItem{item.kind, kAllOfKind}, before);
}

QString describe(const SceneChange& change)
{
    QStringList items;
    for (const SceneItem& item : change.items)
        items << (item.index == SceneChange::kAllOfKind ? QStringLiteral("all %1").arg(kindTitle(item.kind))
                                                        : QStringLiteral("%1[%2]").arg(kindTitle(item.kind)).arg(item.index));
    QStringList fields;
    for (int k = 0; k < kSceneFieldCount; ++k)
        if (change.fields & (1u << k))
            fields << QString::fromLatin1(fieldName(SceneField(1u << k)));
    return QStringLiteral("%1: %2; read by the simulation: %3")
        .arg(items.isEmpty() ? QStringLiteral("nothing") : items.join(", "), fields.join(", "),
             change.simulationReads ? QStringLiteral("yes") : QStringLiteral("no"));
}

}  // namespace throng::editor
