#pragma once
// Moves selected items (agents, obstacles, goals, lights, sources, and whole paths, walls
// and lanes) by one ground offset. Holds each item's original place and the offset moved so
// far, so the moves of one drag merge into one step and undo restores exactly.

#include "editor/SceneItem.h"

#include <glm/vec2.hpp>

#include <QUndoCommand>

#include <vector>

namespace throng::editor {

class SceneDocument;

class MoveItemsCommand : public QUndoCommand {
public:
    // `offsetM` from where the items stand now; moves of the same `dragId` add up.
    MoveItemsCommand(SceneDocument& document, Selection items, glm::vec2 offsetM, int dragId);

    void redo() override;
    void undo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

    // Whether items of this kind can be moved.
    static bool movable(ItemKind kind);

private:
    void place(bool moved);

    SceneDocument& m_document;
    Selection m_items;
    std::vector<std::vector<glm::vec2>> m_original;  // per item: its point(s) before the drag
    glm::vec2 m_offset;
    int m_dragId;
};

}  // namespace throng::editor
