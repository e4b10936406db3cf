#pragma once
// Merge ids of the commands that merge (QUndoCommand::id()): one enum so no two
// command classes ever share an id.

namespace throng::editor {

enum CommandId : int {
    kPaintAgentsId = 1,
    kEraseAgentsId,
    kChangeValueId,
    kChangeAgentsId,
    kMoveItemsId,
    kEditBrainId,
    kChangeValuesId,
};

}  // namespace throng::editor
