#include "editor/commands/PaintAgentsCommand.h"

#include "editor/SceneDocument.h"
#include "editor/commands/CommandIds.h"

#include <QCoreApplication>

namespace throng::editor {

PaintAgentsCommand::PaintAgentsCommand(SceneDocument& document, std::vector<sim::Agent> agents, int strokeId)
    : m_document(document), m_agents(std::move(agents)), m_strokeId(strokeId)
{
    updateText();
}

SceneChange PaintAgentsCommand::change(std::size_t first) const
{
    std::vector<std::size_t> indices(m_agents.size());
    for (std::size_t k = 0; k < indices.size(); ++k)
        indices[k] = first + k;
    return SceneChange::of(ItemKind::Agent, std::move(indices), SceneField::Items);
}

void PaintAgentsCommand::redo()
{
    m_document.modify(change(m_document.scene().agents.size()),
                      [this](sim::Scene& s) { s.agents.insert(s.agents.end(), m_agents.begin(), m_agents.end()); });
}

void PaintAgentsCommand::undo()
{
    // Our agents are the last ones: every later command has been undone first.
    m_document.modify(change(m_document.scene().agents.size() - m_agents.size()),
                      [this](sim::Scene& s) { s.agents.resize(s.agents.size() - m_agents.size()); });
}

int PaintAgentsCommand::id() const
{
    return kPaintAgentsId;
}

bool PaintAgentsCommand::mergeWith(const QUndoCommand* other)
{
    const auto* dab = static_cast<const PaintAgentsCommand*>(other);
    if (dab->m_strokeId != m_strokeId || &dab->m_document != &m_document)
        return false;
    m_agents.insert(m_agents.end(), dab->m_agents.begin(), dab->m_agents.end());
    updateText();
    setObsolete(m_agents.empty());
    return true;
}

void PaintAgentsCommand::updateText()
{
    setText(QCoreApplication::translate("PaintAgentsCommand", "Paint %n agent(s)", nullptr, int(m_agents.size())));
}

}  // namespace throng::editor
