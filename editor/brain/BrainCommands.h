#pragma once
// Undo commands of the brain editor. EditBrainCommand swaps one brain graph between its
// state before and after an edit (nodes, links, params, positions); EditBrainsCommand
// swaps the scene's brain list and agent types' brain names (add, rename, duplicate,
// import, delete). Both change the scene only through SceneDocument::modify.

#include "editor/SceneDocument.h"
#include "simcore/scene/Scene.h"

#include <QUndoCommand>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace throng::editor {

class EditBrainCommand : public QUndoCommand {
public:
    // `mergeable`: a later mergeable edit of the same brain with the same text folds in
    // (dragging a fuzz handle or nudging nodes is one undo step).
    EditBrainCommand(SceneDocument& document, std::size_t brainIndex, sim::BrainGraph before, sim::BrainGraph after,
                     const QString& text, bool mergeable = false);

    void redo() override;
    void undo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

    // The brain's program, or only its layout when nothing but node places and labels
    // differ (redo and undo send it).
    SceneChange change() const;

private:
    void apply(const sim::BrainGraph& graph);

    SceneDocument& m_document;
    std::size_t m_brain;
    sim::BrainGraph m_before, m_after;
    bool m_mergeable;
};

class EditBrainsCommand : public QUndoCommand {
public:
    struct State {
        std::vector<sim::BrainGraph> brains;
        std::vector<sim::AgentType> agentTypes;
        // Placed agents with a brain of their own: (index in Scene::agents, Agent::brain).
        std::vector<std::pair<std::size_t, std::string>> agentBrains;
    };
    EditBrainsCommand(SceneDocument& document, State before, State after, const QString& text);

    void redo() override;
    void undo() override;

    // The brain list, every type's brain and the placed agents' own (redo and undo send it).
    SceneChange change() const;

private:
    void apply(const State& state);

    SceneDocument& m_document;
    State m_before, m_after;
};

}  // namespace throng::editor
