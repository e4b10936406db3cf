#pragma once
// Removes placed agents by index: one erase-brush dab. Records each removed agent and
// its index so undo puts them back exactly; dabs of one stroke merge into one step.

#include "simcore/scene/Scene.h"

#include <QUndoCommand>

#include <cstddef>
#include <vector>

namespace throng::editor {

class SceneDocument;

class EraseAgentsCommand : public QUndoCommand {
public:
    // `indices` into Scene::agents as the scene is when the command is first done.
    EraseAgentsCommand(SceneDocument& document, std::vector<std::size_t> indices, int strokeId);

    void redo() override;
    void undo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

    std::size_t agentCount() const;

private:
    // One dab: ascending indices and, once done, the agents that stood there.
    struct Batch {
        std::vector<std::size_t> indices;
        std::vector<sim::Agent> agents;
    };
    void updateText();

    SceneDocument& m_document;
    std::vector<Batch> m_batches;  // done in order, undone in reverse
    int m_strokeId;
};

}  // namespace throng::editor
