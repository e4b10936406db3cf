#pragma once
// The actions that create agent types: New Agent Type (a pedestrian, or any preset from
// its menu) and Duplicate Agent Type (each selected type). Each pushes one undo step and
// selects what it made; it never draws and never deletes (Edit > Delete does).

#include "editor/AgentTypePresets.h"

#include <QObject>

class QAction;
class QMenu;
class QWidget;

namespace throng::editor {

class SceneDocument;

class AgentTypeActions : public QObject {
    Q_OBJECT

public:
    AgentTypeActions(SceneDocument& document, QWidget* parent);

    // Creates a pedestrian; its menu() offers every preset.
    QAction* newType() const { return m_newType; }
    QMenu* presetMenu() const { return m_presets; }
    QAction* duplicate() const { return m_duplicate; }

    // Adds a type made from `preset`, selects it and returns its index in the scene.
    std::size_t create(TypePreset preset);

private:
    void duplicateSelected();
    void updateEnabled();

    SceneDocument& m_document;
    QAction* m_newType = nullptr;
    QMenu* m_presets = nullptr;
    QAction* m_duplicate = nullptr;
};

}  // namespace throng::editor
