#pragma once
// Sets one value of the scene (a property edit), after Tiled's ChangeValue: redo and undo
// swap the stored value with the scene's. Edits of the same property in a row (a spin
// box scrub) merge into one step, and a net change of zero becomes obsolete. The caller
// says what the value is (a SceneChange), for both redo and undo.

#include "editor/SceneDocument.h"
#include "editor/commands/CommandIds.h"

#include <QString>
#include <QUndoCommand>

#include <functional>
#include <utility>

namespace throng::editor {

template <class Value>
class ChangeValueCommand : public QUndoCommand {
public:
    // `locate` finds the value in the scene; `key` names the property (same key = merge);
    // `change` names the item and field the value is.
    using Locate = std::function<Value&(sim::Scene&)>;

    ChangeValueCommand(SceneDocument& document, QString key, Locate locate, Value value, const QString& text,
                       SceneChange change)
        : m_document(document), m_key(std::move(key)), m_locate(std::move(locate)), m_value(std::move(value)),
          m_change(std::move(change))
    {
        setText(text);
    }

    void redo() override { swap(); }
    void undo() override { swap(); }
    int id() const override { return kChangeValueId; }

    bool mergeWith(const QUndoCommand* other) override
    {
        const auto* next = dynamic_cast<const ChangeValueCommand*>(other);
        if (!next || next->m_key != m_key || &next->m_document != &m_document)
            return false;
        // m_value holds the value before our redo; the scene now holds next's value.
        // locate() only finds the value here; nothing is written through the cast.
        setObsolete(m_locate(const_cast<sim::Scene&>(m_document.scene())) == m_value);
        return true;
    }

private:
    void swap()
    {
        m_document.modify(m_change, [this](sim::Scene& s) { std::swap(m_locate(s), m_value); });
    }

    SceneDocument& m_document;
    QString m_key;
    Locate m_locate;
    Value m_value;
    SceneChange m_change;
};

}  // namespace throng::editor
