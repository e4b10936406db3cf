#pragma once
// The outliner: the scene's things by kind (agent types, groups, agents, the agents'
// groups, paths, walls, obstacles, goals, lights, lanes, heroes, brains), with counts. Selecting rows sets the
// document's selection; it reads the scene and never edits it.

#include "editor/SceneItem.h"

#include <QTreeWidget>

namespace throng::editor {

class SceneDocument;

class OutlinerPanel : public QTreeWidget {
    Q_OBJECT

public:
    explicit OutlinerPanel(SceneDocument& document, QWidget* parent = nullptr);

    // The heading row of a kind ("Walls (4)"), or null.
    QTreeWidgetItem* kindRow(ItemKind kind) const;
    // The row of an agent group (Agent::group) by name, or null; selecting it selects
    // the group's agents.
    QTreeWidgetItem* agentGroupRow(const QString& name) const;
    // Agents are counted, not listed, above this many.
    static constexpr std::size_t kMaxListedAgents = 500;

private:
    void rebuild();
    void addAgentGroups(bool expand);
    void showSelection();
    void takeSelection();

    SceneDocument& m_document;
    bool m_updating = false;
};

}  // namespace throng::editor
