#pragma once
// The crowd brush's type mix as a table: one row per agent type the brush may paint,
// with a weight spin box each (object name "mixWeight_<type>"); the brush draws types in
// proportion to the weights. Shows and reports the mix; never edits the scene.

#include "editor/tools/CrowdBrushPlacement.h"

#include <QFrame>

#include <string>
#include <vector>

class QTableWidget;

namespace throng::editor {

class TypeMixTable : public QFrame {
    Q_OBJECT

public:
    explicit TypeMixTable(QWidget* parent = nullptr);

    // One row per name, weighted as in `mix`; an empty mix weighs `fallback` 1, others 0.
    void setTypes(const std::vector<std::string>& names, const std::vector<TypeShare>& mix,
                  const std::string& fallback);
    // The types of weight > 0 with their weights, in row order.
    std::vector<TypeShare> mix() const;
    QTableWidget* table() const { return m_table; }

signals:
    void mixChanged(const std::vector<TypeShare>& mix);

private:
    QTableWidget* m_table;
};

}  // namespace throng::editor
