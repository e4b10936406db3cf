#pragma once
// Deletes the selected flow strokes, walls and obstacles (things nothing else in the
// scene refers to by name). Records each removed item with its index, so undo puts every
// one back where it was. Never touches widgets or the selection.

#include "editor/SceneDocument.h"
#include "editor/SceneItem.h"

#include <QUndoCommand>

#include <cstddef>
#include <utility>
#include <vector>

namespace throng::editor {

class DeleteItemsCommand : public QUndoCommand {
public:
    // True for the kinds this command deletes.
    static bool deletable(ItemKind kind);
    // The deletable items of `items`; the others are left alone.
    DeleteItemsCommand(SceneDocument& document, const Selection& items);

    // Nothing to delete (no deletable item was given).
    bool isEmpty() const { return m_strokes.empty() && m_walls.empty() && m_obstacles.empty(); }

    void redo() override;
    void undo() override;

private:
    SceneDocument& m_document;
    // Ascending by index, as they stood before the delete.
    std::vector<std::pair<std::size_t, sim::FlowStroke>> m_strokes;
    std::vector<std::pair<std::size_t, sim::Wall>> m_walls;
    std::vector<std::pair<std::size_t, sim::Obstacle>> m_obstacles;
};

}  // namespace throng::editor
