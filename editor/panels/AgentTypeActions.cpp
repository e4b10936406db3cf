#include "editor/panels/AgentTypeActions.h"

#include "editor/Icons.h"
#include "editor/SceneDocument.h"
#include "editor/commands/AddSceneItemCommand.h"

#include <QAction>
#include <QMenu>
#include <QUndoStack>
#include <QWidget>

namespace throng::editor {

AgentTypeActions::AgentTypeActions(SceneDocument& document, QWidget* parent)
    : QObject(parent), m_document(document)
{
    m_presets = new QMenu(tr("New Agent Type"), parent);
    m_presets->setObjectName("typePresetMenu");
    m_presets->setToolTipsVisible(true);
    for (TypePreset preset : kTypePresets) {
        QAction* a = m_presets->addAction(presetLabel(preset), this, [this, preset] { create(preset); });
        a->setObjectName("typePreset" + presetLabel(preset) + "Action");
        a->setToolTip(presetDescription(preset));
        a->setIcon(themeIcon("action-new-agent-type"));
    }
    m_newType = new QAction(tr("New Agent &Type"), this);
    m_newType->setObjectName("newTypeAction");
    m_newType->setIcon(themeIcon("action-new-agent-type"));
    m_newType->setShortcut(QKeySequence(tr("Ctrl+T")));
    m_newType->setToolTip(tr("Add a pedestrian agent type (Ctrl+T); the arrow offers runner, car, bird and rider"));
    m_newType->setMenu(m_presets);
    connect(m_newType, &QAction::triggered, this, [this] { create(TypePreset::Pedestrian); });
    m_duplicate = new QAction(tr("&Duplicate Agent Type"), this);
    m_duplicate->setObjectName("duplicateTypeAction");
    m_duplicate->setIcon(themeIcon("action-duplicate"));
    m_duplicate->setShortcut(QKeySequence(tr("Ctrl+Shift+D")));
    m_duplicate->setToolTip(tr("Copy the selected agent types under new names (Ctrl+Shift+D)"));
    connect(m_duplicate, &QAction::triggered, this, &AgentTypeActions::duplicateSelected);
    connect(&m_document, &SceneDocument::selectionChanged, this, &AgentTypeActions::updateEnabled);
    updateEnabled();
}

std::size_t AgentTypeActions::create(TypePreset preset)
{
    sim::AgentType type = makeTypePreset(preset, m_document.scene());
    const QString text = tr("Add agent type %1").arg(QString::fromStdString(type.name));
    addAndSelect(m_document, &sim::Scene::agentTypes, std::move(type), text);
    return m_document.scene().agentTypes.size() - 1;
}

void AgentTypeActions::duplicateSelected()
{
    std::vector<std::size_t> sources;
    for (const SceneItem& item : m_document.selection())
        if (item.kind == ItemKind::AgentType && item.index < m_document.scene().agentTypes.size())
            sources.push_back(item.index);
    if (sources.empty())
        return;
    QUndoStack* stack = m_document.undoStack();
    if (sources.size() > 1)
        stack->beginMacro(tr("Duplicate %1 agent types").arg(sources.size()));
    Selection made;
    for (std::size_t source : sources) {
        const sim::AgentType& original = m_document.scene().agentTypes[source];
        sim::AgentType copy = duplicateType(original, m_document.scene());
        const QString text = tr("Duplicate agent type %1 as %2")
                                 .arg(QString::fromStdString(original.name), QString::fromStdString(copy.name));
        stack->push(new AddSceneItemCommand<sim::AgentType>(m_document, &sim::Scene::agentTypes, std::move(copy), text));
        made.push_back({ItemKind::AgentType, m_document.scene().agentTypes.size() - 1});
    }
    if (sources.size() > 1)
        stack->endMacro();
    m_document.setSelection(made);
}

void AgentTypeActions::updateEnabled()
{
    const Selection& s = m_document.selection();
    m_duplicate->setEnabled(
        std::any_of(s.begin(), s.end(), [](const SceneItem& item) { return item.kind == ItemKind::AgentType; }));
}

}  // namespace throng::editor
