#pragma once
// Appends one item (a wall, path, obstacle, traffic light, ...) to one of the scene's
// lists; undo removes it again. Structural edits of the set drawn by the tools, which add
// and select what they draw with addAndSelect.

#include "editor/SceneDocument.h"
#include "simcore/scene/Scene.h"

#include <QString>
#include <QUndoCommand>

#include <cstddef>
#include <type_traits>
#include <vector>

namespace throng::editor {

// The kind of the scene's items of type Item (a list of Scene).
template <class Item>
constexpr ItemKind listKind()
{
    if constexpr (std::is_same_v<Item, sim::AgentType>) return ItemKind::AgentType;
    else if constexpr (std::is_same_v<Item, sim::SpawnGroup>) return ItemKind::Group;
    else if constexpr (std::is_same_v<Item, sim::Agent>) return ItemKind::Agent;
    else if constexpr (std::is_same_v<Item, sim::Path>) return ItemKind::Path;
    else if constexpr (std::is_same_v<Item, sim::Wall>) return ItemKind::Wall;
    else if constexpr (std::is_same_v<Item, sim::Obstacle>) return ItemKind::Obstacle;
    else if constexpr (std::is_same_v<Item, sim::Goal>) return ItemKind::Goal;
    else if constexpr (std::is_same_v<Item, sim::TrafficLight>) return ItemKind::TrafficLight;
    else if constexpr (std::is_same_v<Item, sim::Lane>) return ItemKind::Lane;
    else if constexpr (std::is_same_v<Item, sim::FlowStroke>) return ItemKind::FlowStroke;
    else if constexpr (std::is_same_v<Item, sim::Hero>) return ItemKind::Hero;
    else if constexpr (std::is_same_v<Item, sim::BrainGraph>) return ItemKind::Brain;
    else if constexpr (std::is_same_v<Item, sim::Crosswalk>) return ItemKind::Crosswalk;
    else if constexpr (std::is_same_v<Item, sim::ActionPoint>) return ItemKind::ActionPoint;
    else if constexpr (std::is_same_v<Item, sim::Source>) return ItemKind::Source;
    else if constexpr (std::is_same_v<Item, sim::Measurement>) return ItemKind::Measurement;
    else {
        static_assert(std::is_same_v<Item, sim::Vehicle>, "not an item of a scene list");
        return ItemKind::Vehicle;
    }
}

template <class Item>
class AddSceneItemCommand : public QUndoCommand {
public:
    using List = std::vector<Item> sim::Scene::*;

    AddSceneItemCommand(SceneDocument& document, List list, Item item, const QString& text)
        : m_document(document), m_list(list), m_item(std::move(item))
    {
        setText(text);
    }

    void redo() override
    {
        const std::size_t index = (m_document.scene().*m_list).size();
        m_document.modify(change(index), [this](sim::Scene& s) { (s.*m_list).push_back(m_item); });
    }

    void undo() override
    {
        const std::size_t index = (m_document.scene().*m_list).size() - 1;
        m_document.modify(change(index), [this](sim::Scene& s) { (s.*m_list).pop_back(); });
    }

private:
    // The item at `index` of its list comes or goes.
    static SceneChange change(std::size_t index) { return SceneChange::of(listKind<Item>(), {index}, SceneField::Items); }

    SceneDocument& m_document;
    List m_list;
    Item m_item;
};

// Adds `item` to `list` as one undo step and selects it, so Properties shows what was just
// drawn or made, ready for its goal, name or values. The selection is not part of the step.
template <class Item>
void addAndSelect(SceneDocument& document, std::vector<Item> sim::Scene::*list, Item item, const QString& text)
{
    document.undoStack()->push(new AddSceneItemCommand<Item>(document, list, std::move(item), text));
    document.setSelection({{listKind<Item>(), (document.scene().*list).size() - 1}});
}

}  // namespace throng::editor
