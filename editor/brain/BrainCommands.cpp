#include "editor/brain/BrainCommands.h"

#include "editor/commands/CommandIds.h"

#include <utility>

namespace throng::editor {

namespace {

// The graph as the brain compiler reads it: without where its nodes sit on the canvas and
// their labels, which only the editor shows.
sim::BrainGraph program(sim::BrainGraph graph)
{
    for (sim::BrainNode& node : graph.nodes) {
        node.position = {};
        node.label.clear();
    }
    return graph;
}

}  // namespace

EditBrainCommand::EditBrainCommand(SceneDocument& document, std::size_t brainIndex, sim::BrainGraph before,
                                   sim::BrainGraph after, const QString& text, bool mergeable)
    : m_document(document), m_brain(brainIndex), m_before(std::move(before)), m_after(std::move(after)),
      m_mergeable(mergeable)
{
    // Positions in the file no longer match an edited graph.
    m_after.source = {};
    setText(text);
}

SceneChange EditBrainCommand::change() const
{
    // Moving nodes about (or renaming their labels) leaves the program as it was.
    const bool layoutOnly = program(m_before) == program(m_after);
    return SceneChange::of({ItemKind::Brain, m_brain}, layoutOnly ? SceneField::BrainLayout : SceneField::Brain);
}

void EditBrainCommand::apply(const sim::BrainGraph& graph)
{
    m_document.modify(change(), [&](sim::Scene& scene) {
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

SceneChange EditBrainsCommand::change() const
{
    // The brain list as a whole, the brain each type runs, and the placed agents' own.
    SceneChange change = SceneChange::ofAll(ItemKind::Brain, SceneField::Items) |
                         SceneChange::ofAll(ItemKind::AgentType, SceneField::Brain);
    std::vector<std::size_t> agents;
    for (const State* state : {&m_before, &m_after})
        for (const auto& [agent, brain] : state->agentBrains)
            agents.push_back(agent);
    if (!agents.empty())
        change |= SceneChange::of(ItemKind::Agent, std::move(agents), SceneField::Brain);
    return change;
}

void EditBrainsCommand::apply(const State& state)
{
    m_document.modify(change(), [&](sim::Scene& scene) {
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
