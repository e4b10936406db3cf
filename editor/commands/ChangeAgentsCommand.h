#pragma once
// Replaces placed agents by index with edited copies: one dab of the orient, variation or
// assign brush. Records each agent as it was so undo restores it exactly; dabs of one
// stroke merge into one step ("Comb 40 agents"). Never touches widgets.

#include "editor/SceneChange.h"
#include "simcore/scene/Scene.h"

#include <QString>
#include <QUndoCommand>

#include <cstddef>
#include <map>
#include <vector>

namespace throng::editor {

class SceneDocument;

class ChangeAgentsCommand : public QUndoCommand {
public:
    // `indices` into Scene::agents and the agents to put there (same length). `verb` names
    // the edit in the history ("Comb", "Vary", "Assign").
    ChangeAgentsCommand(SceneDocument& document, const std::vector<std::size_t>& indices,
                        const std::vector<sim::Agent>& after, int strokeId, QString verb);

    void redo() override;
    void undo() override;
    int id() const override;
    bool mergeWith(const QUndoCommand* other) override;

    std::size_t agentCount() const { return m_changes.size(); }
    // The agents changed and the fields of theirs that differ (redo and undo send it).
    SceneChange change() const;

private:
    struct Change {
        sim::Agent before, after;
    };
    void updateText();

    SceneDocument& m_document;
    std::map<std::size_t, Change> m_changes;  // by agent index
    int m_strokeId;
    QString m_verb;
};

}  // namespace throng::editor
