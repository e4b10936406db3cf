#include "editor/commands/DeleteItemsCommand.h"

#include <QCoreApplication>

#include <algorithm>

namespace throng::editor {

namespace {

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
    return kind == ItemKind::FlowStroke || kind == ItemKind::Wall || kind == ItemKind::Obstacle;
}

DeleteItemsCommand::DeleteItemsCommand(SceneDocument& document, const Selection& items) : m_document(document)
{
    const sim::Scene& s = document.scene();
    for (const SceneItem& item : items) {
        if (item.kind == ItemKind::FlowStroke)
            take(s.flowStrokes, item.index, m_strokes);
        else if (item.kind == ItemKind::Wall)
            take(s.walls, item.index, m_walls);
        else if (item.kind == ItemKind::Obstacle)
            take(s.obstacles, item.index, m_obstacles);
    }
    auto byIndex = [](const auto& a, const auto& b) { return a.first < b.first; };
    std::sort(m_strokes.begin(), m_strokes.end(), byIndex);
    std::sort(m_walls.begin(), m_walls.end(), byIndex);
    std::sort(m_obstacles.begin(), m_obstacles.end(), byIndex);
    const std::size_t count = m_strokes.size() + m_walls.size() + m_obstacles.size();
    const auto first = std::find_if(items.begin(), items.end(), [](SceneItem i) { return deletable(i.kind); });
    setText(count == 1 ? QCoreApplication::translate("DeleteItemsCommand", "Delete %1").arg(itemLabel(s, *first))
                       : QCoreApplication::translate("DeleteItemsCommand", "Delete %n item(s)", nullptr, int(count)));
}

void DeleteItemsCommand::redo()
{
    m_document.modify([this](sim::Scene& s) {
        removeAll(s.flowStrokes, m_strokes);
        removeAll(s.walls, m_walls);
        removeAll(s.obstacles, m_obstacles);
    });
}

void DeleteItemsCommand::undo()
{
    m_document.modify([this](sim::Scene& s) {
        restoreAll(s.flowStrokes, m_strokes);
        restoreAll(s.walls, m_walls);
        restoreAll(s.obstacles, m_obstacles);
    });
}

}  // namespace throng::editor
