#pragma once
// Sets one property on several scene values at once (a properties-panel edit of a
// multi-selection, or a rename with every reference to the old name): one undo step.
// Redo and undo swap the stored values with the scene's in one SceneDocument::modify.
// Edits with the same non-empty key in a row (a spin box drag) merge into one step. The
// caller says what the values are (a SceneChange), for both redo and undo.

#include "editor/SceneDocument.h"
#include "editor/commands/CommandIds.h"

#include <QString>
#include <QUndoCommand>

#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

namespace throng::editor {

template <class Value>
class ChangeValuesCommand : public QUndoCommand {
public:
    // `locates[k]` finds the k-th value in the scene; `values[k]` is what it becomes.
    using Locate = std::function<Value&(sim::Scene&)>;

    ChangeValuesCommand(SceneDocument& document, QString key, std::vector<Locate> locates, std::vector<Value> values,
                        const QString& text, SceneChange change)
        : m_document(document), m_key(std::move(key)), m_locates(std::move(locates)), m_change(std::move(change))
    {
        values.resize(m_locates.size());
        for (std::size_t k = 0; k < values.size(); ++k)
            m_values.push_back({Value(std::move(values[k]))});
        setText(text);
    }

    // True when redo would change nothing (every value is already the scene's).
    bool changesNothing() const
    {
        auto& scene = const_cast<sim::Scene&>(m_document.scene());  // read only
        for (std::size_t k = 0; k < m_locates.size(); ++k)
            if (!(m_locates[k](scene) == m_values[k].value))
                return false;
        return true;
    }

    void redo() override { swap(); }
    void undo() override { swap(); }
    int id() const override { return m_key.isEmpty() ? -1 : kChangeValuesId; }

    bool mergeWith(const QUndoCommand* other) override
    {
        const auto* next = dynamic_cast<const ChangeValuesCommand*>(other);
        if (!next || next->m_key != m_key || &next->m_document != &m_document)
            return false;
        // m_values hold the values before our redo; the scene now holds next's values.
        setObsolete(changesNothing());
        return true;
    }

private:
    void swap()
    {
        m_document.modify(m_change, [this](sim::Scene& s) {
            for (std::size_t k = 0; k < m_locates.size(); ++k)
                std::swap(m_locates[k](s), m_values[k].value);
        });
    }

    // Boxed, so that a bool is a plain bool& and not std::vector<bool>'s proxy.
    struct Stored {
        Value value;
    };

    SceneDocument& m_document;
    QString m_key;
    std::vector<Locate> m_locates;
    std::vector<Stored> m_values;
    SceneChange m_change;
};

}  // namespace throng::editor
