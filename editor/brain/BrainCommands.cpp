#include "editor/brain/BrainCommands.h"

#include "editor/commands/CommandIds.h"

#include <utility>

namespace throng::editor {

EditBrainCommand::EditBrainCommand(SceneDocument& document, std::size_t brainIndex, sim::BrainGraph before,
                                   sim::BrainGraph after, const QString& text, bool mergeable)
    : m_document(document), m_brain(brainIndex), m_before(std::move(before)), m_after(std::move(after)),
      m_mergeable(mergeable)
{
    // Positions in the file no longer match an edited graph.
    m_after.source = {};
    setText(text);
}

void EditBrainCommand::apply(const sim::BrainGraph& graph)
{
    m_document.modify([&](sim::Scene& scene) {
        if (m_brain < scene.brains.size())
            scene.brains[m_brain] = graph;
    });
}

void EditBrainCommand::redo()
{
    apply(m_after);
}

void EditBrainCommand::undo()
{
    apply(m_before);
}

int EditBrainCommand::id() const
{
    return m_mergeable ? kEditBrainId : -1;
}

bool EditBrainCommand::mergeWith(const QUndoCommand* other)
{
    const auto* o = dynamic_cast<const EditBrainCommand*>(other);
    if (!o || !o->m_mergeable || o->m_brain != m_brain || o->text() != text())
        return false;
    m_after = o->m_after;
    setObsolete(m_after == m_before);
    return true;
}

EditBrainsCommand::EditBrainsCommand(SceneDocument& document, State before, State after, const QString& text)
    : m_document(document), m_before(std::move(before)), m_after(std::move(after))
{
    setText(text);
}

void EditBrainsCommand::apply(const State& state)
{
    m_document.modify([&](sim::Scene& scene) {
        scene.brains = state.brains;
        scene.agentTypes = state.agentTypes;
        for (const auto& [agent, brain] : state.agentBrains)
            if (agent < scene.agents.size())
                scene.agents[agent].brain = brain;
    });
}

void EditBrainsCommand::redo()
{
    apply(m_after);
}

void EditBrainsCommand::undo()
{
    apply(m_before);
}

}  // namespace throng::editor
