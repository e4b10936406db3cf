#pragma once
// Appends one item (a wall, path, obstacle, traffic light, ...) to one of the scene's
// lists; undo removes it again. Structural edits of the set drawn by the tools.

#include "editor/SceneDocument.h"
#include "simcore/scene/Scene.h"

#include <QString>
#include <QUndoCommand>

#include <vector>

namespace throng::editor {

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
        m_document.modify([this](sim::Scene& s) { (s.*m_list).push_back(m_item); });
    }

    void undo() override
    {
        m_document.modify([this](sim::Scene& s) { (s.*m_list).pop_back(); });
    }

private:
    SceneDocument& m_document;
    List m_list;
    Item m_item;
};

}  // namespace throng::editor
