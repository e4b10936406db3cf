#include "editor/commands/EraseAgentsCommand.h"

#include "editor/SceneDocument.h"
#include "editor/commands/CommandIds.h"

#include <QCoreApplication>

#include <algorithm>

namespace throng::editor {

EraseAgentsCommand::EraseAgentsCommand(SceneDocument& document, std::vector<std::size_t> indices, int strokeId)
    : m_document(document), m_strokeId(strokeId)
{
    std::sort(indices.begin(), indices.end());
    indices.erase(std::unique(indices.begin(), indices.end()), indices.end());
    m_batches.push_back({std::move(indices), {}});
    updateText();
}

void EraseAgentsCommand::redo()
{
    // Removing shifts the indices of the agents after the erased ones.
    m_document.modify(SceneChange::ofAll(ItemKind::Agent, SceneField::Items), [this](sim::Scene& s) {
        for (Batch& batch : m_batches) {
            batch.agents.clear();
            for (std::size_t i : batch.indices)
                batch.agents.push_back(s.agents[i]);
            // From the back, so the indices still to remove stay valid.
            for (auto it = batch.indices.rbegin(); it != batch.indices.rend(); ++it)
                s.agents.erase(s.agents.begin() + std::ptrdiff_t(*it));
        }
    });
}

void EraseAgentsCommand::undo()
{
    m_document.modify(SceneChange::ofAll(ItemKind::Agent, SceneField::Items), [this](sim::Scene& s) {
        for (auto batch = m_batches.rbegin(); batch != m_batches.rend(); ++batch)
            for (std::size_t k = 0; k < batch->indices.size(); ++k)
                s.agents.insert(s.agents.begin() + std::ptrdiff_t(batch->indices[k]), batch->agents[k]);
    });
}

int EraseAgentsCommand::id() const
{
    return kEraseAgentsId;
}

bool EraseAgentsCommand::mergeWith(const QUndoCommand* other)
{
    const auto* dab = static_cast<const EraseAgentsCommand*>(other);
    if (dab->m_strokeId != m_strokeId || &dab->m_document != &m_document)
        return false;
    m_batches.insert(m_batches.end(), dab->m_batches.begin(), dab->m_batches.end());
    updateText();
    setObsolete(agentCount() == 0);
    return true;
}

std::size_t EraseAgentsCommand::agentCount() const
{
    std::size_t n = 0;
    for (const Batch& b : m_batches)
        n += b.indices.size();
    return n;
}

void EraseAgentsCommand::updateText()
{
    setText(QCoreApplication::translate("EraseAgentsCommand", "Erase %n agent(s)", nullptr, int(agentCount())));
}

}  // namespace throng::editor
