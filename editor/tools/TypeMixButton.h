#pragma once
// The crowd brush's "Mix" button in the tool options bar: says the mix in a few words
// ("walker 3 : child 1") and opens the TypeMixTable under itself as a popup, so the
// bar keeps its height however many types the scene has. Never edits the scene.

#include "editor/tools/CrowdBrushPlacement.h"

#include <QToolButton>

#include <functional>
#include <string>
#include <vector>

namespace throng::editor {

class TypeMixTable;

class TypeMixButton : public QToolButton {
    Q_OBJECT

public:
    // `types` lists the types the table offers when it opens; `fallback` is the type an
    // empty mix paints.
    using TypeList = std::function<std::vector<std::string>()>;
    using Fallback = std::function<std::string()>;
    TypeMixButton(std::vector<TypeShare> mix, TypeList types, Fallback fallback, QWidget* parent = nullptr);

    // The popup table, shown after a click.
    TypeMixTable* table() const { return m_table; }
    void openTable();

signals:
    void mixChanged(const std::vector<TypeShare>& mix);

private:
    void showSummary();

    std::vector<TypeShare> m_mix;
    TypeList m_types;
    Fallback m_fallback;
    TypeMixTable* m_table;
};

}  // namespace throng::editor
