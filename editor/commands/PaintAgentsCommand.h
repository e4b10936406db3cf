#pragma once
// Adds placed agents at the end of the scene's agent list: one brush dab. Dabs of one
// stroke merge into a single undo step ("Paint 240 agents"). Never touches widgets.

#include "editor/SceneChange.h"
#include "simcore/scene/Scene.h"

#include <QUndoCommand>

#include <vector>

namespace throng::editor {

class SceneDocument;

class PaintAgentsCommand : public QUndoCommand {
public:
    // `strokeId` groups the dabs of one stroke; a dab merges into the previous command
    // only when both carry the same stroke id.
    PaintAgentsCommand(SceneDocument& document, std::vector<sim::Agent> agents, int strokeId);

    void redo() override;
    void undo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

    std::size_t agentCount() const { return m_agents.size(); }

private:
    // Our agents, the first of them at index `first`, come or go.
    SceneChange change(std::size_t first) const;
    void updateText();

    SceneDocument& m_document;
    std::vector<sim::Agent> m_agents;
    int m_strokeId;
};

}  // namespace throng::editor
