#include "editor/commands/ChangeAgentsCommand.h"

#include "editor/SceneDocument.h"
#include "editor/commands/CommandIds.h"

#include <QCoreApplication>

namespace throng::editor {

namespace {

// What differs between two states of one placed agent, as SceneField bits.
std::uint32_t differences(const sim::Agent& a, const sim::Agent& b)
{
    std::uint32_t fields = 0;
    auto differ = [&fields](bool differs, SceneField field) {
        if (differs)
            fields |= fieldBit(field);
    };
    differ(a.position != b.position, SceneField::Position);
    differ(a.headingDeg != b.headingDeg, SceneField::Heading);
    differ(a.type != b.type, SceneField::Type);
    differ(a.goal != b.goal || a.path != b.path || a.leader != b.leader, SceneField::Route);
    differ(a.brain != b.brain, SceneField::Brain);
    differ(a.group != b.group, SceneField::Group);
    differ(a.look != b.look || a.tint != b.tint || a.heightScale != b.heightScale, SceneField::Look);
    // An id is what the agent is: a new one makes it another agent.
    differ(a.id != b.id, SceneField::Items);
    return fields;
}

}  // namespace

ChangeAgentsCommand::ChangeAgentsCommand(SceneDocument& document, const std::vector<std::size_t>& indices,
                                         const std::vector<sim::Agent>& after, int strokeId, QString verb)
    : m_document(document), m_strokeId(strokeId), m_verb(std::move(verb))
{
    const std::vector<sim::Agent>& agents = document.scene().agents;
    for (std::size_t k = 0; k < indices.size() && k < after.size(); ++k)
        m_changes[indices[k]] = {agents[indices[k]], after[k]};
    updateText();
}

SceneChange ChangeAgentsCommand::change() const
{
    std::vector<std::size_t> indices;
    std::uint32_t fields = 0;
    for (const auto& [i, change] : m_changes) {
        indices.push_back(i);
        fields |= differences(change.before, change.after);
    }
    SceneChange out;
    for (int k = 0; k < kSceneFieldCount; ++k)
        if (fields & (1u << k))
            out |= SceneChange::of(ItemKind::Agent, indices, SceneField(1u << k));
    return out;
}

void ChangeAgentsCommand::redo()
{
    m_document.modify(change(), [this](sim::Scene& s) {
        for (const auto& [i, change] : m_changes)
            s.agents[i] = change.after;
    });
}

void ChangeAgentsCommand::undo()
{
    m_document.modify(change(), [this](sim::Scene& s) {
        for (const auto& [i, change] : m_changes)
            s.agents[i] = change.before;
    });
}

int ChangeAgentsCommand::id() const
{
    return kChangeAgentsId;
}

bool ChangeAgentsCommand::mergeWith(const QUndoCommand* other)
{
    const auto* dab = static_cast<const ChangeAgentsCommand*>(other);
    if (dab->m_strokeId != m_strokeId || &dab->m_document != &m_document)
        return false;
    for (const auto& [i, change] : dab->m_changes) {
        auto [it, added] = m_changes.try_emplace(i, change);
        if (!added)
            it->second.after = change.after;  // keep the state before the whole stroke
    }
    std::erase_if(m_changes, [](const auto& entry) { return entry.second.before == entry.second.after; });
    updateText();
    setObsolete(m_changes.empty());
    return true;
}

void ChangeAgentsCommand::updateText()
{
    setText(QCoreApplication::translate("ChangeAgentsCommand", "%1 %n agent(s)", nullptr, int(m_changes.size()))
                .arg(m_verb));
}

}  // namespace throng::editor
